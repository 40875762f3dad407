// What a front keeps for a periodic cell besides its nodes: the images of the disks near a
// periodic side (wrap.hpp: in the grid only, so that every neighbour search sees them),
// and the cycles a front that meets itself splits into (FrontList::splice()). Header-only and
// CGAL-free: the closed form adds images as it places disks.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "common/release.hpp"
#include "frontpack/geometry.hpp"
#include "periodic/wrap.hpp"

namespace frontpack::detail {

/// A Node has x, y, r, cell_next and the flag `image`; kNone ends a grid chain.
template <class Node, std::int32_t kNone>
class PeriodicImages {
 public:
  PeriodicWrap wrap;  // local
  /// The front has met itself across the cell (it no longer turns about its start).
  bool wrapped = false;

  /// The images of node id within `reach` of the cell: nodes flagged `image`, in the grid
  /// (`head`, `grid`) and not on the front; `add_links()` gives each the front's links.
  template <class Grid, class AddLinks>
  void add(std::vector<Node>& nodes, std::vector<std::int32_t>& head, const Grid& grid, std::int32_t id, double reach,
           AddLinks&& add_links) {
    const Node o = nodes[static_cast<std::size_t>(id)];
    std::array<std::array<double, 2>, 3> shifts{};
    const std::size_t n = wrap.image_shifts(o.x, o.y, reach, shifts);
    for (std::size_t k = 0; k < n; ++k) {
      const double x = o.x + shifts[k][0];
      const double y = o.y + shifts[k][1];
      const std::size_t c = grid.cell_of(x, y);
      const auto image = static_cast<std::int32_t>(nodes.size());
      Node copy = o;
      copy.x = x;
      copy.y = y;
      copy.cell_next = head[c];
      copy.inside = copy.blocked = copy.on_front = 0;
      copy.image = 1;
      nodes.push_back(copy);
      head[c] = image;
      add_links();
      image_of_.resize(nodes.size(), kNone);
      image_of_.back() = id;
      ++count_;
    }
  }

  /// How many images there are.
  [[nodiscard]] std::size_t count() const noexcept { return count_; }

  /// The node whose image `id` is (id itself for a disk in the cell).
  [[nodiscard]] std::int32_t real(const std::vector<Node>& nodes, std::int32_t id) const noexcept {
    return nodes[static_cast<std::size_t>(id)].image != 0 ? image_of_[static_cast<std::size_t>(id)] : id;
  }

  /// Node o as seen from (x, y): its minimum image.
  [[nodiscard]] Node seen_from(Node o, double x, double y) const noexcept {
    o.x = x + wrap.dx(o.x - x);
    o.y = y + wrap.dy(o.y - y);
    return o;
  }

  /// A cycle that a split left apart starts at n.
  void keep_entry(std::int32_t n) { entries_.push_back(n); }

  /// The entry of a cycle still on the front (`on_front(id)`), from those kept: false if none.
  template <class OnFront>
  bool next_cycle(std::int32_t& cur, OnFront&& on_front) {
    while (!entries_.empty()) {
      const std::int32_t e = entries_.back();
      entries_.pop_back();
      if (on_front(e)) {
        cur = e;
        return true;
      }
    }
    return false;
  }

  /// Removes the images from nodes[first, end) (the grid is gone), keeping the disks' order.
  void drop(std::vector<Node>& nodes, std::size_t first) {
    if (count_ == 0) {
      return;
    }
    std::size_t kept = first;
    for (std::size_t i = first; i < nodes.size(); ++i) {
      if (nodes[i].image == 0) {
        nodes[kept++] = nodes[i];
      }
    }
    nodes.resize(kept);
    release(image_of_);
    release(entries_);
  }

 private:
  std::vector<std::int32_t> image_of_;  // per node: the disk an image is of
  std::size_t count_ = 0;
  std::vector<std::int32_t> entries_;  // entries of cycles that splits left apart
};

}  // namespace frontpack::detail
