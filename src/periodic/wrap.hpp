// A periodic cell as a front sees it (Domain::periodic()): in a run's local units, the cell is
// [0, lx) x [0, ly); a disk's centre is kept in it on each periodic axis, and a disk near a
// periodic side has images, translated by a period, in the grid's margin, so that a neighbour
// search from a centre in the cell finds every disk it could touch, images included, with no
// change to the search itself. Header-only and CGAL-free: the fronts use it per candidate.
//
// The periods here are rounded (the local difference of the cell's bounds); the exact ones are
// the certifier's. The difference, half an ulp of the cell's size, is far inside the clearance's
// margin, which keeps every accepted pair apart by more than the rounding of coordinates can take
// away (acceptance.hpp), so the pairs across a side are certified as the others are.
#pragma once

#include <array>
#include <cstddef>
#include <span>

#include "frontpack/geometry.hpp"

namespace frontpack::detail {

struct PeriodicWrap {
  bool x = false;  // wraps in x
  bool y = false;  // wraps in y
  double lx = 0;   // the periods, local
  double ly = 0;

  [[nodiscard]] bool any() const noexcept { return x || y; }

  /// The displacement d (a difference of two coordinates in the cell, |d| < the period) made the
  /// shortest among its images: the minimum image. Exact for |d| <= half the period; used where
  /// the two disks are known to be near (a front segment, a window walk), which a cell at least
  /// 10 rmax wide guarantees (the periodic check of the options).
  [[nodiscard]] double dx(double d) const noexcept { return x ? shortest(d, lx) : d; }
  [[nodiscard]] double dy(double d) const noexcept { return y ? shortest(d, ly) : d; }

  /// A coordinate within a period of the cell brought into it: [0, l).
  [[nodiscard]] double wrap_x(double v) const noexcept { return x ? into(v, lx) : v; }
  [[nodiscard]] double wrap_y(double v) const noexcept { return y ? into(v, ly) : v; }

  /// A point within a period of `cell` (the cell in the caller's coordinates, whose sides are
  /// lx and ly apart) brought into it on each periodic axis; a coordinate already in the cell stays
  /// as it is, bit for bit.
  [[nodiscard]] Point into_cell(Point p, const Box& cell) const noexcept {
    if (x && (p.x < cell.xmin || p.x >= cell.xmax)) {
      p.x = cell.xmin + into(p.x - cell.xmin, lx);
    }
    if (y && (p.y < cell.ymin || p.y >= cell.ymax)) {
      p.y = cell.ymin + into(p.y - cell.ymin, ly);
    }
    return p;
  }

  /// The shifts (multiples of the periods, not (0, 0)) of the images a disk centred at (px, py)
  /// in the cell needs: those within `reach` of the cell. Returns how many it wrote.
  std::size_t image_shifts(double px, double py, double reach,
                           std::array<std::array<double, 2>, 3>& out) const noexcept {
    const double sx = !x ? 0 : (px < reach ? lx : (px > lx - reach ? -lx : 0));
    const double sy = !y ? 0 : (py < reach ? ly : (py > ly - reach ? -ly : 0));
    std::size_t n = 0;
    if (sx != 0) {
      out[n++] = {sx, 0};
    }
    if (sy != 0) {
      out[n++] = {0, sy};
    }
    if (sx != 0 && sy != 0) {
      out[n++] = {sx, sy};
    }
    return n;
  }

 private:
  static double shortest(double d, double l) noexcept {
    if (d > 0.5 * l) {
      return d - l;
    }
    if (d < -0.5 * l) {
      return d + l;
    }
    return d;
  }
  // v + l may round up to l when v is a tiny negative number: then 0, a rounding away.
  static double into(double v, double l) noexcept {
    if (v < 0) {
      v += l;
    } else if (v >= l) {
      v -= l;
    }
    return v >= 0 && v < l ? v : 0;
  }
};

/// The centres written out (cell corner + local position, rounded) kept in the half-open cell
/// [xmin, xmax) on a periodic axis: one that rounded up onto the far bound lay within a rounding
/// of the near one, so it goes there (a move far inside the clearance's margin).
inline void keep_in_cell(const PeriodicWrap& wrap, std::span<Disk> disks, const Box& cell) noexcept {
  for (Disk& d : disks) {
    if (wrap.x && d.centre.x >= cell.xmax) {
      d.centre.x = cell.xmin;
    }
    if (wrap.y && d.centre.y >= cell.ymax) {
      d.centre.y = cell.ymin;
    }
  }
}

}  // namespace frontpack::detail
