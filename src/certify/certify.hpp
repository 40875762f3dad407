// The certifier's parts (the global overlap pass, exact containment): CGAL-free declarations,
// defined in certify/certify.cpp (CGAL).
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <stop_token>
#include <utility>
#include <vector>

#include "frontpack/domain.hpp"
#include "frontpack/geometry.hpp"

namespace frontpack::detail {

/// Every pair (i < j) of disks whose interiors intersect, decided exactly, sorted. Candidates
/// come from CGAL::box_self_intersection_d over boxes rounded outwards; `candidates` counts them.
/// Disks with a non-finite centre or radius, or a negative radius, take part in no pair. Throws
/// CancelledError once `stop` is requested (checked per tile, about 2^17 disks).
void overlapping_pairs(std::span<const Disk> disks, std::vector<std::pair<std::size_t, std::size_t>>& out,
                       std::size_t& candidates, const std::stop_token& stop = {});

/// Domain::contains in blocks of 2^16 disks, with `stop` checked between blocks.
void contains(const Domain& domain, std::span<const Disk> disks, std::span<std::uint8_t> inside,
              const std::stop_token& stop);

}  // namespace frontpack::detail
