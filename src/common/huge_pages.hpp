// Memory for the generators' large working arrays, and page-level helpers for them.
//
// HugePageAllocator: blocks of 2 MiB and more are aligned to 2 MiB and offered to the kernel for
// transparent huge pages (Linux, madvise); elsewhere, and for small blocks, the standard
// allocator. For arrays read at random across the whole run: the boundary front's nodes, links
// and cell heads, which its voids send the scans all over (4 KiB pages cost that front 8-10% with
// a fault per page, 3.5% prefaulted).
//
// The paper's fronts read near the front only (the last layer's nodes and cells), so their arrays
// are ordinary vectors (4 KiB pages, unless the machine's transparent huge pages are `always`),
// and their nodes are prefaulted in one call (prefault()) instead of a fault per 4 KiB: on this
// project's VM a huge page first touched costs several times what the same memory costs in 4 KiB
// pages once a run needs more than the machine has just freed (10M disks: kernel time 0.9-1.1 s
// with huge pages against 0.4 s; docs/performance.md).
//
// discard() gives pages of a vector's storage back; prefault() faults them in ahead; move_out()
// copies the nodes out as disks while giving their memory back. Header-only and CGAL-free (hot
// loops).
#pragma once

#include <algorithm>
#include <cassert>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <limits>
#include <memory>
#include <new>
#include <utility>
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

namespace page {
constexpr std::size_t kSize = 4096;
// The whole pages of v's storage in elements [begin, end), as [first, last) (empty: last <= first).
// Whole pages only: the allocator's own bookkeeping may share the first and last page.
template <class T, class A>
std::pair<std::uintptr_t, std::uintptr_t> inside(const std::vector<T, A>& v, std::size_t begin,
                                                 std::size_t end) noexcept {
  const auto base = reinterpret_cast<std::uintptr_t>(v.data());  // NOLINT(*-reinterpret-cast)
  return {(base + begin * sizeof(T) + kSize - 1) / kSize * kSize, (base + end * sizeof(T)) / kSize * kSize};
}
}  // namespace page

/// Gives the whole pages of `v`'s storage in elements [begin, end) back to the kernel (Linux,
/// MADV_DONTNEED; elsewhere nothing): for a vector that is read once more from front to back
/// before it is freed. Those elements must not be read again.
template <class T, class A>
void discard(std::vector<T, A>& v, std::size_t begin, std::size_t end) noexcept {
  assert(begin <= end && end <= v.size());
#if defined(__linux__)
  const auto [first, last] = page::inside(v, begin, end);
  if (last > first) {
    ::madvise(reinterpret_cast<void*>(first), last - first, MADV_DONTNEED);  // NOLINT(*-reinterpret-cast)
  }
#else
  (void)v;
  (void)begin;
  (void)end;
#endif
}

/// Faults in the whole pages of `v`'s reserved storage for elements [0, n) (n <= capacity) in one
/// call (Linux 5.14+, MADV_POPULATE_WRITE; advice only: elsewhere, or on failure, the pages are
/// faulted one at a time as they are first written, as without it). Costs no memory beyond what
/// the first n push_backs would touch: n is the caller's estimate of what the run will use.
template <class T, class A>
void prefault(std::vector<T, A>& v, std::size_t n) noexcept {
  assert(n <= v.capacity());
#if defined(__linux__) && defined(MADV_POPULATE_WRITE)
  const auto [first, last] = page::inside(v, 0, n);
  if (last > first) {
    ::madvise(reinterpret_cast<void*>(first), last - first, MADV_POPULATE_WRITE);  // NOLINT(*-reinterpret-cast)
  }
#else
  (void)v;
  (void)n;
#endif
}

/// Appends the disks of nodes[first, size), scaled by `unit` (a power of two: exact) and shifted
/// by `origin`, to `out` and frees the nodes.
/// The copy gives the nodes' memory back as it goes, a 2 MiB block of the nodes' storage at a
/// time, so that the output's fresh pages are the ones just given back: the peak holds the nodes
/// or the output, not both, and the output's first touches reuse memory the machine has just
/// used (a VM's first touch of memory the host has reclaimed is several times slower). The
/// output is reserved first, so that it never moves (and nothing throws) while nodes are
/// discarded.
template <class Node, class A>
void move_out(std::vector<Node, A>& nodes, std::size_t first, Point origin, double unit, std::vector<Disk>& out) {
  static_assert(sizeof(Node) <= HugePageAllocator<Node>::kHuge);
  constexpr std::size_t kStep = HugePageAllocator<Node>::kHuge / sizeof(Node);
  if (const std::size_t n = nodes.size() - std::min(first, nodes.size()); out.capacity() - out.size() < n) {
    out.reserve(std::max(out.size() + n, 2 * out.capacity()));  // geometric over several polygons
  }
  std::size_t done = 0;  // nodes[0, done) are discarded
  for (std::size_t i = first; i < nodes.size();) {
    const std::size_t end = std::min(nodes.size(), (i / kStep + 1) * kStep);  // a block boundary
    for (; i < end; ++i) {
      out.push_back(Disk{{origin.x + nodes[i].x * unit, origin.y + nodes[i].y * unit}, nodes[i].r * unit});
    }
    discard(nodes, done, end);
    done = end;
  }
  std::vector<Node, A>().swap(nodes);
}

}  // namespace frontpack::detail
