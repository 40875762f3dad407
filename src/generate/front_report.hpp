// What a generator's run reports (advance_front(), advance_boundary()): its counters, for
// diagnostics, and why it stopped. Each run returns its own; fill() sums them over the polygons
// into FillStats and Packing::truncated and cancelled. Standard library only.
#pragma once

#include <cstddef>

namespace frontpack::detail {

struct FrontReport {
  std::size_t attempts = 0;          ///< tangent positions computed
  std::size_t cuts = 0;              ///< cases (b)-(d)
  std::size_t blocked_segments = 0;  ///< the paper's fronts: segments retired because a disk off the window overlapped
  std::size_t exact_checks = 0;      ///< overlap tests close enough to need the exact predicate (acceptance.hpp)
  std::size_t void_fills = 0;        ///< disks placed in voids left behind the front
  std::size_t skipped_radii = 0;     ///< the boundary front: radii drawn at the end that fitted no void
  std::size_t cavities = 0;          ///< the boundary front: points of cavities given a void
  bool truncated = false;            ///< stopped at FrontSettings::max_disks
  bool cancelled = false;            ///< FrontSettings::tick returned false
  bool over_memory = false;          ///< stopped before the disks would take more than memory_limit
  std::size_t fixed_bytes = 0;       ///< what the run's grids took besides the disks (for the message)
};

}  // namespace frontpack::detail
