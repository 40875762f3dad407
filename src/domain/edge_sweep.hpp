// Whether the edges of a set of rings meet anywhere but at common endpoints: a sweep over all of
// them in exact arithmetic, for the validator (domain/validate.cpp) when the edges' boxes meet in too many
// pairs to classify one by one.
#pragma once

#include <cstdint>
#include <vector>

#include "frontpack/geometry.hpp"

namespace frontpack::detail {

/// True if no two of the edges v[e] -> v[next[e]] have a common point in the interior of either
/// (no crossing, no overlap, no vertex on another edge's interior): edges may share endpoints, as
/// many as meet there. Every edge must have two distinct endpoints. O(n log n).
[[nodiscard]] bool edge_interiors_disjoint(const std::vector<Point>& v, const std::vector<std::uint32_t>& next);

}  // namespace frontpack::detail
