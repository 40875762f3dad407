// Uniform grids for floating-point measurements (the statistics, the float distance index over a
// domain's edges): how many cells an axis gets and which cell a coordinate falls in, safe for
// NaN and for lengths beyond the doubles.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace frontpack::detail {

// The cells of a grid along an axis `g` cells long (a length over a cell size, maybe a fraction
// of a cell more): floor(g) + 1, at least 1 and at most `cap`. A NaN (lengths that overflowed, or a
// cell size that underflowed) gives 1: a coarser grid finds the same neighbours, more slowly.
inline std::size_t axis_cells(double g, std::size_t cap) noexcept {
  if (!(g >= 0)) {
    return 1;
  }
  return g < static_cast<double>(cap - 1) ? static_cast<std::size_t>(g) + 1 : cap;
}
constexpr std::size_t kMaxAxisCells = std::size_t{1} << 24;

// Index of the cell of coordinate x in a grid from `origin` with cell size h, clamped to [0, n).
inline std::size_t cell_index(double x, double origin, double inv_h, std::size_t n) noexcept {
  const double t = std::floor((x - origin) * inv_h);
  if (!(t > 0)) {
    return 0;
  }
  return t >= static_cast<double>(n - 1) ? n - 1 : static_cast<std::size_t>(t);
}

// Visits the cells (i, j) of ring k around cell (ci, cj) of an nx x ny grid: those with
// max(|i - ci|, |j - cj|) == k, clipped to the grid, row by row. Searches outwards for the
// nearest of something ring by ring: what a ring k has not met lies outside the (2k + 1)-cell
// block around the cell.
template <class Visit>
void visit_ring(std::size_t ci, std::size_t cj, std::size_t k, std::size_t nx, std::size_t ny, Visit&& visit) {
  const std::size_t i0 = ci >= k ? ci - k : 0;
  const std::size_t i1 = std::min(ci + k, nx - 1);
  const std::size_t j0 = cj >= k ? cj - k : 0;
  const std::size_t j1 = std::min(cj + k, ny - 1);
  for (std::size_t j = j0; j <= j1; ++j) {
    if (j + k == cj || j == cj + k) {
      for (std::size_t i = i0; i <= i1; ++i) {
        visit(i, j);
      }
    } else {
      if (ci >= k) {
        visit(ci - k, j);
      }
      if (ci + k < nx) {
        visit(ci + k, j);
      }
    }
  }
}

}  // namespace frontpack::detail
