// The certifier's two entry points, composed from the same parts (cull.hpp, overlap_pass.hpp,
// report.hpp): frontpack::certify() reports on any set of disks; certify_fill() below removes
// from a fill's output what the report would name. CGAL-free.
#pragma once

#include <cstddef>
#include <span>
#include <stop_token>
#include <vector>

#include "frontpack/fill.hpp"

namespace frontpack::detail {

/// Certifies a fill's raw output in place: culls the disks not inside their own polygon
/// (contains_in_own_polygon(), `part_end` as there; empty: inside the domain, for disks that
/// can have left no polygon for another, as the jam stage's), then drops one disk of every overlapping pair
/// (drop_one_of_each_pair(); frontpack's generators never make one). Returns the certificate and
/// records the two passes' wall times in stats.seconds_cull and stats.seconds_overlap. Throws
/// CancelledError once `stop` is requested.
Certificate certify_fill(const Domain& domain, std::vector<Disk>& disks, std::span<const std::size_t> part_end,
                         const std::stop_token& stop, FillStats& stats);

}  // namespace frontpack::detail
