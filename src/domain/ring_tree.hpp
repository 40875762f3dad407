// Which ring encloses which: the nesting tree of a set of rings, by one plane sweep.
#pragma once

#include <cstdint>
#include <vector>

#include "domain/ring_set.hpp"

namespace frontpack::detail {

/// No enclosing ring.
inline constexpr std::uint32_t no_ring = UINT32_MAX;

/// For each ring r, the innermost other ring whose interior contains the interior of r, or
/// no_ring. Precondition: what validate() checks before nesting holds: every ring is simple and
/// has area; no two rings cross (properly or at a common point) or share a segment; rings may
/// touch at points. The interiors of such rings are nested or disjoint, so the answer is a
/// forest, and ring s is an ancestor of r exactly when a point of r that lies on no other ring
/// is inside s. O(n log n) for n edges, decided exactly (orientation tests on the input doubles).
[[nodiscard]] std::vector<std::uint32_t> ring_parents(const RingSet& rings);

}  // namespace frontpack::detail
