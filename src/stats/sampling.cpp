// The interior and band fractions by stratified sampling (floating point: measurements; point
// location in the domain is exact, via Domain).
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>

#include "common/grid_cells.hpp"
#include "common/rng.hpp"
#include "common/stop.hpp"
#include "stats/parts.hpp"

namespace frontpack::detail {

namespace {

double unit(std::uint64_t h) noexcept {
  return static_cast<double>(h >> 11) * 0x1p-53;
}

// The lattice of sample cells over the bounding box: nx x ny cells of sx x sy.
struct Lattice {
  Box b;
  std::size_t nx = 1;
  std::size_t ny = 1;
  double sx = 0;
  double sy = 0;

  [[nodiscard]] double row_top(std::size_t j) const { return b.ymin + static_cast<double>(j) * sy + sy; }
};

// About `samples` cells (area > 0, samples > 0), at least one along each axis.
Lattice make_lattice(const Box& b, double area, std::size_t samples) {
  double step = std::sqrt(area / static_cast<double>(samples));
  if (!(step > 0)) {
    step = std::sqrt(area) / std::sqrt(static_cast<double>(samples));  // area / samples underflowed
  }
  Lattice lat;
  lat.b = b;
  // ceil(width / step), at least 1 (and at most kMaxAxisCells).
  lat.nx = axis_cells(std::ceil(b.width() / step) - 1, kMaxAxisCells);
  lat.ny = axis_cells(std::ceil(b.height() / step) - 1, kMaxAxisCells);
  lat.sx = b.width() / static_cast<double>(lat.nx);
  lat.sy = b.height() / static_cast<double>(lat.ny);
  return lat;
}

// The disks by the row where the sweep takes them up: order[row_start[j], row_start[j + 1]) in
// index order.
struct RowOrder {
  std::vector<std::size_t> row_start;
  std::vector<std::uint32_t> order;
};

// A disk's row is the first row j whose top y1(j) is at or above the disk's bottom (the last row
// for a disk above the box). A counting sort, linear in the disks: the quotient gives the row up
// to rounding, the comparisons with y1 settle it.
RowOrder sort_by_row(std::span<const Disk> disks, const Lattice& lat) {
  const std::size_t ny = lat.ny;
  RowOrder rows;
  std::vector<std::uint32_t> row_of(disks.size());
  rows.row_start.assign(ny + 1, 0);
  for (std::size_t k = 0; k < disks.size(); ++k) {
    const double bottom = disks[k].centre.y - disks[k].radius;
    const double q = std::floor((bottom - lat.b.ymin) / lat.sy);
    std::size_t j = q > 0 ? static_cast<std::size_t>(std::min(q, static_cast<double>(ny - 1))) : 0;
    while (j > 0 && bottom <= lat.row_top(j - 1)) {
      --j;
    }
    while (j + 1 < ny && bottom > lat.row_top(j)) {
      ++j;
    }
    row_of[k] = static_cast<std::uint32_t>(j);
    ++rows.row_start[j + 1];
  }
  for (std::size_t j = 0; j < ny; ++j) {
    rows.row_start[j + 1] += rows.row_start[j];
  }
  rows.order.resize(disks.size());
  std::vector<std::size_t> fill(rows.row_start.begin(), rows.row_start.end() - 1);
  for (std::size_t k = 0; k < disks.size(); ++k) {
    rows.order[fill[row_of[k]]++] = static_cast<std::uint32_t>(k);
  }
  return rows;
}

// Row j's sample points, one at a hashed position in each of its cells.
void place_points(const Lattice& lat, std::size_t j, std::vector<Point>& points) {
  const double y0 = lat.b.ymin + static_cast<double>(j) * lat.sy;
  for (std::size_t i = 0; i < lat.nx; ++i) {
    const std::uint64_t key = splitmix64(splitmix64(0x5eed0000ULL + j) ^ i);
    points[i] = Point{lat.b.xmin + (static_cast<double>(i) + unit(key)) * lat.sx, y0 + unit(splitmix64(key)) * lat.sy};
  }
}

// Marks the points of row j covered by an active disk, and drops from `active` the disks below
// the row (hence below every later one).
void cover_row(const Lattice& lat, std::size_t j, std::span<const Point> points, std::vector<Disk>& active,
               std::span<std::uint8_t> covered) {
  const double y0 = lat.b.ymin + static_cast<double>(j) * lat.sy;
  const std::size_t nx = lat.nx;
  std::fill(covered.begin(), covered.end(), std::uint8_t{0});
  std::size_t keep = 0;
  for (const Disk& d : active) {
    if (d.centre.y + d.radius < y0) {
      continue;  // below this row, hence below every later one
    }
    active[keep++] = d;
    const double first = std::floor((d.centre.x - d.radius - lat.b.xmin) / lat.sx);
    const double last = std::floor((d.centre.x + d.radius - lat.b.xmin) / lat.sx);
    if (last < 0 || first > static_cast<double>(nx - 1)) {
      continue;
    }
    const auto i0 = static_cast<std::size_t>(std::max(first, 0.0));
    const auto i1 = static_cast<std::size_t>(std::min(last, static_cast<double>(nx - 1)));
    const double r2 = d.radius * d.radius;
    for (std::size_t i = i0; i <= i1; ++i) {
      const double dx = points[i].x - d.centre.x;
      const double dy = points[i].y - d.centre.y;
      covered[i] = static_cast<std::uint8_t>(covered[i] | (dx * dx + dy * dy <= r2 ? 1 : 0));
    }
  }
  active.resize(keep);
}

constexpr std::size_t kBins = 7;

// The counts of sample points inside the domain and of those covered: in the band (distance to
// the boundary below w) and in the interior, and per bin of the coverage profile.
struct Tally {
  std::size_t n_int = 0;
  std::size_t c_int = 0;
  std::size_t n_band = 0;
  std::size_t c_band = 0;
  std::array<std::size_t, kBins> n_bin{};
  std::array<std::size_t, kBins> c_bin{};
};

// What the sweep reads besides the disks: the domain and its periods, the distance to the walls
// up to `cap`, the band's width and the profile's unit (profile: whether one is asked).
struct Tallying {
  const Domain& domain;
  const Periods& periods;
  const EdgeDistanceIndex& edges;
  double w;
  double cap;
  bool profile;
  double bin_unit;

  void count_row(std::span<const Point> points, std::span<const std::uint8_t> covered, Tally& t) const {
    for (std::size_t i = 0; i < points.size(); ++i) {
      const Point p = points[i];
      if (locate_wrapped(domain, periods, p) == Location::outside) {
        continue;
      }
      const double d = edges.distance(p, cap);
      if (profile) {
        const double k = std::floor(d / bin_unit);
        const std::size_t bin = k < static_cast<double>(kBins - 1) ? static_cast<std::size_t>(k) : kBins - 1;
        ++t.n_bin[bin];
        t.c_bin[bin] += covered[i];
      }
      if (d < w) {
        ++t.n_band;
        t.c_band += covered[i];
      } else {
        ++t.n_int;
        t.c_int += covered[i];
      }
    }
  }
};

double fraction(std::size_t c, std::size_t n) {
  return n == 0 ? 0.0 : static_cast<double>(c) / static_cast<double>(n);
}

double standard_error(double f, std::size_t n) {
  return n == 0 ? 0.0 : std::sqrt(std::max(f * (1 - f), 1.0 / static_cast<double>(n)) / static_cast<double>(n));
}

// The fractions, their errors and the areas sampled (each point stands for a cell of area
// `cell`), and the coverage profile when one was asked.
void write_tally(const Tally& t, double cell, bool profile, double bin_unit, PackingStats& s) {
  s.interior_samples = t.n_int;
  s.band_samples = t.n_band;
  s.interior_fraction = fraction(t.c_int, t.n_int);
  s.band_fraction = fraction(t.c_band, t.n_band);
  s.interior_error = standard_error(s.interior_fraction, t.n_int);
  s.band_error = standard_error(s.band_fraction, t.n_band);
  s.interior_area = static_cast<double>(t.n_int) * cell;
  s.band_area = static_cast<double>(t.n_band) * cell;
  if (!profile) {
    return;
  }
  s.coverage_unit = bin_unit;
  for (std::size_t k = 0; k < kBins; ++k) {
    CoverageBin bin;
    bin.from = static_cast<double>(k) * bin_unit;
    bin.to = k + 1 < kBins ? static_cast<double>(k + 1) * bin_unit : std::numeric_limits<double>::infinity();
    bin.samples = t.n_bin[k];
    bin.fraction = fraction(t.c_bin[k], t.n_bin[k]);
    bin.error = standard_error(bin.fraction, t.n_bin[k]);
    s.coverage_profile.push_back(bin);
  }
}

}  // namespace

// Fractions by stratified sampling: one point per cell of an nx x ny lattice over the bounding
// box, at a hashed position in its cell (independently in x and y, so that the estimate is a
// stratified one, never worse than independent points). Rows of cells are swept upwards; the
// disks meeting the row are kept in an active list (disks sorted by their lowest y).
//
// The same points give the coverage profile: each point's distance to the boundary, as far as
// 6 units, puts it in the bin [k, k + 1) units (k = 0..5) or in the last bin. In a periodic cell
// the distance is to the walls alone (domain/edge_distance.hpp): without walls every point is
// interior and falls in the last bin; a point is covered by a disk or by an image of one.
void sample_fractions(const Domain& domain, std::span<const Disk> disks, const EdgeDistanceIndex& edges, double w,
                      std::size_t samples, double bin_unit, PackingStats& s, const std::stop_token& stop) {
  const Box b = domain.bbox();
  const Periods periods(domain);
  const double area = b.width() * b.height();
  if (samples == 0 || !(area > 0)) {
    return;
  }
  const Lattice lat = make_lattice(b, area, samples);
  const RowOrder rows = sort_by_row(disks, lat);
  const bool profile = bin_unit > 0 && std::isfinite(6 * bin_unit);
  const Tallying tallying{domain, periods, edges, w, profile ? std::max(w, 6 * bin_unit) : w, profile, bin_unit};
  // Copies of the disks meeting the row: each disk is read from `disks` once, as it is taken up
  // (the disks of a row in index order), and the rows it spans read the compact copies (reading
  // them through indices missed the cache at nearly every disk: 40% of the sweep's time).
  std::vector<Disk> active;
  std::size_t next = 0;
  std::vector<Point> points(lat.nx);
  std::vector<std::uint8_t> covered(lat.nx);
  Tally tally;
  for (std::size_t j = 0; j < lat.ny; ++j) {
    detail::throw_if_stopped(stop);
    place_points(lat, j, points);
    for (; next < rows.row_start[j + 1]; ++next) {
      active.push_back(disks[rows.order[next]]);
    }
    cover_row(lat, j, points, active, covered);
    tallying.count_row(points, covered, tally);
  }
  write_tally(tally, lat.sx * lat.sy, profile, bin_unit, s);
}

}  // namespace frontpack::detail
