// A uniform grid whose cells list items (disks, edges): the float grids of the statistics, the jam,
// the thinning and the distance index over a domain's edges, written once. The grid is a frame
// (origin, cell sizes, cells per axis; a coordinate's cell by grid_cells.hpp's cell_index) and the
// lists in compressed rows: the items of cell c are items()[begin(c), end(c)), filled by a counting
// sort, so that every cell lists its items in ascending order of their indices, whatever the order
// in which the cells of one item are named. That order is what the users' sums and scans rely on
// for bit-identical output.
//
// Not for the generator's grid over placed disks (generate/disk_grid.hpp): it grows one disk at a
// time, a chain per cell, while every grid here is built once from a whole list.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "common/grid_cells.hpp"
#include "frontpack/geometry.hpp"

namespace frontpack::detail {

/// Where the cells of a uniform grid lie: cell (i, j) is [x0 + i / inv_x, x0 + (i + 1) / inv_x) x
/// [y0 + j / inv_y, ...), numbered j * nx + i; coordinates outside map to the border cells.
struct GridFrame {
  double x0 = 0;
  double y0 = 0;
  double inv_x = 1;  ///< cells per unit of x
  double inv_y = 1;  ///< cells per unit of y
  std::size_t nx = 1;
  std::size_t ny = 1;

  [[nodiscard]] std::size_t cells() const noexcept { return nx * ny; }
  [[nodiscard]] std::size_t column(double x) const noexcept { return cell_index(x, x0, inv_x, nx); }
  [[nodiscard]] std::size_t row(double y) const noexcept { return cell_index(y, y0, inv_y, ny); }
  [[nodiscard]] std::size_t cell_of(Point p) const noexcept { return row(p.y) * nx + column(p.x); }

  /// Calls visit(c) for each cell of the block [i0, i1] x [j0, j1], row by row from below.
  template <class Visit>
  void visit_block(std::size_t i0, std::size_t i1, std::size_t j0, std::size_t j1, Visit&& visit) const {
    for (std::size_t j = j0; j <= j1; ++j) {
      for (std::size_t i = i0; i <= i1; ++i) {
        visit(j * nx + i);
      }
    }
  }

  /// Calls visit(c) for each cell that the box meets (its corners' cells and those between), row
  /// by row from below.
  template <class Visit>
  void visit_box(const Box& b, Visit&& visit) const {
    visit_block(column(b.xmin), column(b.xmax), row(b.ymin), row(b.ymax), visit);
  }
};

/// The lists of a grid's cells. `Index` holds an item's index, `Offset` a position in the lists
/// (32 bits where the count of listings is known to fit, as the jam's).
template <class Index = std::uint32_t, class Offset = std::size_t>
class BucketGrid {
 public:
  /// Lists each item k < `items` in every cell c < `cells` for which cells_of(k, emit) calls
  /// emit(c) (at most once per cell for one item). cells_of is called twice per item, to count and
  /// to place, and must name the same cells both times. The vectors are kept from build to build:
  /// a grid rebuilt no larger allocates nothing.
  template <class CellsOf>
  void build(std::size_t cells, std::size_t items, CellsOf&& cells_of) {
    start_.assign(cells + 1, 0);
    for (std::size_t k = 0; k < items; ++k) {
      cells_of(k, [this](std::size_t c) { ++start_[c + 1]; });
    }
    for (std::size_t c = 0; c < cells; ++c) {
      start_[c + 1] += start_[c];
    }
    items_.resize(static_cast<std::size_t>(start_.back()));
    fill_.assign(start_.begin(), start_.end() - 1);
    for (std::size_t k = 0; k < items; ++k) {
      cells_of(k, [this, k](std::size_t c) { items_[static_cast<std::size_t>(fill_[c]++)] = static_cast<Index>(k); });
    }
  }

  /// Lists each point of `points` in the cell of `frame` that holds it.
  void build(const GridFrame& frame, std::span<const Point> points) {
    build(frame.cells(), points.size(), [&](std::size_t k, auto&& emit) { emit(frame.cell_of(points[k])); });
  }

  /// Lists each item k < `items` in every cell of `frame` that box_of(k) meets.
  template <class BoxOf>
  void build_boxes(const GridFrame& frame, std::size_t items, BoxOf&& box_of) {
    build(frame.cells(), items, [&](std::size_t k, auto&& emit) { frame.visit_box(box_of(k), emit); });
  }

  [[nodiscard]] bool empty() const noexcept { return start_.empty(); }
  [[nodiscard]] std::size_t cells() const noexcept { return start_.empty() ? 0 : start_.size() - 1; }
  /// The listings of cell c: item(begin(c)) .. item(end(c) - 1).
  [[nodiscard]] Offset begin(std::size_t c) const noexcept { return start_[c]; }
  [[nodiscard]] Offset end(std::size_t c) const noexcept { return start_[c + 1]; }
  [[nodiscard]] Index item(Offset e) const noexcept { return items_[static_cast<std::size_t>(e)]; }
  /// The items of cell c, in ascending order.
  [[nodiscard]] std::span<const Index> items(std::size_t c) const noexcept {
    return std::span<const Index>(items_).subspan(static_cast<std::size_t>(start_[c]),
                                                  static_cast<std::size_t>(start_[c + 1] - start_[c]));
  }
  /// Calls visit(item) for each item of cell c, in ascending order.
  template <class Visit>
  void visit(std::size_t c, Visit&& visit) const {
    for (Offset e = start_[c]; e < start_[c + 1]; ++e) {
      visit(items_[static_cast<std::size_t>(e)]);
    }
  }
  /// Calls visit(item) for each listing of the cells of `frame` that `query` meets: cell by cell,
  /// row by row from below, each cell's items in ascending order (an item listed in several of
  /// these cells comes once for each).
  template <class Visit>
  void visit_box(const GridFrame& frame, const Box& query, Visit&& visit) const {
    frame.visit_box(query, [&](std::size_t c) { this->visit(c, visit); });
  }

 private:
  std::vector<Offset> start_;
  std::vector<Index> items_;
  std::vector<Offset> fill_;
};

}  // namespace frontpack::detail
