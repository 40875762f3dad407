// The uniform grid over the placed disks that both generators' neighbour searches run on (the
// boundary front also lists its walls by the same cells), and the scan over a block of its cells.
// Header-only and CGAL-free: every candidate disk scans it. Not common/bucket_grid.hpp's lists,
// which are built once from a whole list: this grid grows one disk at a time as the fronts place
// them (a chain per cell, its heads gathered without a branch by visit_cells()).
#pragma once

#include <array>
#include <cassert>
#include <cmath>
#include <cstddef>
#include <cstdint>

namespace frontpack::detail {

/// Square cells over the box [xmin, xmin + w] x [ymin, ymin + h] grown by 4 rmax on every side.
/// The cells are rmax wide, or wider where that would make more than about 16M cells (a domain of
/// more than about 11 million disks at rmax / rmin = 10, or an absurd aspect ratio): then the side
/// grows to just what the cap allows. Points outside map to the border cells (col() and row()
/// clamp). A search covers the cells its reach spans, whatever their size. Narrower cells fit the
/// box a scan spans more tightly to the reach (fewer disks tested, each a likely cache miss) but
/// put more cells in it. Since visit_cells() reads a block's cell heads without a branch, an empty
/// cell costs little: from 1.5 rmax to rmax, the open front became 9% and the boundary front 8%
/// faster (at 0.75 rmax, the boxes outgrow kGatherCells; 0.9 and 1.1 rmax measured no better),
/// for 3 more bytes per disk of cell heads, freed before the output grows (docs/performance.md).
struct CellGrid {
  double x0 = 0, y0 = 0;  // lower-left corner
  double side = 1, inv_side = 1;
  std::size_t nx = 1, ny = 1;
  bool coarse = false;  // one_cell(): the margin is not 4 rmax

  CellGrid() = default;
  CellGrid(double xmin, double ymin, double w, double h, double rmax) {
    const double margin = 4 * rmax;
    x0 = xmin - margin;
    y0 = ymin - margin;
    const double gw = w + 2 * margin;
    const double gh = h + 2 * margin;
    if (!(std::isfinite(gw) && std::isfinite(gh))) {
      one_cell(xmin, ymin);  // rmax beyond about 2e307: no cell size fits the range of doubles
      return;
    }
    side = rmax;
    if (const double fit = std::sqrt(gw * gh / 16e6); fit > side) {
      side = fit;  // about 16M cells; the loop below allows for the cells cut at the edges
    }
    while ((gw / side + 1) * (gh / side + 1) > 16e6) {
      side *= 1.0625;
    }
    inv_side = 1.0 / side;
    if (!std::isfinite(inv_side)) {
      one_cell(xmin, ymin);  // a subnormal rmax in a domain as small
      return;
    }
    nx = static_cast<std::size_t>(gw * inv_side) + 1;
    ny = static_cast<std::size_t>(gh * inv_side) + 1;
    last_col_ = static_cast<double>(nx - 1);
    last_row_ = static_cast<double>(ny - 1);
  }

  [[nodiscard]] std::size_t cells() const noexcept { return nx * ny; }
  [[nodiscard]] std::int64_t col(double x) const noexcept { return clamp((x - x0) * inv_side, last_col_); }
  [[nodiscard]] std::int64_t row(double y) const noexcept { return clamp((y - y0) * inv_side, last_row_); }
  [[nodiscard]] std::size_t cell_of(double x, double y) const noexcept {
    return static_cast<std::size_t>(row(y)) * nx + static_cast<std::size_t>(col(x));
  }
  // col() and row() for a coordinate known to lie in the grid (within its margin of 4 rmax around
  // the box): the same cell, without the clamping.
  [[nodiscard]] std::int64_t col_inside(double x) const noexcept {
    const double g = (x - x0) * inv_side;
    assert(g >= 0 && g < last_col_ + 1);
    return static_cast<std::int64_t>(g);
  }
  [[nodiscard]] std::int64_t row_inside(double y) const noexcept {
    const double g = (y - y0) * inv_side;
    assert(g >= 0 && g < last_row_ + 1);
    return static_cast<std::int64_t>(g);
  }

 private:
  double last_col_ = 0, last_row_ = 0;  // nx - 1, ny - 1

  // Where lengths overflow or a cell's reciprocal does: one cell, 2^1022 wide, whose lower-left
  // corner lies 2^1020 below and left of the box, so that every coordinate within 2^1021 of the
  // box maps to it exactly and every scan covers it (the scans are then linear, but disks that
  // large, or that small, are few).
  void one_cell(double xmin, double ymin) noexcept {
    x0 = xmin - 0x1p1020;
    y0 = ymin - 0x1p1020;
    side = 0x1p1022;
    inv_side = 0x1p-1022;
    nx = ny = 1;
    last_col_ = last_row_ = 0;
    coarse = true;
  }

  // g's cell index, clamped to [0, last]: compared before the conversion, which would be undefined
  // for a huge or infinite g.
  static std::int64_t clamp(double g, double last) noexcept {
    if (!(g > 0)) {
      return 0;  // also NaN
    }
    return static_cast<std::int64_t>(g < last ? g : last);
  }
};

/// How many cells a scan's block may have for visit_cells() to gather their first disks.
inline constexpr std::size_t kGatherCells = 32;

/// Visits the disks in the cells [c0, c1] x [r0, r1] (0 <= c0 <= c1 < nx, 0 <= r0 <= r1 < the rows
/// of `heads`) of a grid whose cell i's disks are the chain heads[i], nodes[heads[i]].cell_next,
/// ... ending at `none`: visit(d, node) for each, in the order of the rows, the cells in them and
/// the chains, until it returns true. Returns whether it did. In a block of up to kGatherCells
/// cells, the chains' first disks are gathered, without a branch, and prefetched before any is
/// visited, so that their loads overlap; walked one cell after another, each chain waited for the
/// one before (a scan is longer than the processor looks ahead). Empty cells prefetch an address
/// computed from `none` in integer arithmetic (a prefetch never faults): a branch or a select
/// there cost the gain. Measurements in docs/performance.md.
template <class Node, class Visit>
[[gnu::always_inline]] inline bool visit_cells(const std::int32_t* heads, std::size_t nx, const Node* nodes,
                                               std::int32_t none, std::int64_t c0, std::int64_t c1, std::int64_t r0,
                                               std::int64_t r1, Visit&& visit) {
  const auto cols = static_cast<std::size_t>(c1 - c0 + 1);
  const auto rows = static_cast<std::size_t>(r1 - r0 + 1);
  auto row = [&](std::size_t j) {
    return heads + (static_cast<std::size_t>(r0) + j) * nx + static_cast<std::size_t>(c0);
  };
  auto chain = [&](std::int32_t d) {  // visits the chain from d; whether visit() said stop
    while (d != none) {
      const Node& o = nodes[d];
      if (visit(d, o)) {
        return true;
      }
      d = o.cell_next;
    }
    return false;
  };
  assert(c0 >= 0 && c0 <= c1 && static_cast<std::size_t>(c1) < nx && r0 >= 0 && r0 <= r1);
  std::array<std::int32_t, kGatherCells> first;  // NOLINT(cppcoreguidelines-pro-type-member-init): written before read
  // More cells than that: always with a clearance c above about 2/3 rmax; below it, for a radius
  // near rmax, with a probability of about (1.5 c / rmax)^2 (never, in practice, at the automatic
  // clearance of a few ulps).
  if (cols * rows > first.size()) {
    for (std::size_t j = 0; j < rows; ++j) {
      for (std::size_t i = 0; i < cols; ++i) {
        if (chain(row(j)[i])) {
          return true;
        }
      }
    }
    return false;
  }
  std::size_t count = 0;
  const auto base = reinterpret_cast<std::uintptr_t>(nodes);  // NOLINT(*-reinterpret-cast)
  for (std::size_t j = 0; j < rows; ++j) {
    for (std::size_t i = 0; i < cols; ++i) {
      const std::int32_t d = row(j)[i];
      const std::uintptr_t at = base + static_cast<std::uintptr_t>(static_cast<std::intptr_t>(d)) * sizeof(Node);
#if defined(__GNUC__)
      __builtin_prefetch(reinterpret_cast<const void*>(at));  // NOLINT(*-reinterpret-cast, performance-no-int-to-ptr)
#else
      (void)at;
#endif
      first[count] = d;
      count += d != none ? 1 : 0;
    }
  }
  for (std::size_t k = 0; k < count; ++k) {
    if (chain(first[k])) {
      return true;
    }
  }
  return false;
}

}  // namespace frontpack::detail
