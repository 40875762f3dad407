// Sec. 2.4.3's final global search: every pair of overlapping disks, decided exactly, and the
// drop of one disk of each pair. CGAL-free declarations; overlap_pass.cpp uses CGAL.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <stop_token>
#include <utility>
#include <vector>

#include "frontpack/geometry.hpp"

namespace frontpack::detail {

/// Every pair (i < j) of disks whose interiors intersect, decided exactly, sorted. Candidates
/// come from CGAL::box_self_intersection_d over boxes rounded outwards; `candidates` counts them.
/// Disks with a non-finite centre or radius, or a negative radius, take part in no pair. Throws
/// CancelledError once `stop` is requested (checked per tile, about 2^17 disks).
void overlapping_pairs(std::span<const Disk> disks, std::vector<std::pair<std::size_t, std::size_t>>& out,
                       std::size_t& candidates, const std::stop_token& stop = {});

/// Removes one disk of every pair in `pairs` (sorted, as overlapping_pairs() gives them): the
/// later one, unless one of the two is already removed. Deterministic; keeps the order of the
/// others. Returns how many were removed.
std::size_t drop_one_of_each_pair(std::vector<Disk>& disks, std::span<const std::pair<std::size_t, std::size_t>> pairs);

}  // namespace frontpack::detail
