// Exact predicates of a periodic cell [xmin, xmax) x [ymin, ymax) (Domain::periodic). The
// periods are the exact differences xmax - xmin and ymax - ymin, never their rounded doubles:
// every expression below is evaluated inside the predicate, with interval arithmetic first and
// exact arithmetic when the interval answer is uncertain (predicates.hpp, filtered()). Integer
// shifts are exact as long as |k| <= 2^53 (callers keep them far below). CGAL-free declarations.
#pragma once

#include <cstdint>

#include "frontpack/geometry.hpp"

namespace frontpack::detail {

/// Sign of |c1 - (c2 + (kx (xmax - xmin), ky (ymax - ymin)))| - (r1 + r2), exactly: -1 when the
/// disk (c1, r1) overlaps the image of (c2, r2) shifted by kx periods in x and ky in y (interiors
/// intersect), 0 when they touch, +1 when they are apart.
int compare_image_distance(Point c1, Point c2, double r1, double r2, std::int64_t kx, std::int64_t ky, const Box& cell);

/// Where v - k (hi - lo) lies, exactly: -1 below lo, 0 in [lo, hi), +1 at or above hi.
int wrapped_side(double v, std::int64_t k, double lo, double hi);

/// Whether lo <= v - r and v + r <= hi, exactly (the closed disk between the walls of a shear cell).
bool between_walls(double v, double r, double lo, double hi);

}  // namespace frontpack::detail
