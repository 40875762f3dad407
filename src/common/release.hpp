// Freeing a vector's memory, which clear() keeps.
#pragma once

#include <vector>

namespace frontpack::detail {

/// Frees a vector's memory (clear() keeps it): the generators free their working arrays before
/// copying the disks out, so that the peak holds the disks and the output only.
template <class T, class A>
void release(std::vector<T, A>& v) {
  std::vector<T, A>().swap(v);
}

}  // namespace frontpack::detail
