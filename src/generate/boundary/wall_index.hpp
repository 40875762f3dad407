// Where the boundary front finds the walls near a candidate: per cell of the disks' grid, the walls
// within reach of it (built once by counting sort, kept for the blocks of cells that walls come
// near), and a bounding-box tree over the walls for the nearest-wall and point-in-polygon tests.
// Built once per run; the queries are header-only and allocate nothing (every candidate asks).
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "generate/boundary/walls.hpp"
#include "generate/disk_grid.hpp"

namespace frontpack::detail {

/// The memory limit as the set-up checks it: a structure of `bytes` (with what the run has set up
/// before it) at or beyond `limit` (0: none) throws LimitError, saying `what` and counting
/// `estimate` disks.
struct SetupBudget {
  std::size_t limit = 0;
  double estimate = 0;
  void check(std::size_t bytes, const std::string& what) const;
};

class WallIndex {
 public:
  static constexpr std::size_t kBlock = 16;  // cells per side of a block in the walled_ bitmap
  static constexpr std::size_t kBlockCells = kBlock * kBlock;
  static constexpr std::size_t kLeafWalls = 4;  // walls per leaf of the wall tree

  /// What the index takes per block of `grid`'s cells whether or not walls come near (counted
  /// before it is built).
  [[nodiscard]] static std::size_t block_bytes(const CellGrid& grid) noexcept;

  /// Lists, per cell of `grid`, the walls that come within `reach` of it, and builds the tree.
  /// `need`: the bytes the run holds already, for the memory limit. Keeps a pointer to `walls`.
  void build(const std::vector<Wall>& walls, const CellGrid& grid, double reach, std::size_t need,
             const SetupBudget& budget);

  /// The bytes the cell lists hold (the tree and the walls are not counted).
  [[nodiscard]] std::size_t bytes() const noexcept {
    return (wall_ids_.size() + cell_walls_.size() + block_first_.size()) * sizeof(std::uint32_t) +
           walled_.size() * sizeof(std::uint64_t);
  }

  /// Frees the cell lists (before the output grows).
  void release() noexcept;

  /// The range [first, end) of cell (row, col)'s walls for id(): empty in a block no wall comes
  /// near. A bit per block says which: most probes lie in blocks without, and the bits of a whole
  /// front fit in the first-level cache, unlike the cells' lists.
  [[nodiscard]] std::pair<std::uint32_t, std::uint32_t> near_cell(std::size_t row, std::size_t col) const noexcept {
    const std::size_t block = block_of(row, col);
    if ((walled_[block / 64] >> (block % 64) & 1) == 0) {
      return {0, 0};
    }
    const std::uint32_t* at = cell_walls_.data() + block_first_[block] + place_in_block(row, col);
    return {at[0], at[1]};
  }
  /// The k-th entry of the cell lists: a wall's element id.
  [[nodiscard]] std::int32_t id(std::uint32_t k) const noexcept { return wall_ids_[k]; }

  // The walls in a bounding-box tree, for cells whose list is long (a ring of 100,000 short edges
  // puts hundreds of walls within rmax of every cell along it; scanning them all made such rings
  // cost hundreds of microseconds per disk). The tree is implicit over the walls in their order,
  // which follows the rings, so consecutive walls are neighbours and a node's box stays small:
  // leaves of kLeafWalls walls, node k's children 2k and 2k + 1, leaves from index leaves_. Built
  // once; queries allocate nothing. (Boost.Geometry's rtree allocates in its nearest query, and
  // CGAL 5.5's AABB tree is three-dimensional only.)

  // The wall nearest to (x, y) at a squared distance below d2 (on return, its squared distance),
  // or kNoElement. Of walls at the same distance, the first in order, as the cell lists have them.
  // A caller that knows a wall `best` at squared distance d2 passes it: the search then prunes
  // everything farther from the start, and returns `best` if no wall is nearer (or as near and
  // before it in order).
  std::int32_t nearest(double x, double y, double& d2, std::int32_t best = kNoElement) const noexcept {
    // Depth <= 64: at most one deferred sibling per level. Each entry carries its box's squared
    // distance, computed once when it was pushed. Not zeroed: only what was pushed is read, and
    // zeroing the stack was 4% of the instructions on a 12,000-edge ring.
    struct Entry {
      std::size_t node;
      double d2;
    };
    std::array<Entry, 128> stack;  // NOLINT(cppcoreguidelines-pro-type-member-init)
    std::size_t top = 0;
    stack[top++] = Entry{1, distance2(tree_[1], x, y)};
    while (top > 0) {
      const auto [k, box_d2] = stack[--top];
      if (!(box_d2 <= d2)) {
        continue;
      }
      if (k >= leaves_) {
        const std::size_t first = (k - leaves_) * kLeafWalls;
        const std::size_t last = std::min(first + kLeafWalls, walls_->size());
        for (std::size_t e = first; e < last; ++e) {
          const double w2 = detail::distance2((*walls_)[e], x, y);
          const auto id = wall_id(e);
          if (w2 < d2 || (w2 == d2 && best != kNoElement && id > best)) {
            d2 = w2;
            best = id;
          }
        }
        continue;
      }
      // The nearer child on top, so that it is searched first and prunes the other.
      const Entry left{2 * k, distance2(tree_[2 * k], x, y)};
      const Entry right{2 * k + 1, distance2(tree_[2 * k + 1], x, y)};
      const bool left_first = left.d2 <= right.d2;
      stack[top++] = left_first ? right : left;
      stack[top++] = left_first ? left : right;
    }
    return best;
  }

  // Crossing number (floating point: the points asked about are seed centres and candidates that
  // touch only walls, at least their radius from every wall).
  [[nodiscard]] bool inside(double x, double y) const noexcept {
    // The walls whose boxes meet the ray from (x, y) to the right, from the wall tree.
    bool in = false;
    std::array<std::size_t, 128> stack;  // NOLINT(cppcoreguidelines-pro-type-member-init): see nearest()
    std::size_t top = 0;
    stack[top++] = 1;
    while (top > 0) {
      const std::size_t k = stack[--top];
      const Bounds& b = tree_[k];
      if (!(b.ymin <= y && y <= b.ymax && x <= b.xmax)) {
        continue;
      }
      if (k < leaves_) {
        stack[top++] = 2 * k;
        stack[top++] = 2 * k + 1;
        continue;
      }
      const std::size_t first = (k - leaves_) * kLeafWalls;
      const std::size_t last = std::min(first + kLeafWalls, walls_->size());
      for (std::size_t e = first; e < last; ++e) {
        const Wall& w = (*walls_)[e];
        if ((w.ay > y) != (w.by > y)) {
          const double xc = w.ax + (y - w.ay) * (w.bx - w.ax) / (w.by - w.ay);
          in = in != (x < xc);
        }
      }
    }
    return in;
  }

 private:
  struct Bounds {
    double xmin, ymin, xmax, ymax;
  };
  struct Pair;

  [[nodiscard]] std::size_t block_of(std::size_t row, std::size_t col) const noexcept {
    return row / kBlock * blocks_x_ + col / kBlock;
  }
  // Cell (row, col)'s place in its block, the order of the block's lists.
  [[nodiscard]] static std::size_t place_in_block(std::size_t row, std::size_t col) noexcept {
    return row % kBlock * kBlock + col % kBlock;
  }

  // Squared distance from (x, y) to box b (0 inside; infinite for an empty box).
  static double distance2(const Bounds& b, double x, double y) noexcept {
    const double dx = std::max(std::max(b.xmin - x, 0.0), x - b.xmax);
    const double dy = std::max(std::max(b.ymin - y, 0.0), y - b.ymax);
    return dx * dx + dy * dy;
  }

  std::vector<Pair> list_pairs(const CellGrid& grid, double reach, std::size_t need, const SetupBudget& budget) const;
  void group(std::vector<Pair>& pairs, std::size_t blocks, std::size_t need, const SetupBudget& budget);
  void build_tree();

  const std::vector<Wall>* walls_ = nullptr;
  std::vector<std::uint32_t> block_first_;  // per block of cells: its first entry in cell_walls_
  std::vector<std::uint32_t> cell_walls_;   // per cell of a walled block: its first wall in wall_ids_
  std::vector<std::int32_t> wall_ids_;
  std::vector<std::uint64_t> walled_;  // a bit per block of cells: any walls
  std::size_t blocks_x_ = 1;
  std::vector<Bounds> tree_;
  std::size_t leaves_ = 1;
};

}  // namespace frontpack::detail
