// CGAL-free declarations of the exact disk predicates, for the advancing-front hot loop (whose
// translation unit must not include CGAL). Defined in overlap.cpp.
#pragma once

#include "frontpack/geometry.hpp"

namespace frontpack::detail {

/// Exact: the interiors of the two disks intersect (|c1 - c2| < r1 + r2).
[[nodiscard]] bool disks_overlap_exact(Point c1, double r1, Point c2, double r2);

/// Exact: the centres are closer than r1 + r2 + gap (gap >= 0), the sum taken exactly.
[[nodiscard]] bool disks_closer_than_exact(Point c1, double r1, Point c2, double r2, double gap);

}  // namespace frontpack::detail
