// What the two generators (generate/paper_front.cpp, generate/boundary/boundary_front.cpp) share: the uniform grid their neighbour
// searches run on, the candidate disk their overlap tests take, the position of a disk touching
// two others, the radius classes of their void buckets, and freeing their arrays. Header-only and
// CGAL-free: both are hot loops.
#pragma once

#include <algorithm>
#include <array>
#include <bit>
#include <cassert>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

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

/// A candidate disk with the limits of the overlap test's band precomputed: the test runs tens of
/// times per disk. Another disk o is clear beyond r_hi + o.r and overlapping within r_lo + o.r;
/// in between the exact predicate decides (margin = clearance / 2, band = clearance / 4).
struct Probe {
  double x, y, r;
  double r_hi;  // r + margin + band
  double r_lo;  // r + margin - band

  static Probe at(double x, double y, double r, double margin, double band) noexcept {
    return {x, y, r, r + margin + band, r + margin - band};
  }
};

/// A power of two that brings lengths of the order of `length` (a run's largest radius) to about 1.
/// Multiplying by it rounds nothing, so a computation done at that scale and scaled back gives the
/// same bits, but its squares and fourth powers neither overflow nor underflow at any scale the
/// library accepts (lengths of 1e80 or 1e-80).
struct LengthScale {
  double k = 1;      // lengths are multiplied by this
  double inv_k = 1;  // and the results by this
  LengthScale() = default;
  explicit LengthScale(double length) {
    if (std::isfinite(length) && length > 0) {
      const int e = std::clamp(std::ilogb(length), -1000, 1000);
      k = std::ldexp(1.0, -e);
      inv_k = std::ldexp(1.0, e);
    }
  }
};

/// The generators' unit of length. A run multiplies every length it is given (coordinates relative
/// to its box's corner, radii, the clearance) by k, a power of two (exact), and its disks by inv_k
/// on the way out. k is 1 for rmax in [2^-300, 2^300] (about 5e-91 to 2e90), which covers every
/// domain of ordinary size: their packings are the ones computed without it, bit for bit. Outside,
/// k = 2^-ilogb(rmax) brings rmax to [1, 2) (k at most 2^1000: a subnormal rmax stays below that),
/// so that the squares in the overlap tests and the clearance's band around them stay normal
/// numbers and finite: at 1e-200 they underflowed to 0, and with radii of 1e200 to 1e300 every
/// pair of disks, their squared distances infinite, tested clear; either way the floating-point
/// filter decided nothing and a run did not end. A domain that small packs as it does at 1.
struct WorkScale {
  double k = 1;
  double inv_k = 1;
  WorkScale() = default;
  explicit WorkScale(double rmax) {
    if ((rmax > 0 && rmax < 0x1p-300) || (rmax > 0x1p300 && std::isfinite(rmax))) {
      const LengthScale s(rmax);
      k = s.k;
      inv_k = s.inv_k;
    }
  }
};

/// The centre (px, py) of a disk touching two disks from outside: at distance ra from (ax, ay) and
/// rb from (bx, by) (their radii plus the new one's, and the clearance), on the left of a -> b if
/// `left`, else on the right. False if there is none (the disks are too far apart or one holds
/// the other), or if the centres coincide. The lengths are taken at `scale` (see LengthScale).
inline bool tangent_to_two(double ax, double ay, double ra, double bx, double by, double rb, bool left,
                           const LengthScale& scale, double& px, double& py) noexcept {
  const double dx = (bx - ax) * scale.k;
  const double dy = (by - ay) * scale.k;
  ra *= scale.k;
  rb *= scale.k;
  const double d2 = dx * dx + dy * dy;
  if (!(d2 > 0)) {
    return false;
  }
  // With q = ra^2 - rb^2 + d2 (2 d times the distance from a to the chord) and
  // H = 4 ra^2 d2 - q^2 (2 d times the half-chord, squared), the centre is
  // a + (q (dx, dy) +- sqrt(H) (-dy, dx)) / (2 d2): one square root and one division, independent
  // of each other, where normalising first takes two square roots in a row.
  const double q = ra * ra - rb * rb + d2;
  const double big_h = 4 * ra * ra * d2 - q * q;
  if (!(big_h >= 0 && big_h <= std::numeric_limits<double>::max())) {
    return false;
  }
  const double s = left ? std::sqrt(big_h) : -std::sqrt(big_h);
  const double f = 0.5 / d2 * scale.inv_k;
  px = ax + (q * dx - s * dy) * f;
  py = ay + (q * dy + s * dx) * f;
  return true;
}

/// Radius classes for the void buckets: N classes log-spaced between rmin and rmax; class k >= 1
/// holds the radii from floor_[k] up, class 0 the rest (below floor_[1], and NaN); with
/// rmin = rmax everything is class 0. The generators ask for the class of every radius drawn and
/// every void kept, so of() takes no logarithm and no search: the bits of a positive double, as
/// an integer, grow with it, and their top bits (the exponent and the first mantissa bits) index
/// a table of the class at the bottom of each such bucket of radii; the buckets are made narrower
/// than a class where the table's kTable entries allow it, so one comparison finishes the lookup
/// (a loop climbs further where they do not). A binary search with log2(N) dependent steps took
/// about 40 cycles.
template <int N>
class RadiusClasses {
  static_assert(N >= 2 && N <= 256);  // classes fit the table's bytes
  static constexpr std::size_t kTable = 1024;

 public:
  RadiusClasses() {
    floor_.fill(std::numeric_limits<double>::infinity());
    floor_[N] = std::numeric_limits<double>::quiet_NaN();  // never reached: r >= NaN is false
  }
  RadiusClasses(double rmin, double rmax) : RadiusClasses() {
    const double log_rmin = std::log(rmin);
    const double span = std::log(rmax) - log_rmin;
    floor_[0] = -std::numeric_limits<double>::infinity();
    if (!(span > 0)) {
      return;
    }
    // Above rmin (a range a few ulps wide rounds the low floors down to it) and increasing.
    const double above_rmin = std::nextafter(rmin, std::numeric_limits<double>::infinity());
    for (std::size_t k = 1; k < N; ++k) {
      floor_[k] = std::max({std::exp(log_rmin + span * static_cast<double>(k) / N), above_rmin, floor_[k - 1]});
    }
    // The finest buckets whose keys from rmin to rmax fit the table (rmin > 0 and finite here).
    const auto bits_min = std::bit_cast<std::uint64_t>(rmin);
    const auto bits_max = std::bit_cast<std::uint64_t>(rmax);
    shift_ = 0;
    while (shift_ < 63 && (bits_max >> shift_) - (bits_min >> shift_) >= kTable) {
      ++shift_;
    }
    key0_ = bits_min >> shift_;
    rmin_ = rmin;
    for (std::size_t i = 0; i < kTable; ++i) {
      const std::uint64_t bottom = (key0_ + i) << shift_;
      // Keys past rmax's get its class's table entry (of() clamps to the last one it needs).
      table_[i] = static_cast<std::uint8_t>(bottom <= bits_max ? search(std::max(rmin, std::bit_cast<double>(bottom)))
                                                               : table_[i - 1]);
    }
  }

  [[nodiscard]] int of(double r) const noexcept {
    if (!(r > rmin_)) {
      return 0;  // also NaN and, with rmin = rmax (rmin_ infinite), everything
    }
    const std::uint64_t i = (std::bit_cast<std::uint64_t>(r) >> shift_) - key0_;
    int k = table_[std::min<std::uint64_t>(i, kTable - 1)];
    k += r >= floor_[static_cast<std::size_t>(k) + 1] ? 1 : 0;
    while (r >= floor_[static_cast<std::size_t>(k) + 1]) {  // buckets wider than a class
      ++k;
    }
    return k;
  }

 private:
  // The class by bisection over the floors, for the table.
  [[nodiscard]] int search(double r) const noexcept {
    std::size_t k = 0;
    for (std::size_t step = std::bit_ceil(static_cast<std::size_t>(N)) / 2; step > 0; step /= 2) {
      k += k + step < N && r >= floor_[k + step] ? step : 0;
    }
    return static_cast<int>(k);
  }

  std::array<double, static_cast<std::size_t>(N) + 1> floor_;  // floor_[N]: NaN, a sentinel
  std::array<std::uint8_t, kTable> table_{};
  double rmin_ = std::numeric_limits<double>::infinity();
  std::uint64_t key0_ = 0;
  unsigned shift_ = 0;
};

/// Frees a vector's memory (clear() keeps it): the generators free their working arrays before
/// copying the disks out, so that the peak holds the disks and the output only.
template <class T, class A>
void release(std::vector<T, A>& v) {
  std::vector<T, A>().swap(v);
}

}  // namespace frontpack::detail
