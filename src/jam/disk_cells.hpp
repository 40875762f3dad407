// The disks of the jam stage sorted into the cells of a uniform grid, for the neighbour searches of
// the relaxation (its pair lists) and of the insertion (the clearance of a point). Every disk whose
// centre lies within `reach` of a point of a cell lies in the 3 x 3 cells around it, wrapped on a
// periodic axis. The lists are common/bucket_grid.hpp's; the wrapped neighbours and the whole cells
// that tile a period (each axis its own cell size) are the jam's own.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "common/bucket_grid.hpp"
#include "frontpack/geometry.hpp"

namespace frontpack::detail {

class DiskCells {
 public:
  /// Sorts `disks` (centres in `cell`, or within reach of it on an axis that does not wrap) into
  /// cells at least `reach` wide. Disks are indexed in 32 bits: fewer than 2^32 of them.
  void build(const std::vector<Disk>& disks, const Box& cell, bool wrap_x, bool wrap_y, double reach) {
    wrap_x_ = wrap_x;
    wrap_y_ = wrap_y;
    const double margin_x = wrap_x ? 0 : reach;
    const double margin_y = wrap_y ? 0 : reach;
    const double x0 = cell.xmin - margin_x;
    const double y0 = cell.ymin - margin_y;
    const double w = cell.xmax - cell.xmin + 2 * margin_x;
    const double h = cell.ymax - cell.ymin + 2 * margin_y;
    // Cells at least `reach` wide, and at most 4 per disk: a domain whose parts lie far apart covers
    // little of its box (a square and a speck 1,000 away: a millionth), and cells of `reach` there
    // would be billions. Larger cells find the same disks, scanning more.
    // (w * h may overflow where w and h do not: then the root of each.)
    const double most = std::max(1024.0, 4.0 * static_cast<double>(disks.size()));
    const double area = w * h;
    const double side = !((w / reach) * (h / reach) > most) ? reach
                        : std::isfinite(area)               ? std::sqrt(area / most)
                                                            : std::sqrt(w / most) * std::sqrt(h);
    // Whole cells of at least `side` (the last takes what is left), so that every disk within reach
    // lies in neighbouring cells. On a periodic axis they tile the period (at least 3 of them, each
    // still wider than reach: the cell is at least 10 rmax across, reach at most about 2.5 rmax), so
    // that the neighbours of a cell wrap onto whole cells.
    // (A NaN ratio, from lengths beyond the doubles: one cell, which finds every disk.)
    const auto cells = [side](double length, bool wrap) {
      const double g = length / side;
      const std::size_t whole = g >= 1 ? static_cast<std::size_t>(std::min(g, static_cast<double>(kMaxAxisCells))) : 0;
      return std::max<std::size_t>(wrap ? 3 : 1, whole);
    };
    frame_.x0 = x0;
    frame_.y0 = y0;
    frame_.nx = cells(w, wrap_x);
    frame_.ny = cells(h, wrap_y);
    frame_.inv_x = static_cast<double>(frame_.nx) / w;
    frame_.inv_y = static_cast<double>(frame_.ny) / h;
    grid_.build(frame_.cells(), disks.size(),
                [this, &disks](std::size_t i, auto&& emit) { emit(frame_.cell_of(disks[i].centre)); });
  }

  [[nodiscard]] std::size_t cells() const noexcept { return frame_.cells(); }
  [[nodiscard]] std::size_t cell_of(Point p) const noexcept { return frame_.cell_of(p); }
  /// The disks of cell c: item(begin(c)) .. item(end(c) - 1).
  [[nodiscard]] std::uint32_t begin(std::size_t c) const noexcept { return grid_.begin(c); }
  [[nodiscard]] std::uint32_t end(std::size_t c) const noexcept { return grid_.end(c); }
  [[nodiscard]] std::uint32_t item(std::uint32_t e) const noexcept { return grid_.item(e); }

  /// Calls visit(k) for each of the 3 x 3 cells k around cell c (c included) that the grid has,
  /// row by row from below.
  template <class Visit>
  void neighbours(std::size_t c, Visit&& visit) const {
    const std::size_t nx = frame_.nx;
    const std::size_t cx = c % nx;
    const std::size_t cy = c / nx;
    for (int oy = -1; oy <= 1; ++oy) {
      std::size_t ky = 0;
      if (!step(cy, oy, frame_.ny, wrap_y_, ky)) {
        continue;
      }
      for (int ox = -1; ox <= 1; ++ox) {
        std::size_t kx = 0;
        if (step(cx, ox, nx, wrap_x_, kx)) {
          visit(ky * nx + kx);
        }
      }
    }
  }

 private:
  // The cell `offset` (-1, 0 or 1) from cell c of an axis of n cells, wrapped on a periodic axis;
  // false where the grid ends.
  static bool step(std::size_t c, int offset, std::size_t n, bool wrap, std::size_t& out) noexcept {
    if (offset < 0 && c == 0) {
      out = n - 1;
      return wrap;
    }
    if (offset > 0 && c + 1 == n) {
      out = 0;
      return wrap;
    }
    out = offset < 0 ? c - 1 : offset > 0 ? c + 1 : c;
    return true;
  }

  bool wrap_x_ = false;
  bool wrap_y_ = false;
  // Whole cells over the cell and its margins; 32-bit offsets (fewer than 2^32 disks, each listed
  // once), reused from build to build: nothing is allocated once the lists have grown.
  GridFrame frame_;
  BucketGrid<std::uint32_t, std::uint32_t> grid_;
};

}  // namespace frontpack::detail
