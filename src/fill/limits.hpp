// What a fill may take: the disk-count and memory estimates checked against FillOptions::max_disks
// and memory_limit before the run, and why a run placed no disk. CGAL-free.
#pragma once

#include <cstddef>

#include "frontpack/fill.hpp"
#include "options/clearance.hpp"

namespace frontpack::detail {

struct RunBudget {
  double estimate = 0;           ///< disks a dense packing of every polygon's box takes
  std::size_t memory_bytes = 0;  ///< what the run may take (0: no limit), for the generators
};

/// The estimate of the disks a fill makes, and the memory it may take (options.memory_limit, or
/// three quarters of the physical memory if 0). Throws LimitError if the estimate exceeds
/// options.max_disks, or if its disks at peak_bytes_per_disk each exceed the memory limit. A fill
/// to a count (options.count > 0: the plain fill under fill_to_count) makes at most
/// `generation_cap` disks, and is estimated so.
[[nodiscard]] RunBudget check_limits(const Domain& domain, const FillOptions& options, const RadiusDistribution& radii,
                                     std::size_t generation_cap);

/// Throws NothingFitsError naming why the fill of `domain` with `options` gave `packing` no disk:
/// a fraction or a level that keeps none, radii larger than the domain holds, a start point
/// outside the domain, a clearance (given, or the one the precision at the domain's coordinates
/// needs) that leaves no room; else the disks generated, none inside.
[[noreturn]] void throw_nothing_fits(const Domain& domain, const FillOptions& options, const Packing& packing);

}  // namespace frontpack::detail
