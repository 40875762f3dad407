// The global overlap pass: CGAL-free declaration, defined in certify.cpp (CGAL).
#pragma once

#include <cstddef>
#include <span>
#include <utility>
#include <vector>

#include "frontpack/geometry.hpp"

namespace frontpack::detail {

/// Every pair (i < j) of disks whose interiors intersect, decided exactly, sorted. Candidates
/// come from CGAL::box_self_intersection_d over boxes rounded outwards; `candidates` counts them.
/// Disks with a non-finite centre or radius, or a negative radius, take part in no pair.
void overlapping_pairs(std::span<const Disk> disks, std::vector<std::pair<std::size_t, std::size_t>>& out,
                       std::size_t& candidates);

}  // namespace frontpack::detail
