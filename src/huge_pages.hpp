// An allocator for the generators' large working arrays (the nodes, the front links, the grid's
// cell heads): blocks of 2 MiB and more are aligned to 2 MiB and offered to the kernel for
// transparent huge pages (Linux, madvise). A million-disk front touches tens of megabytes; with
// 4 KiB pages that is thousands of page faults and, in the grid scans, TLB misses. Elsewhere, and
// for small blocks, it is the standard allocator. Also move_out(), which copies the nodes out as
// disks while giving their memory back. Header-only and CGAL-free (hot loops).
#pragma once

#include <algorithm>
#include <cassert>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <limits>
#include <memory>
#include <new>
#include <vector>

#if defined(__linux__)
#include <sys/mman.h>
#endif

#include "frontpack/geometry.hpp"

namespace frontpack::detail {

template <class T>
struct HugePageAllocator {
  using value_type = T;
  static constexpr std::size_t kHuge = std::size_t{1} << 21;

  HugePageAllocator() = default;
  template <class U>
  constexpr HugePageAllocator(const HugePageAllocator<U>& /*other*/) noexcept {}  // NOLINT(*-explicit-*)

  [[nodiscard]] T* allocate(std::size_t n) {
    if (n > static_cast<std::size_t>(-1) / sizeof(T)) {
      throw std::bad_array_new_length();
    }
    const std::size_t bytes = n * sizeof(T);
#if defined(__linux__)
    if (bytes >= kHuge) {
      if (bytes > std::numeric_limits<std::size_t>::max() - kHuge) {
        throw std::bad_alloc();  // the rounding up would wrap
      }
      const std::size_t rounded = (bytes + kHuge - 1) / kHuge * kHuge;
      void* p = std::aligned_alloc(kHuge, rounded);
      if (p == nullptr) {
        throw std::bad_alloc();
      }
      ::madvise(p, rounded, MADV_HUGEPAGE);  // advice only: on failure, ordinary pages
      return static_cast<T*>(p);
    }
#endif
    return std::allocator<T>().allocate(n);
  }

  void deallocate(T* p, std::size_t n) noexcept {
#if defined(__linux__)
    if (n * sizeof(T) >= kHuge) {
      std::free(p);  // NOLINT(*-no-malloc, *-owning-memory): allocated by aligned_alloc
      return;
    }
#endif
    std::allocator<T>().deallocate(p, n);
  }

  template <class U>
  friend constexpr bool operator==(const HugePageAllocator& /*a*/, const HugePageAllocator<U>& /*b*/) noexcept {
    return true;
  }
};

/// A vector in huge pages when large.
template <class T>
using HugeVector = std::vector<T, HugePageAllocator<T>>;

/// Gives the whole pages of `v`'s storage in elements [begin, end) back to the kernel (Linux,
/// MADV_DONTNEED; elsewhere nothing): for a vector that is read once more from front to back
/// before it is freed. Those elements must not be read again.
template <class T>
void discard(HugeVector<T>& v, std::size_t begin, std::size_t end) noexcept {
  assert(begin <= end && end <= v.size());
#if defined(__linux__)
  constexpr std::size_t kPage = 4096;
  const auto base = reinterpret_cast<std::uintptr_t>(v.data());  // NOLINT(*-reinterpret-cast)
  const std::uintptr_t first = (base + begin * sizeof(T) + kPage - 1) / kPage * kPage;
  const std::uintptr_t last = (base + end * sizeof(T)) / kPage * kPage;
  if (last > first) {
    ::madvise(reinterpret_cast<void*>(first), last - first, MADV_DONTNEED);  // NOLINT(*-reinterpret-cast)
  }
#else
  (void)v;
  (void)begin;
  (void)end;
#endif
}

/// Appends the disks of nodes[first, size), shifted by `origin`, to `out` and frees the nodes.
/// The copy gives the nodes' memory back as it goes, a 2 MiB block of the nodes' storage at a
/// time, so that the output's fresh pages are the ones just given back: the peak holds the nodes
/// or the output, not both, and the output's first touches reuse memory the machine has just
/// used (a VM's first touch of memory the host has reclaimed is several times slower). The
/// output is reserved first, so that it never moves (and nothing throws) while nodes are
/// discarded.
template <class Node>
void move_out(HugeVector<Node>& nodes, std::size_t first, Point origin, std::vector<Disk>& out) {
  static_assert(sizeof(Node) <= HugePageAllocator<Node>::kHuge);
  constexpr std::size_t kStep = HugePageAllocator<Node>::kHuge / sizeof(Node);
  if (const std::size_t n = nodes.size() - std::min(first, nodes.size()); out.capacity() - out.size() < n) {
    out.reserve(std::max(out.size() + n, 2 * out.capacity()));  // geometric over several polygons
  }
  std::size_t done = 0;  // nodes[0, done) are discarded
  for (std::size_t i = first; i < nodes.size();) {
    const std::size_t end = std::min(nodes.size(), (i / kStep + 1) * kStep);  // a block boundary
    for (; i < end; ++i) {
      out.push_back(Disk{{origin.x + nodes[i].x, origin.y + nodes[i].y}, nodes[i].r});
    }
    discard(nodes, done, end);
    done = end;
  }
  HugeVector<Node>().swap(nodes);
}

}  // namespace frontpack::detail
