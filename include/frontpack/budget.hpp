// What a call may make. Every count frontpack derives from its input before making it (free
// disks, wall disks, arc segments, hole probes, coverage cells, periodic images) is estimated first
// and held to one Budget: refused up front with the estimate in a LimitError, never discovered as
// an allocation failure or a run that does not end. docs/robustness.md, "Derived counts", lists
// each count, its estimate and its bytes per item.
#pragma once

#include <cstddef>

namespace frontpack {

struct Budget {
  /// The most items of any one kind a call makes (the tool's --max-disks). 0: no count limit.
  std::size_t max_count = 50'000'000;
  /// The memory a call may take, in bytes (the tool's --memory-limit); 0: three quarters of the
  /// machine's physical memory.
  std::size_t memory_limit = 0;
};

}  // namespace frontpack
