// Whether the edges of a set of rings meet anywhere but at the vertex consecutive edges share:
// a sweep over all of them in exact arithmetic (CGAL::do_curves_intersect), for the validator
// (validate.cpp) when the edges' boxes meet in too many pairs to classify one by one. In a
// translation unit of its own: the sweep's headers are heavy, and GCC 12 warns falsely inside
// them (edge_sweep.cpp).
#pragma once

#include <cstdint>
#include <vector>

#include "frontpack/geometry.hpp"

namespace frontpack::detail {

/// True if no two of the edges v[e] -> v[next[e]] have a common point in the interior of either
/// (no crossing, no overlap, no vertex on another edge's interior). Edges sharing an endpoint are
/// not reported: the caller checks separately that no two vertices lie at the same point.
/// Every edge must have two distinct endpoints.
[[nodiscard]] bool edge_interiors_disjoint(const std::vector<Point>& v, const std::vector<std::uint32_t>& next);

}  // namespace frontpack::detail
