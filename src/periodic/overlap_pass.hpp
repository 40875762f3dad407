// The global overlap pass of a periodic cell (Domain::periodic): every pair of disks where one
// meets an image of the other, decided exactly against the exact periods. CGAL-free declarations.
#pragma once

#include <cstddef>
#include <span>
#include <stop_token>
#include <utility>
#include <vector>

#include "frontpack/domain.hpp"
#include "frontpack/geometry.hpp"

namespace frontpack::detail {

/// Every pair (i, j), i <= j, such that disk i overlaps (interiors intersect) disk j translated by
/// (kx (xmax - xmin), ky (ymax - ymin)) for some integers kx, ky (ky = 0 for Periodicity::x),
/// decided exactly; (i, i) when a disk overlaps its own image (its diameter exceeds a period).
/// Sorted. Centres need not lie in the cell (a simulation's dump): each is wrapped by a whole
/// number of periods for the search, and the exact test uses the total shift. Disks with a
/// non-finite centre or radius, a negative radius, or a centre more than 2^50 periods from the
/// cell take part in no pair. `candidates` counts the pairs whose boxes met for some image.
/// Precondition: domain.periodicity() != Periodicity::none. Throws CancelledError once `stop` is
/// requested.
void periodic_overlapping_pairs(const Domain& domain, std::span<const Disk> disks,
                                std::vector<std::pair<std::size_t, std::size_t>>& out, std::size_t& candidates,
                                const std::stop_token& stop = {});

/// r_a + r_b - |c_a - c_b| with the nearest image of b (floating point, for reports); with
/// `same` (a pair (i, i)), the nearest image other than the disk itself.
[[nodiscard]] double periodic_overlap_depth(const Domain& domain, const Disk& a, const Disk& b, bool same);

}  // namespace frontpack::detail
