// The boundary front's walls: the open form's walls (Sec. 3, disks of infinite radius) generalised
// to every edge of every ring of the polygon, and its reflex vertices, obstacles of radius 0. Their
// geometry, and the element ids the front gives them. Header-only and CGAL-free.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>

namespace frontpack::detail {

// Element ids: a node (disk or reflex vertex) is >= 0, wall e is -(e + 1); kNoElement is none.
inline constexpr std::int32_t kNoElement = std::numeric_limits<std::int32_t>::min();
[[nodiscard]] inline std::int32_t wall_id(std::size_t e) noexcept {
  return -(static_cast<std::int32_t>(e) + 1);
}
[[nodiscard]] inline std::size_t wall_index(std::int32_t id) noexcept {
  return static_cast<std::size_t>(-(id + 1));
}

// kSlideTurn, 0.35 rad (20 degrees): a vertex where the boundary turns by less is no corner: the
// front does not start there, and the wall layer slides across it (slide()). Used through its
// cosine only, correctly rounded here (no C library call).
inline constexpr double kCosSlideTurn = 0.9393727128473789;  // cos(0.35)

struct Wall {
  double ax, ay, bx, by;  // a -> b, the domain on the left
  double tx, ty;          // unit direction
  double nx, ny;          // unit inward normal
  double len, w;          // length; n . a
};

struct Corner {  // a reflex vertex: the directions of its edges in and out
  double ux1, uy1, ux2, uy2;
};

// |(dx, dy)| from + - * / and a square root alone, all correctly rounded on every platform:
// std::hypot's last bit differs between C libraries, and every tangent to the wall, so every
// packing, would differ with it. At a power-of-two scale (exact), so that the squares neither
// overflow nor underflow.
inline double length(double dx, double dy) noexcept {
  const double m = std::max(std::abs(dx), std::abs(dy));
  if (!(m > 0) || !std::isfinite(m)) {
    return m;  // 0 where two vertices round to one local point (the wall then tests as nothing)
  }
  const int e = std::ilogb(m);
  const double x = std::ldexp(dx, -e);
  const double y = std::ldexp(dy, -e);
  return std::ldexp(std::sqrt(x * x + y * y), e);
}

/// The wall a -> b (the domain on its left).
inline Wall make_wall(double ax, double ay, double bx, double by) noexcept {
  const double dx = bx - ax;
  const double dy = by - ay;
  const double len = length(dx, dy);
  Wall w{ax, ay, bx, by, dx / len, dy / len, -dy / len, dx / len, len, 0};
  w.w = w.nx * ax + w.ny * ay;
  return w;
}

// Squared distance from (x, y) to wall wl.
inline double distance2(const Wall& wl, double x, double y) noexcept {
  const double u = (x - wl.ax) * wl.tx + (y - wl.ay) * wl.ty;
  double qx = wl.ax;
  double qy = wl.ay;
  if (u >= wl.len) {
    qx = wl.bx;
    qy = wl.by;
  } else if (u > 0) {
    qx += u * wl.tx;
    qy += u * wl.ty;
  }
  const double dx = x - qx;
  const double dy = y - qy;
  return dx * dx + dy * dy;
}

// Whether segment wl meets the box [x0, x1] x [y0, y1] (Liang-Barsky clipping; conservative
// enough: the box is already grown by the reach).
inline bool segment_meets_box(const Wall& wl, double x0, double y0, double x1, double y1) noexcept {
  double t0 = 0;
  double t1 = 1;
  const double dx = wl.bx - wl.ax;
  const double dy = wl.by - wl.ay;
  const std::array<double, 4> p{-dx, dx, -dy, dy};
  const std::array<double, 4> q{wl.ax - x0, x1 - wl.ax, wl.ay - y0, y1 - wl.ay};
  for (std::size_t k = 0; k < 4; ++k) {
    if (p[k] == 0) {
      if (q[k] < 0) {
        return false;
      }
      continue;
    }
    const double t = q[k] / p[k];
    if (p[k] < 0) {
      t0 = std::max(t0, t);
    } else {
      t1 = std::min(t1, t);
    }
    if (t0 > t1) {
      return false;
    }
  }
  return true;
}

}  // namespace frontpack::detail
