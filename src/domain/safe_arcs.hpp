// Arcs replaced by polylines on the domain's side of the true arc (include/frontpack/
// domain_file.hpp, "Curves made safe"): the step count for a deviation, the vertices, and the
// exact check that moves each rounded vertex to the safe side.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "domain/contour.hpp"
#include "frontpack/geometry.hpp"

namespace frontpack::detail {

struct ArcPolyline {
  std::vector<Point> vertices;  ///< for an arc: the vertices between its endpoints; for a circle: all
  double deviation = 0.0;       ///< largest distance between polyline and arc, before nudges
  double radius = 0.0;          ///< the circle's radius as used (see arc_polyline)
  std::size_t segments = 0;
  std::size_t nudged = 0;
};

/// Segments an arc of `radius` and |sweep| becomes for `deviation`: chords when `inside` (the
/// domain inside the circle), tangents otherwise; every step at most pi/2. Throws OptionError
/// naming `entity` when more than max_segments_per_curve would be needed.
[[nodiscard]] std::size_t arc_segments(double radius, double sweep, bool inside, double deviation,
                                       const std::string& entity);

/// The segments `arc` (a full circle if `full_circle`, its sweep then 2 pi) becomes for `deviation`
/// on either side of the domain (the larger of arc_segments' chords and tangents): what reading a
/// file counts for every curve before it splits any, to hold the sum to its Budget. Throws like
/// arc_polyline for a bad arc or deviation, and like arc_segments past max_segments_per_curve.
[[nodiscard]] double curve_segments(const Arc& arc, bool full_circle, double deviation, const std::string& entity);

/// The polyline for `arc` between its given endpoints a (at arc.start) and b (at arc.start +
/// arc.sweep). The radius is first moved by at most 1e-12 of itself, when that puts both endpoints
/// exactly on the domain's side (they are on the circle up to rounding); `radius` says which was
/// used. inside: chords, every constructed vertex in the closed disk (exact). Outside: the
/// tangent polyline, whose every segment keeps out of the open disk, and the two end segments no
/// nearer to the centre than their given endpoint (exact).
[[nodiscard]] ArcPolyline arc_polyline(const Arc& arc, Point a, Point b, bool inside, double deviation,
                                       const std::string& entity);

/// A full circle as a closed anticlockwise polygon (chords when `inside`, tangents otherwise),
/// with the same exact guarantees and no given vertex.
[[nodiscard]] ArcPolyline circle_polygon(const Arc& circle, bool inside, double deviation, const std::string& entity);

}  // namespace frontpack::detail
