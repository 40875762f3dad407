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
  double step = std::sqrt(area / static_cast<double>(samples));
  if (!(step > 0)) {
    step = std::sqrt(area) / std::sqrt(static_cast<double>(samples));  // area / samples underflowed
  }
  // ceil(width / step), at least 1 (and at most kMaxAxisCells).
  const std::size_t nx = axis_cells(std::ceil(b.width() / step) - 1, kMaxAxisCells);
  const std::size_t ny = axis_cells(std::ceil(b.height() / step) - 1, kMaxAxisCells);
  const double sx = b.width() / static_cast<double>(nx);
  const double sy = b.height() / static_cast<double>(ny);
  // The disks by the row where the sweep takes them up: the first row j whose top y1(j) is at or
  // above the disk's bottom (the last row for a disk above the box). A counting sort, linear in
  // the disks: the quotient gives the row up to rounding, the comparisons with y1 settle it.
  const auto row_top = [&b, sy](std::size_t j) { return b.ymin + static_cast<double>(j) * sy + sy; };
  std::vector<std::uint32_t> row_of(disks.size());
  std::vector<std::size_t> row_start(ny + 1, 0);
  for (std::size_t k = 0; k < disks.size(); ++k) {
    const double bottom = disks[k].centre.y - disks[k].radius;
    const double q = std::floor((bottom - b.ymin) / sy);
    std::size_t j = q > 0 ? static_cast<std::size_t>(std::min(q, static_cast<double>(ny - 1))) : 0;
    while (j > 0 && bottom <= row_top(j - 1)) {
      --j;
    }
    while (j + 1 < ny && bottom > row_top(j)) {
      ++j;
    }
    row_of[k] = static_cast<std::uint32_t>(j);
    ++row_start[j + 1];
  }
  for (std::size_t j = 0; j < ny; ++j) {
    row_start[j + 1] += row_start[j];
  }
  std::vector<std::uint32_t> order(disks.size());
  {
    std::vector<std::size_t> fill(row_start.begin(), row_start.end() - 1);
    for (std::size_t k = 0; k < disks.size(); ++k) {
      order[fill[row_of[k]]++] = static_cast<std::uint32_t>(k);
    }
  }
  // Copies of the disks meeting the row: each disk is read from `disks` once, as it is taken up
  // (the disks of a row in index order), and the rows it spans read the compact copies (reading
  // them through indices missed the cache at nearly every disk: 40% of the sweep's time).
  std::vector<Disk> active;
  std::size_t next = 0;
  std::vector<Point> points(nx);
  std::vector<std::uint8_t> covered(nx);
  std::size_t n_int = 0;
  std::size_t c_int = 0;
  std::size_t n_band = 0;
  std::size_t c_band = 0;
  constexpr std::size_t kBins = 7;
  const bool profile = bin_unit > 0 && std::isfinite(6 * bin_unit);
  const double cap = profile ? std::max(w, 6 * bin_unit) : w;
  std::array<std::size_t, kBins> n_bin{};
  std::array<std::size_t, kBins> c_bin{};
  for (std::size_t j = 0; j < ny; ++j) {
    detail::throw_if_stopped(stop);
    const double y0 = b.ymin + static_cast<double>(j) * sy;
    for (std::size_t i = 0; i < nx; ++i) {
      const std::uint64_t key = splitmix64(splitmix64(0x5eed0000ULL + j) ^ i);
      points[i] = Point{b.xmin + (static_cast<double>(i) + unit(key)) * sx, y0 + unit(splitmix64(key)) * sy};
    }
    for (; next < row_start[j + 1]; ++next) {
      active.push_back(disks[order[next]]);
    }
    std::fill(covered.begin(), covered.end(), std::uint8_t{0});
    std::size_t keep = 0;
    for (const Disk& d : active) {
      if (d.centre.y + d.radius < y0) {
        continue;  // below this row, hence below every later one
      }
      active[keep++] = d;
      const double first = std::floor((d.centre.x - d.radius - b.xmin) / sx);
      const double last = std::floor((d.centre.x + d.radius - b.xmin) / sx);
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
    for (std::size_t i = 0; i < nx; ++i) {
      const Point p = points[i];
      if (locate_wrapped(domain, periods, p) == Location::outside) {
        continue;
      }
      const double d = edges.distance(p, cap);
      if (profile) {
        const double k = std::floor(d / bin_unit);
        const std::size_t bin = k < static_cast<double>(kBins - 1) ? static_cast<std::size_t>(k) : kBins - 1;
        ++n_bin[bin];
        c_bin[bin] += covered[i];
      }
      if (d < w) {
        ++n_band;
        c_band += covered[i];
      } else {
        ++n_int;
        c_int += covered[i];
      }
    }
  }
  const double cell = sx * sy;
  const auto fraction = [](std::size_t c, std::size_t n) {
    return n == 0 ? 0.0 : static_cast<double>(c) / static_cast<double>(n);
  };
  const auto error = [](double f, std::size_t n) {
    return n == 0 ? 0.0 : std::sqrt(std::max(f * (1 - f), 1.0 / static_cast<double>(n)) / static_cast<double>(n));
  };
  s.interior_samples = n_int;
  s.band_samples = n_band;
  s.interior_fraction = fraction(c_int, n_int);
  s.band_fraction = fraction(c_band, n_band);
  s.interior_error = error(s.interior_fraction, n_int);
  s.band_error = error(s.band_fraction, n_band);
  s.interior_area = static_cast<double>(n_int) * cell;
  s.band_area = static_cast<double>(n_band) * cell;
  if (profile) {
    s.coverage_unit = bin_unit;
    for (std::size_t k = 0; k < kBins; ++k) {
      CoverageBin bin;
      bin.from = static_cast<double>(k) * bin_unit;
      bin.to = k + 1 < kBins ? static_cast<double>(k + 1) * bin_unit : std::numeric_limits<double>::infinity();
      bin.samples = n_bin[k];
      bin.fraction = fraction(c_bin[k], n_bin[k]);
      bin.error = error(bin.fraction, n_bin[k]);
      s.coverage_profile.push_back(bin);
    }
  }
}

}  // namespace frontpack::detail
