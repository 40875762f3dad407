// frontpack: value types shared by every stage.
//
// These are plain aggregates of doubles. Every exact decision frontpack makes (point in domain,
// disk in domain, disk overlap) is taken on these very doubles, so what you write out is what
// was certified. See README.md, "Guarantees".
#pragma once

#include <cmath>
#include <compare>

namespace frontpack {

/// A point in the plane.
struct Point {
  double x = 0.0;
  double y = 0.0;
  friend constexpr bool operator==(const Point&, const Point&) = default;
};

/// A disk: centre and radius (radius >= 0).
struct Disk {
  Point centre;
  double radius = 0.0;
  friend constexpr bool operator==(const Disk&, const Disk&) = default;
};

/// A closed axis-aligned box [xmin, xmax] x [ymin, ymax]. Empty when xmin > xmax.
struct Box {
  double xmin = INFINITY;
  double ymin = INFINITY;
  double xmax = -INFINITY;
  double ymax = -INFINITY;

  [[nodiscard]] constexpr bool empty() const noexcept { return xmin > xmax || ymin > ymax; }
  [[nodiscard]] constexpr double width() const noexcept { return empty() ? 0.0 : xmax - xmin; }
  [[nodiscard]] constexpr double height() const noexcept { return empty() ? 0.0 : ymax - ymin; }
  constexpr void extend(Point p) noexcept {
    xmin = p.x < xmin ? p.x : xmin;
    ymin = p.y < ymin ? p.y : ymin;
    xmax = p.x > xmax ? p.x : xmax;
    ymax = p.y > ymax ? p.y : ymax;
  }
  constexpr void extend(const Box& b) noexcept {
    if (!b.empty()) {
      extend(Point{b.xmin, b.ymin});
      extend(Point{b.xmax, b.ymax});
    }
  }
  friend constexpr bool operator==(const Box&, const Box&) = default;
};

}  // namespace frontpack
