// Closed contours with circular arcs, as CAD readers give them (domain/dxf_reader.cpp), before
// they are nested into polygons and their arcs made polylines (domain/contour_nesting.cpp).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "frontpack/geometry.hpp"

namespace frontpack::detail {

/// A circular arc: from angle `start` (radians) through the signed `sweep` (> 0 anticlockwise).
struct Arc {
  Point centre{};
  double radius = 0.0;
  double start = 0.0;
  double sweep = 0.0;
};

/// One edge of a contour, from `from` to the next edge's `from`: straight, or along `arc`.
struct ContourEdge {
  Point from{};
  bool curved = false;
  Arc arc{};
  std::uint32_t name = 0;   ///< index into Contour::names: the entity the edge came from
  std::uint32_t index = 0;  ///< the edge's index within that entity (polyline edges), for reports
};

/// A closed contour: its edges in order, or one full circle (`edges` empty).
struct Contour {
  std::vector<ContourEdge> edges;
  bool full_circle = false;
  Arc circle{};  ///< the full circle (start 0, sweep 2 pi)
  std::vector<std::string> names;

  /// The entities it is made of, for messages: "CIRCLE (handle 2F, line 12)", or the first
  /// two and a count.
  [[nodiscard]] std::string describe() const {
    std::string s = names.empty() ? std::string("contour") : names.front();
    if (names.size() == 2) {
      s += " and " + names[1];
    } else if (names.size() > 2) {
      s += ", " + names[1] + " and " + std::to_string(names.size() - 2) + " more entities";
    }
    return s;
  }
};

/// The arc of bulge `bulge` (tan of a quarter of the signed sweep, DXF group 42) from a to b.
/// Centre and radius in closed form (no trigonometry): c = m + (1 - b^2) / (4 b) * perp(b - a),
/// r = |b - a| (1 + b^2) / (4 |b|). Precondition: bulge != 0, finite, a != b.
[[nodiscard]] Arc arc_from_bulge(Point a, Point b, double bulge);

}  // namespace frontpack::detail
