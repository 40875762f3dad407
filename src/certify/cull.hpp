// Sec. 2.4.5's cull: which disks lie entirely inside the domain, decided exactly
// (Domain::contains, through the domain's edge grid), and removing the others. CGAL-free.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <stop_token>
#include <vector>

#include "frontpack/domain.hpp"
#include "frontpack/geometry.hpp"

namespace frontpack::detail {

/// inside[i] = domain.contains(disks[i]), in blocks of 2^16 disks with `stop` checked between
/// blocks (CancelledError). Precondition: inside.size() == disks.size().
void contains(const Domain& domain, std::span<const Disk> disks, std::span<std::uint8_t> inside,
              const std::stop_token& stop);

/// As contains(), each disk against its own polygon: disks[part_end[p - 1] .. part_end[p]) (from 0
/// for p = 0) came from the fill of polygon p and must lie in that polygon, not merely in the
/// domain: the boxes of two polygons can overlap, and a disk of one polygon's fill inside the other
/// would overlap that polygon's own disks. (A disk inside the domain lies in exactly one polygon:
/// polygons meet at most at points, and a disk minus a point is connected.) With one polygon this
/// is contains() against the domain itself, and so it is with an empty part_end: for disks that
/// stayed in their polygons by construction (the jam stage moves certified disks, none across a
/// wall). Precondition: part_end empty or part_end.back() == disks.size().
void contains_in_own_polygon(const Domain& domain, std::span<const Disk> disks, std::span<const std::size_t> part_end,
                             std::span<std::uint8_t> inside, const std::stop_token& stop);

/// Keeps the disks whose flag equals `keep`, in order, in place (no second copy of the disks).
void keep_where(std::vector<Disk>& disks, const std::vector<std::uint8_t>& flag, std::uint8_t keep);

}  // namespace frontpack::detail
