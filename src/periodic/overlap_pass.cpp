// The periodic overlap pass. Why it is complete and exact:
//
// Exact. Every decision is compare_image_distance() (exact/periodic_predicates.hpp) on the
// disks' own doubles, an integer shift and the cell's bounds: the period enters as the exact
// difference xmax - xmin inside the predicate, never as its rounded double. The wrap counts that
// bring each centre into the cell are exact too (wrapped_side()): t = c - k L lies in [lo, hi)
// exactly.
//
// Complete. With exact wrapped centres t_i, t_j in the half-open cell, t_i - t_j lies in (-L, L)
// on each periodic axis, so the integer s minimising |t_i - t_j - s L| is -1, 0 or 1; on a
// rectangular lattice the nearest image is nearest on each axis separately, so if any image of j
// overlaps i, the image with s in {-1, 0, 1}^2 (s_y = 0 without y periodicity) does. Each pair is
// tested with those (at most 9) shifts, whatever the radii: a disk larger than the cell needs no
// more. A disk meets its own image iff it meets one of the shortest lattice vectors' images, (1, 0)
// or (0, 1): the pair (i, i). The search works on the rounded wrapped centres p, each within `tol`
// of t (tol bounds every rounding: of the period, of k L, of the subtraction), with boxes widened by
// tol; an overlapping pair's nearest-image separation is below r_i + r_j + tol <= 2 rmax + tol on
// each axis. The grid's cells are at least 2 rmax + 2 tol wide, so such a pair lies in the same or
// in neighbouring cells, cyclically on a periodic axis (the cell index of p is computed with an
// error far below tol); with fewer than 3 cells along an axis the neighbours coincide and are
// visited once. On a shear cell's walled axis a centre beyond a wall is clamped into the first or
// last row: clamping is monotone and never moves two rows apart, so neighbours stay neighbours.
//
// Linear time: cells hold O(1) disks for a packing (cell side about 2 rmax, or larger so that
// there are at most as many cells as disks); every disk visits at most 9 cells. (A few disks far
// larger than the rest make every cell large: the cost then grows with the disks per cell, as
// for any uniform grid.)
#include "periodic/overlap_pass.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>

#include "common/stop.hpp"
#include "exact/periodic_predicates.hpp"

namespace frontpack::detail {

namespace {

constexpr double kFarthest = 0x1p50;  // wrap counts beyond this are not searched

struct Placed {
  Point p;              // the wrapped centre, rounded
  double r = 0;         // radius
  std::int64_t kx = 0;  // p ~ centre - (kx Lx, ky Ly)
  std::int64_t ky = 0;
  std::size_t index = 0;  // in the input
};

// One axis of the search grid.
struct Axis {
  bool wraps = false;
  double lo = 0;      // the cell's bound (periodic) or the smallest wrapped centre (walls)
  double period = 0;  // rounded; only on a periodic axis
  double scale = 0;   // cells per unit length
  std::size_t n = 1;  // cells

  [[nodiscard]] std::size_t cell(double v) const noexcept {
    const double t = std::floor((v - lo) * scale);
    if (!(t > 0)) {
      return 0;
    }
    return t >= static_cast<double>(n - 1) ? n - 1 : static_cast<std::size_t>(t);
  }
  // The distinct cells next to c (c itself included), cyclically on a periodic axis.
  [[nodiscard]] std::size_t neighbours(std::size_t c, std::array<std::size_t, 3>& out) const noexcept {
    std::size_t count = 0;
    const auto add = [&](std::size_t v) {
      if (std::find(out.begin(), out.begin() + static_cast<std::ptrdiff_t>(count), v) ==
          out.begin() + static_cast<std::ptrdiff_t>(count)) {
        out[count++] = v;
      }
    };
    add(c);
    if (c > 0) {
      add(c - 1);
    } else if (wraps) {
      add(n - 1);
    }
    if (c + 1 < n) {
      add(c + 1);
    } else if (wraps) {
      add(0);
    }
    return count;
  }
};

bool takes_part(const Disk& d) {
  return std::isfinite(d.centre.x) && std::isfinite(d.centre.y) && std::isfinite(d.radius) && d.radius >= 0;
}

// The exact wrap count k with lo <= v - k (hi - lo) < hi, from a rounded first guess; false when
// v is more than kFarthest periods away.
bool wrap_count(double v, double lo, double hi, double period, std::int64_t& k) {
  const double q = std::floor((v - lo) / period);
  if (!(std::abs(q) <= kFarthest)) {
    return false;
  }
  k = static_cast<std::int64_t>(q);
  // The guess is off by at most one period (|q| <= 2^50: its rounding error is below 1/4); each
  // step moves towards the exact count, so the loop ends.
  for (int side = wrapped_side(v, k, lo, hi); side != 0; side = wrapped_side(v, k, lo, hi)) {
    k += side;
  }
  return true;
}

// cells = ceil-free count of cells of width >= h along `extent`, at least 1, at most 2^24.
std::size_t cells_along(double extent, double h) {
  const double g = std::floor(extent / h);
  if (!(g >= 1)) {
    return 1;
  }
  return g < 0x1p24 ? static_cast<std::size_t>(g) : std::size_t{1} << 24;
}

// The pass's state, shared by its steps: the cell, the wrapped disks sorted by grid cell, and the
// pairs found.
class OverlapPass {
 public:
  OverlapPass(const Domain& domain, std::span<const Disk> disks, const std::stop_token& stop)
      : disks_(disks),
        stop_(stop),
        cell_(domain.bbox()),  // a periodic domain's one polygon is its cell
        wraps_y_(domain.periodicity() == Periodicity::xy),
        lx_(cell_.xmax - cell_.xmin),
        ly_(cell_.ymax - cell_.ymin) {}

  void run(std::vector<std::pair<std::size_t, std::size_t>>& out, std::size_t& candidates) {
    out.clear();
    candidates = 0;
    std::vector<Placed> placed = wrap_disks();
    if (placed.empty()) {
      return;
    }
    make_grid(placed.size());
    sort_by_cell(std::move(placed));
    own_images(out, candidates);
    scan_cells(out, candidates);
    std::sort(out.begin(), out.end());
  }

 private:
  // Each disk that takes part, wrapped into the cell; sets rmax_ and tol_.
  std::vector<Placed> wrap_disks() {
    std::vector<Placed> placed;
    placed.reserve(disks_.size());
    double magnitude =
        std::max({std::abs(cell_.xmin), std::abs(cell_.xmax), std::abs(cell_.ymin), std::abs(cell_.ymax)});
    for (std::size_t i = 0; i < disks_.size(); ++i) {
      throw_if_stopped(stop_, i);
      const Disk& d = disks_[i];
      if (!takes_part(d)) {
        continue;
      }
      Placed w;
      w.r = d.radius;
      w.index = i;
      if (!wrap_count(d.centre.x, cell_.xmin, cell_.xmax, lx_, w.kx)) {
        continue;
      }
      if (wraps_y_ && !wrap_count(d.centre.y, cell_.ymin, cell_.ymax, ly_, w.ky)) {
        continue;
      }
      const double shift_x = static_cast<double>(w.kx) * lx_;
      const double shift_y = static_cast<double>(w.ky) * ly_;
      w.p = Point{std::clamp(d.centre.x - shift_x, cell_.xmin, cell_.xmax),
                  wraps_y_ ? std::clamp(d.centre.y - shift_y, cell_.ymin, cell_.ymax) : d.centre.y};
      magnitude =
          std::max({magnitude, std::abs(d.centre.x) + std::abs(shift_x), std::abs(d.centre.y) + std::abs(shift_y)});
      rmax_ = std::max(rmax_, d.radius);
      placed.push_back(w);
    }
    // Each rounding above (the period, k L, c - k L, r_i + r_j, the box test's own subtraction) is
    // at most 2^-53 of a magnitude below `magnitude + rmax`; a few of them add up far below 2^-46.
    tol_ = 0x1p-46 * (magnitude + rmax_);
    return placed;
  }

  // The grid: cells at least 2 rmax + 2 tol wide (a relative margin of 2^-20 covers the rounding
  // of the cell index), and no more cells than disks.
  void make_grid(std::size_t count) {
    ax_.wraps = true;
    ax_.lo = cell_.xmin;
    ax_.period = lx_;
    // y: the cell's rows; on a walled axis a centre beyond a wall falls in the first or last row
    // (clamping the row index is monotone and never pulls two rows apart, so neighbours stay
    // neighbours).
    ay_.wraps = wraps_y_;
    ay_.lo = cell_.ymin;
    ay_.period = ly_;
    const double sparse = std::sqrt(lx_ * ly_ / static_cast<double>(count));
    double h = (2 * rmax_ + 2 * tol_) * (1 + 0x1p-20);
    if (std::isfinite(sparse) && sparse > h) {
      h = sparse;
    }
    ax_.n = cells_along(lx_, h);
    ax_.scale = static_cast<double>(ax_.n) / lx_;
    ay_.n = cells_along(ly_, h);
    ay_.scale = static_cast<double>(ay_.n) / ly_;
  }

  // Counting sort by cell, stable: fills start_ and sorted_.
  void sort_by_cell(std::vector<Placed> placed) {
    const std::size_t cells = ax_.n * ay_.n;
    start_.assign(cells + 1, 0);
    std::vector<std::size_t> cell_of(placed.size());
    for (std::size_t a = 0; a < placed.size(); ++a) {
      cell_of[a] = ay_.cell(placed[a].p.y) * ax_.n + ax_.cell(placed[a].p.x);
      ++start_[cell_of[a] + 1];
    }
    for (std::size_t c = 0; c < cells; ++c) {
      start_[c + 1] += start_[c];
    }
    sorted_.resize(placed.size());
    std::vector<std::size_t> next(start_.begin(), start_.end() - 1);
    for (std::size_t a = 0; a < placed.size(); ++a) {
      sorted_[next[cell_of[a]]++] = placed[a];
    }
  }

  // A disk and its own image (1, 0) or, on a torus, (0, 1): the shortest lattice vectors.
  void own_images(std::vector<std::pair<std::size_t, std::size_t>>& out, std::size_t& candidates) const {
    for (const Placed& w : sorted_) {
      const Point c = disks_[w.index].centre;
      const bool near_x = 2 * w.r + tol_ >= lx_;
      const bool near_y = wraps_y_ && 2 * w.r + tol_ >= ly_;
      if (near_x || near_y) {
        ++candidates;
        if ((near_x && compare_image_distance(c, c, w.r, w.r, 1, 0, cell_) < 0) ||
            (near_y && compare_image_distance(c, c, w.r, w.r, 0, 1, cell_) < 0)) {
          out.emplace_back(w.index, w.index);
        }
      }
    }
  }

  // Every pair (a, b), a < b in sorted order, with b in a cell next to a's.
  void scan_cells(std::vector<std::pair<std::size_t, std::size_t>>& out, std::size_t& candidates) const {
    std::array<std::size_t, 3> nx{};
    std::array<std::size_t, 3> ny{};
    for (std::size_t cy = 0; cy < ay_.n; ++cy) {
      throw_if_stopped(stop_);
      const std::size_t count_y = ay_.neighbours(cy, ny);
      for (std::size_t cx = 0; cx < ax_.n; ++cx) {
        const std::size_t own = cy * ax_.n + cx;
        if (start_[own] == start_[own + 1]) {
          continue;
        }
        const std::size_t count_x = ax_.neighbours(cx, nx);
        for (std::size_t a = start_[own]; a < start_[own + 1]; ++a) {
          for (std::size_t u = 0; u < count_y; ++u) {
            for (std::size_t v = 0; v < count_x; ++v) {
              const std::size_t other = ny[u] * ax_.n + nx[v];
              for (std::size_t b = std::max(start_[other], a + 1); b < start_[other + 1]; ++b) {
                test_pair(sorted_[a], sorted_[b], out, candidates);
              }
            }
          }
        }
      }
    }
  }

  // The pair's images with shifts in {-1, 0, 1}^2 (s_y = 0 without y periodicity): counted when a
  // box met, kept when one overlaps exactly.
  void test_pair(const Placed& p, const Placed& q, std::vector<std::pair<std::size_t, std::size_t>>& out,
                 std::size_t& candidates) const {
    static constexpr std::array<std::int64_t, 3> kShifts = {-1, 0, 1};
    const std::size_t sy_count = wraps_y_ ? 3 : 1;
    const std::int64_t* sy_first = wraps_y_ ? kShifts.data() : kShifts.data() + 1;
    const double reach = p.r + q.r + tol_;
    bool met = false;
    bool overlap = false;
    for (std::size_t t = 0; t < sy_count && !overlap; ++t) {
      const std::int64_t sy = sy_first[t];
      if (!(std::abs(p.p.y - (q.p.y + static_cast<double>(sy) * ly_)) <= reach)) {
        continue;
      }
      for (const std::int64_t sx : kShifts) {
        if (!(std::abs(p.p.x - (q.p.x + static_cast<double>(sx) * lx_)) <= reach)) {
          continue;
        }
        met = true;
        if (compare_image_distance(disks_[p.index].centre, disks_[q.index].centre, p.r, q.r, sx + p.kx - q.kx,
                                   sy + p.ky - q.ky, cell_) < 0) {
          overlap = true;
          break;
        }
      }
    }
    if (met) {
      ++candidates;
    }
    if (overlap) {
      out.emplace_back(std::min(p.index, q.index), std::max(p.index, q.index));
    }
  }

  std::span<const Disk> disks_;
  const std::stop_token& stop_;
  Box cell_;
  bool wraps_y_ = false;
  double lx_ = 0;
  double ly_ = 0;
  double rmax_ = 0;
  double tol_ = 0;
  Axis ax_;
  Axis ay_;
  std::vector<std::size_t> start_;  // sorted_[start_[c], start_[c + 1]) lie in grid cell c
  std::vector<Placed> sorted_;
};

}  // namespace

void periodic_overlapping_pairs(const Domain& domain, std::span<const Disk> disks,
                                std::vector<std::pair<std::size_t, std::size_t>>& out, std::size_t& candidates,
                                const std::stop_token& stop) {
  OverlapPass(domain, disks, stop).run(out, candidates);
}

double periodic_overlap_depth(const Domain& domain, const Disk& a, const Disk& b, bool same) {
  const Box cell = domain.bbox();
  const double lx = cell.xmax - cell.xmin;
  const double ly = cell.ymax - cell.ymin;
  const bool wraps_y = domain.periodicity() == Periodicity::xy;
  double dx = a.centre.x - b.centre.x;
  double dy = a.centre.y - b.centre.y;
  dx -= lx * std::round(dx / lx);
  if (wraps_y) {
    dy -= ly * std::round(dy / ly);
  }
  double distance = std::hypot(dx, dy);
  if (same) {
    distance = wraps_y ? std::min(lx, ly) : lx;
  }
  return a.radius + b.radius - distance;
}

}  // namespace frontpack::detail
