// Packing statistics (include/frontpack/stats.hpp): fractions by stratified sampling, contacts
// by a uniform grid, sizes against the requested distribution. Floating point throughout: these
// are measurements, not certificates (point location in the domain is exact, via Domain).
#include "frontpack/stats.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "common/format.hpp"
#include "common/stop.hpp"

namespace frontpack {

namespace {

std::uint64_t mix(std::uint64_t z) noexcept {  // splitmix64's finaliser
  z += 0x9e3779b97f4a7c15ULL;
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

double unit(std::uint64_t h) noexcept {
  return static_cast<double>(h >> 11) * 0x1p-53;
}

// The cells of a grid along an axis `g` cells long (a length over a cell size, maybe a fraction
// of a cell more): floor(g) + 1, at least 1 and at most `cap`. A NaN (lengths that overflowed, or a
// cell size that underflowed) gives 1: a coarser grid finds the same neighbours, more slowly.
std::size_t axis_cells(double g, std::size_t cap) noexcept {
  if (!(g >= 0)) {
    return 1;
  }
  return g < static_cast<double>(cap - 1) ? static_cast<std::size_t>(g) + 1 : cap;
}
constexpr std::size_t kMaxAxisCells = std::size_t{1} << 24;

// A length scale (a power of two) that brings lengths of the order of `length` to about 1 when
// they are so small or so large that their squares leave the range of doubles; 1 otherwise (so
// that ordinary figures are the ones computed without it, bit for bit).
double square_safe_scale(double length) noexcept {
  if (!(length > 0) || !std::isfinite(length) || (length >= 0x1p-400 && length <= 0x1p400)) {
    return 1;
  }
  return std::ldexp(1.0, -std::clamp(std::ilogb(length), -1000, 1000));
}

// Index of the cell of coordinate x in a grid from `origin` with cell size h, clamped to [0, n).
std::size_t cell_index(double x, double origin, double inv_h, std::size_t n) noexcept {
  const double t = std::floor((x - origin) * inv_h);
  if (!(t > 0)) {
    return 0;
  }
  return t >= static_cast<double>(n - 1) ? n - 1 : static_cast<std::size_t>(t);
}

// The domain's edges in a uniform grid, for distance-to-boundary queries (floating point).
class EdgeIndex {
 public:
  EdgeIndex(const Domain& domain, double h) {
    for (const Polygon& p : domain.polygons()) {
      add_ring(p.outer);
      for (const Ring& hole : p.holes) {
        add_ring(hole);
      }
    }
    const Box b = domain.bbox();
    // At most about 4 million cells (and at least one).
    const double area = std::max(b.width() * b.height(), 0.0);
    h = std::max(h, std::sqrt(area / 4e6));
    h_ = h > 0 ? h : 1;
    inv_h_ = 1 / h_;
    x0_ = b.xmin;
    y0_ = b.ymin;
    nx_ = axis_cells(b.width() * inv_h_, kMaxAxisCells);
    ny_ = axis_cells(b.height() * inv_h_, kMaxAxisCells);
    std::vector<std::pair<std::size_t, std::uint32_t>> entries;  // (cell, edge)
    for (std::size_t e = 0; e < a_.size(); ++e) {
      const Point a = a_[e];
      const Point c = b_[e];
      const double xlo = std::min(a.x, c.x);
      const double xhi = std::max(a.x, c.x);
      const std::size_t i0 = column(xlo);
      const std::size_t i1 = column(xhi);
      for (std::size_t i = i0; i <= i1; ++i) {
        // The edge's y range over this column's x range (conservative by a relative 1e-9).
        const double cx0 = std::max(xlo, x0_ + static_cast<double>(i) * h_);
        const double cx1 = std::min(xhi, x0_ + static_cast<double>(i + 1) * h_);
        double ylo = std::min(a.y, c.y);
        double yhi = std::max(a.y, c.y);
        if (c.x != a.x) {
          const double ya = a.y + (c.y - a.y) * ((cx0 - a.x) / (c.x - a.x));
          const double yb = a.y + (c.y - a.y) * ((cx1 - a.x) / (c.x - a.x));
          ylo = std::max(ylo, std::min(ya, yb) - 1e-9 * h_);
          yhi = std::min(yhi, std::max(ya, yb) + 1e-9 * h_);
        }
        for (std::size_t j = row(ylo); j <= row(yhi); ++j) {
          entries.emplace_back(j * nx_ + i, static_cast<std::uint32_t>(e));
        }
      }
    }
    std::sort(entries.begin(), entries.end());
    start_.assign(nx_ * ny_ + 1, 0);
    for (const auto& [cell, e] : entries) {
      ++start_[cell + 1];
      edges_.push_back(e);
    }
    for (std::size_t c = 0; c < nx_ * ny_; ++c) {
      start_[c + 1] += start_[c];
    }
  }

  /// Calls f(closest point, distance) for each edge (possibly repeated) listed in the cells
  /// within d of p; every edge at distance <= d from p is among them.
  template <class F>
  void near(Point p, double d, F&& f) const {
    const std::size_t i0 = column(p.x - d);
    const std::size_t i1 = column(p.x + d);
    const std::size_t j0 = row(p.y - d);
    const std::size_t j1 = row(p.y + d);
    for (std::size_t j = j0; j <= j1; ++j) {
      for (std::size_t i = i0; i <= i1; ++i) {
        const std::size_t c = j * nx_ + i;
        for (std::size_t k = start_[c]; k < start_[c + 1]; ++k) {
          const Point q = closest(edges_[k], p);
          f(q, std::hypot(q.x - p.x, q.y - p.y));
        }
      }
    }
  }

  /// Whether the boundary comes closer than d to p.
  [[nodiscard]] bool closer_than(Point p, double d) const {
    bool found = false;
    near(p, d, [&found, d](Point, double dist) { found = found || dist < d; });
    return found;
  }

 private:
  void add_ring(const Ring& ring) {
    for (std::size_t k = 0; k < ring.size(); ++k) {
      a_.push_back(ring[k]);
      b_.push_back(ring[(k + 1) % ring.size()]);
    }
  }
  [[nodiscard]] std::size_t column(double x) const { return cell_index(x, x0_, inv_h_, nx_); }
  [[nodiscard]] std::size_t row(double y) const { return cell_index(y, y0_, inv_h_, ny_); }
  [[nodiscard]] Point closest(std::uint32_t e, Point p) const {
    const Point a = a_[e];
    const Point b = b_[e];
    const double dx = b.x - a.x;
    const double dy = b.y - a.y;
    const double len2 = dx * dx + dy * dy;
    double t = len2 > 0 ? ((p.x - a.x) * dx + (p.y - a.y) * dy) / len2 : 0;
    t = std::clamp(t, 0.0, 1.0);
    return Point{a.x + t * dx, a.y + t * dy};
  }

  std::vector<Point> a_;
  std::vector<Point> b_;
  double h_ = 1;
  double inv_h_ = 1;
  double x0_ = 0;
  double y0_ = 0;
  std::size_t nx_ = 1;
  std::size_t ny_ = 1;
  std::vector<std::size_t> start_;
  std::vector<std::uint32_t> edges_;
};

// Disk-disk contacts. Each disk is listed in every cell its box, grown by half the tolerance,
// meets; a pair is examined only in the cell that holds the lower-left corner of the
// intersection of the two boxes, so once. Linear for any ratio of radii.
void count_contacts(std::span<const Disk> disks, double tol, PackingStats& s, std::vector<std::size_t>& degree,
                    const std::stop_token& stop) {
  const std::size_t n = disks.size();
  Box b;
  double sum_r = 0;
  for (const Disk& d : disks) {
    b.extend(d.centre);
    sum_r += d.radius;
  }
  const double h0 = 4 * sum_r / static_cast<double>(n) + tol;
  const double w = b.width() + 2 * (s.sizes.rmax + tol);
  const double ht = b.height() + 2 * (s.sizes.rmax + tol);
  const double h = std::max(h0, std::sqrt(w * ht / (4.0 * static_cast<double>(n) + 16)));
  const double inv_h = 1 / h;
  const double x0 = b.xmin - s.sizes.rmax - tol;
  const double y0 = b.ymin - s.sizes.rmax - tol;
  const std::size_t nx = axis_cells(w * inv_h, kMaxAxisCells);
  const std::size_t ny = axis_cells(ht * inv_h, kMaxAxisCells);
  const auto box_of = [tol](const Disk& d) {
    const double e = d.radius + tol / 2;
    return Box{d.centre.x - e, d.centre.y - e, d.centre.x + e, d.centre.y + e};
  };
  std::vector<std::size_t> start(nx * ny + 1, 0);
  const auto cells = [&](const Box& bx, auto&& f) {
    const std::size_t i0 = cell_index(bx.xmin, x0, inv_h, nx);
    const std::size_t i1 = cell_index(bx.xmax, x0, inv_h, nx);
    const std::size_t j0 = cell_index(bx.ymin, y0, inv_h, ny);
    const std::size_t j1 = cell_index(bx.ymax, y0, inv_h, ny);
    for (std::size_t j = j0; j <= j1; ++j) {
      for (std::size_t i = i0; i <= i1; ++i) {
        f(j * nx + i);
      }
    }
  };
  for (const Disk& d : disks) {
    cells(box_of(d), [&start](std::size_t c) { ++start[c + 1]; });
  }
  for (std::size_t c = 0; c < nx * ny; ++c) {
    start[c + 1] += start[c];
  }
  std::vector<std::uint32_t> members(start.back());
  {
    std::vector<std::size_t> fill(start.begin(), start.end() - 1);
    for (std::size_t k = 0; k < n; ++k) {
      cells(box_of(disks[k]), [&](std::size_t c) { members[fill[c]++] = static_cast<std::uint32_t>(k); });
    }
  }
  for (std::size_t c = 0; c < nx * ny; ++c) {
    detail::throw_if_stopped(stop, c);
    for (std::size_t p = start[c]; p < start[c + 1]; ++p) {
      const Disk& a = disks[members[p]];
      const Box ba = box_of(a);
      for (std::size_t q = p + 1; q < start[c + 1]; ++q) {
        const Disk& d = disks[members[q]];
        const Box bd = box_of(d);
        if (ba.xmax < bd.xmin || bd.xmax < ba.xmin || ba.ymax < bd.ymin || bd.ymax < ba.ymin) {
          continue;
        }
        const std::size_t owner = cell_index(std::max(ba.ymin, bd.ymin), y0, inv_h, ny) * nx +
                                  cell_index(std::max(ba.xmin, bd.xmin), x0, inv_h, nx);
        if (owner != c) {
          continue;
        }
        const double gap = std::hypot(a.centre.x - d.centre.x, a.centre.y - d.centre.y) - a.radius - d.radius;
        if (gap <= tol) {
          ++s.contacts;
          ++degree[members[p]];
          ++degree[members[q]];
        }
        if (gap < -tol) {
          ++s.overlaps;
          s.max_overlap = std::max(s.max_overlap, -gap);
        }
      }
    }
  }
}

// Fractions by stratified sampling: one point per cell of an nx x ny lattice over the bounding
// box, at a hashed position in its cell (independently in x and y, so that the estimate is a
// stratified one, never worse than independent points). Rows of cells are swept upwards; the
// disks meeting the row are kept in an active list (disks sorted by their lowest y).
void sample_fractions(const Domain& domain, std::span<const Disk> disks, const EdgeIndex& edges, double w,
                      std::size_t samples, PackingStats& s, const std::stop_token& stop) {
  const Box b = domain.bbox();
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
  std::vector<std::uint32_t> order(disks.size());
  for (std::size_t k = 0; k < order.size(); ++k) {
    order[k] = static_cast<std::uint32_t>(k);
  }
  std::sort(order.begin(), order.end(), [&disks](std::uint32_t p, std::uint32_t q) {
    return disks[p].centre.y - disks[p].radius < disks[q].centre.y - disks[q].radius;
  });
  std::vector<std::uint32_t> active;
  std::size_t next = 0;
  std::vector<Point> points(nx);
  std::vector<std::uint8_t> covered(nx);
  std::size_t n_int = 0;
  std::size_t c_int = 0;
  std::size_t n_band = 0;
  std::size_t c_band = 0;
  for (std::size_t j = 0; j < ny; ++j) {
    detail::throw_if_stopped(stop);
    const double y0 = b.ymin + static_cast<double>(j) * sy;
    const double y1 = y0 + sy;
    for (std::size_t i = 0; i < nx; ++i) {
      const std::uint64_t key = mix(mix(0x5eed0000ULL + j) ^ i);
      points[i] = Point{b.xmin + (static_cast<double>(i) + unit(key)) * sx, y0 + unit(mix(key)) * sy};
    }
    while (next < order.size() && disks[order[next]].centre.y - disks[order[next]].radius <= y1) {
      active.push_back(order[next++]);
    }
    std::fill(covered.begin(), covered.end(), std::uint8_t{0});
    std::size_t keep = 0;
    for (const std::uint32_t k : active) {
      const Disk& d = disks[k];
      if (d.centre.y + d.radius < y0) {
        continue;  // below this row, hence below every later one
      }
      active[keep++] = k;
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
      if (domain.locate(p) == Location::outside) {
        continue;
      }
      if (edges.closer_than(p, w)) {
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
}

// Wall contacts of one disk: distinct closest points of the edges it touches.
std::size_t wall_contacts(const EdgeIndex& edges, const Disk& d, double tol) {
  std::vector<Point> points;
  edges.near(d.centre, d.radius + tol, [&](Point q, double dist) {
    if (dist - d.radius > tol) {
      return;
    }
    for (const Point& r : points) {
      if (std::hypot(r.x - q.x, r.y - q.y) <= tol + 1e-9 * d.radius) {
        return;
      }
    }
    points.push_back(q);
  });
  return points.size();
}

// The area weight of radius x, r^2 at a scale k from square_safe_scale() (the weights are only
// ever compared with or divided by one another).
double weight(double x, double k) noexcept {
  const double y = x * k;
  return y * y;
}

// The radius with half of the area (sum of r^2) at or below it; sorts r. 0 for none.
double median_by_area(std::vector<double>& r) {
  std::sort(r.begin(), r.end());
  const double k = square_safe_scale(r.empty() ? 1 : r.back());
  double total = 0;
  for (const double x : r) {
    total += weight(x, k);
  }
  double acc = 0;
  for (const double x : r) {
    acc += weight(x, k);
    if (acc >= total / 2) {
      return x;
    }
  }
  return 0;
}

// Two-sample Kolmogorov-Smirnov distance by area, sup over r of |A_a(r) - A_b(r)| with A_s(r) the
// share of s's area in radii <= r; a and b sorted. 0 if either is empty.
double ks_by_area(const std::vector<double>& a, const std::vector<double>& b) {
  if (a.empty() || b.empty()) {
    return 0;
  }
  const double k = square_safe_scale(std::max(a.back(), b.back()));
  double total_a = 0;
  double total_b = 0;
  for (const double x : a) {
    total_a += weight(x, k);
  }
  for (const double x : b) {
    total_b += weight(x, k);
  }
  double ks = 0;
  double acc_a = 0;
  double acc_b = 0;
  std::size_t i = 0;
  std::size_t j = 0;
  while (i < a.size() || j < b.size()) {
    // Both sides of each jump: take every radius equal to the smallest one left, then compare.
    const double x = j == b.size() || (i < a.size() && a[i] <= b[j]) ? a[i] : b[j];
    while (i < a.size() && a[i] == x) {
      acc_a += weight(x, k);
      ++i;
    }
    while (j < b.size() && b[j] == x) {
      acc_b += weight(x, k);
      ++j;
    }
    ks = std::max(ks, std::abs(acc_a / total_a - acc_b / total_b));
  }
  return ks;
}

}  // namespace

SizeStats measure_sizes(std::span<const double> radii, const RadiusDistribution* requested,
                        std::size_t histogram_bins) {
  SizeStats s;
  s.count = radii.size();
  if (requested != nullptr) {
    s.compared = true;
    s.requested = requested->describe();
  }
  std::vector<double> r(radii.begin(), radii.end());
  std::sort(r.begin(), r.end());
  const std::size_t n = r.size();
  // Area weights (r^2) at a scale where they neither overflow nor underflow.
  const double k = square_safe_scale(n > 0 ? r.back() : 1);
  double total_area = 0;
  double sum = 0;
  for (const double x : r) {
    total_area += weight(x, k);
    sum += x;
  }
  if (n > 0) {
    s.rmin = r.front();
    s.rmax = r.back();
    s.mean = sum / static_cast<double>(n);
    double var = 0;
    for (const double x : r) {
      const double d = (x - s.mean) * k;
      var += d * d;
    }
    s.sd = std::sqrt(var / static_cast<double>(n)) / k;
    s.median_number = r[(n - 1) / 2];
    double acc = 0;
    for (const double x : r) {
      acc += weight(x, k);
      if (acc >= total_area / 2) {
        s.median_area = x;
        break;
      }
    }
  }
  // KS distances over the distinct radii: compare both sides of each jump.
  if (requested != nullptr && n > 0) {
    double count_before = 0;
    double area_before = 0;
    for (std::size_t i = 0; i < n;) {
      const double x = r[i];
      double area_here = 0;
      std::size_t m = i;
      while (m < n && r[m] == x) {
        area_here += weight(x, k);
        ++m;
      }
      const double fn_lo = count_before / static_cast<double>(n);
      const double fn_hi = static_cast<double>(m) / static_cast<double>(n);
      const double fa_lo = area_before / total_area;
      const double fa_hi = (area_before + area_here) / total_area;
      const double below = std::nextafter(x, 0.0);
      const double dn = std::max(std::abs(fn_hi - requested->cdf(x)), std::abs(fn_lo - requested->cdf(below)));
      const double da =
          std::max(std::abs(fa_hi - requested->area_cdf(x)), std::abs(fa_lo - requested->area_cdf(below)));
      if (dn > s.ks_number) {
        s.ks_number = dn;
        s.ks_number_at = x;
      }
      if (da > s.ks_area) {
        s.ks_area = da;
        s.ks_area_at = x;
      }
      count_before = static_cast<double>(m);
      area_before += area_here;
      i = m;
    }
  }
  // Per-class table: classes (previous radius, radius].
  if (requested != nullptr) {
    const std::vector<double> classes = requested->class_radii();
    std::size_t next = 0;
    double count = 0;
    double area = 0;
    SizeClassRow previous;
    for (const double c : classes) {
      while (next < n && r[next] <= c) {
        count += 1;
        area += weight(r[next], k);
        ++next;
      }
      SizeClassRow row;
      row.radius = c;
      row.requested_number_passing = requested->cdf(c);
      row.requested_area_passing = requested->area_cdf(c);
      row.achieved_number_passing = n > 0 ? count / static_cast<double>(n) : 0;
      row.achieved_area_passing = total_area > 0 ? area / total_area : 0;
      row.requested_number = row.requested_number_passing - previous.requested_number_passing;
      row.requested_area = row.requested_area_passing - previous.requested_area_passing;
      row.achieved_number = row.achieved_number_passing - previous.achieved_number_passing;
      row.achieved_area = row.achieved_area_passing - previous.achieved_area_passing;
      s.classes.push_back(row);
      previous = row;
    }
  }
  // Histogram, log-spaced over the achieved and requested ranges.
  double lo = n > 0 ? s.rmin : INFINITY;
  double hi = n > 0 ? s.rmax : -INFINITY;
  if (requested != nullptr) {
    lo = std::min(lo, requested->min());
    hi = std::max(hi, requested->max());
  }
  if (histogram_bins > 0 && lo <= hi) {
    const std::size_t bins = lo == hi ? 1 : histogram_bins;
    // hi / lo overflows for radii spanning more than the range of doubles (1e-10 to 1e308): then
    // the edges are taken from log(lo) (the same edges up to rounding).
    const bool wide = !std::isfinite(hi / lo);
    const double log_span = wide ? std::log(hi) - std::log(lo) : std::log(hi / lo);
    const auto edge = [&](std::size_t b) {
      const double f = log_span * static_cast<double>(b) / static_cast<double>(bins);
      return wide ? std::exp(std::log(lo) + f) : lo * std::exp(f);
    };
    for (std::size_t b = 0; b < bins; ++b) {
      HistogramBin bin;
      bin.lo = b == 0 ? lo : edge(b);
      bin.hi = b + 1 == bins ? hi : edge(b + 1);
      s.histogram.push_back(bin);
    }
    for (const double x : r) {
      std::size_t b = 0;
      if (bins > 1) {
        const double t = std::floor(std::log(x / lo) / log_span * static_cast<double>(bins));
        b = t > 0 ? (t < static_cast<double>(bins - 1) ? static_cast<std::size_t>(t) : bins - 1) : 0;  // NaN: 0
        // The computed index may be off by one at a bin edge: settle on the bounds.
        while (b > 0 && x < s.histogram[b].lo) {
          --b;
        }
        while (b + 1 < bins && x >= s.histogram[b + 1].lo) {
          ++b;
        }
      }
      HistogramBin& bin = s.histogram[b];
      ++bin.count;
      bin.achieved_number += 1 / static_cast<double>(n);
      bin.achieved_area += weight(x, k) / total_area;
    }
    if (requested != nullptr) {
      for (std::size_t b = 0; b < bins; ++b) {
        HistogramBin& bin = s.histogram[b];
        const double below = std::nextafter(bin.lo, 0.0);
        const double top = b + 1 == bins ? bin.hi : std::nextafter(bin.hi, 0.0);
        bin.requested_number = requested->cdf(top) - (b == 0 ? 0.0 : requested->cdf(below));
        bin.requested_area = requested->area_cdf(top) - (b == 0 ? 0.0 : requested->area_cdf(below));
      }
    }
  }
  return s;
}

namespace {

// measure() on the domain and the disks scaled by k (a power of two > 1: exact), with the lengths
// and areas it reports scaled back: for lengths so small that their squares underflow.
PackingStats measure_scaled(const Domain& domain, std::span<const Disk> disks, const StatsOptions& options,
                            double k) {
  std::vector<Polygon> polygons = domain.polygons();
  const auto scale_ring = [k](Ring& ring) {
    for (Point& p : ring) {
      p = {p.x * k, p.y * k};
    }
  };
  for (Polygon& polygon : polygons) {
    scale_ring(polygon.outer);
    for (Ring& hole : polygon.holes) {
      scale_ring(hole);
    }
  }
  std::vector<Disk> scaled(disks.begin(), disks.end());
  for (Disk& d : scaled) {
    d = Disk{{d.centre.x * k, d.centre.y * k}, d.radius * k};
  }
  StatsOptions o = options;
  o.contact_gap *= k;
  o.band_width *= k;
  PackingStats s = measure(Domain::from_polygons(std::move(polygons)), scaled, o);
  const double inv = 1 / k;
  s.domain_area = domain.area();
  s.disk_area = 0;
  std::vector<double> radii;
  radii.reserve(disks.size());
  for (const Disk& d : disks) {
    radii.push_back(d.radius);
    s.disk_area += std::numbers::pi * d.radius * d.radius;
  }
  s.band_width *= inv;
  s.contact_gap *= inv;
  s.max_overlap *= inv;
  s.interior_area *= inv * inv;
  s.band_area *= inv * inv;
  s.band_median_area *= inv;
  s.inside_median_area *= inv;
  s.sizes =
      measure_sizes(radii, options.requested ? &options.requested->distribution() : nullptr, options.histogram_bins);
  return s;
}

}  // namespace

PackingStats measure(const Domain& domain, std::span<const Disk> disks, const StatsOptions& options) {
  double largest = 0;  // |coordinate| or radius
  double largest_radius = 0;
  for (std::size_t k = 0; k < disks.size(); ++k) {
    const Disk& d = disks[k];
    if (!std::isfinite(d.centre.x) || !std::isfinite(d.centre.y) || !std::isfinite(d.radius) || !(d.radius > 0)) {
      throw std::invalid_argument("measure: disk " + std::to_string(k) + " (centre " + detail::format_point(d.centre) +
                                  ", radius " + detail::format_double(d.radius) +
                                  ") needs a finite centre and a finite radius > 0");
    }
    largest = std::max({largest, std::abs(d.centre.x), std::abs(d.centre.y), d.radius});
    largest_radius = std::max(largest_radius, d.radius);
  }
  // A domain and disks so small that areas and squared distances underflow (a domain at 1e-200):
  // measured at the scale of 1, unless a disk would then overflow.
  if (const double k = square_safe_scale(domain.max_abs_coordinate() + 5 * largest_radius);
      k > 1 && std::isfinite(largest * k)) {
    return measure_scaled(domain, disks, options, k);
  }
  PackingStats s;
  s.disks = disks.size();
  s.domain_area = domain.area();
  std::vector<double> radii;
  radii.reserve(disks.size());
  for (const Disk& d : disks) {
    radii.push_back(d.radius);
    s.disk_area += std::numbers::pi * d.radius * d.radius;
  }
  s.sizes =
      measure_sizes(radii, options.requested ? &options.requested->distribution() : nullptr, options.histogram_bins);
  s.packing_fraction = s.disk_area == 0 ? 0 : s.disk_area / s.domain_area;  // (no disk: 0, also where the area underflows)
  s.void_ratio = !(s.packing_fraction > 0)                ? std::numeric_limits<double>::infinity()
                 : std::isfinite(s.packing_fraction) ? (1 - s.packing_fraction) / s.packing_fraction
                                                     : -1.0;  // disk areas beyond the doubles (radii of 1e308)
  const double rmax = s.sizes.rmax;
  s.band_width = options.band_width > 0 ? options.band_width : 2 * rmax;
  s.contact_gap =
      options.contact_gap > 0
          ? options.contact_gap
          : std::max(1e-9 * rmax, 0x1p-42 * std::min(domain.max_abs_coordinate() + 5 * rmax,
                                                       std::numeric_limits<double>::max()));  // (finite for any radius)
  const double w = s.band_width;
  const EdgeIndex edges(domain, w > 0 ? w : std::sqrt(domain.area()) / 64);
  sample_fractions(domain, disks, edges, w, options.samples, s, options.stop);
  if (disks.empty()) {
    return s;
  }
  std::vector<std::size_t> degree(disks.size(), 0);
  count_contacts(disks, s.contact_gap, s, degree, options.stop);
  std::size_t interior_contacts = 0;
  std::size_t non_rattler_contacts = 0;
  for (std::size_t k = 0; k < disks.size(); ++k) {
    detail::throw_if_stopped(options.stop, k);
    const Disk& d = disks[k];
    const std::size_t walls = wall_contacts(edges, d, s.contact_gap);
    s.wall_contacts += walls;
    if (degree[k] >= s.coordination_histogram.size()) {
      s.coordination_histogram.resize(degree[k] + 1, 0);
    }
    ++s.coordination_histogram[degree[k]];
    if (degree[k] + walls < 3) {
      ++s.rattlers;
    } else {
      non_rattler_contacts += degree[k];
    }
    if (!edges.closer_than(d.centre, w + d.radius)) {
      ++s.interior_disks;
      interior_contacts += degree[k];
    }
  }
  const auto n = static_cast<double>(disks.size());
  s.mean_coordination = 2 * static_cast<double>(s.contacts) / n;
  const double non_rattlers = n - static_cast<double>(s.rattlers);
  s.mean_coordination_without_rattlers =
      non_rattlers > 0 ? static_cast<double>(non_rattler_contacts) / non_rattlers : 0;
  s.interior_coordination =
      s.interior_disks > 0 ? static_cast<double>(interior_contacts) / static_cast<double>(s.interior_disks) : 0;

  std::vector<double> band;
  std::vector<double> inside;
  for (const Disk& d : disks) {
    (edges.closer_than(d.centre, w) ? band : inside).push_back(d.radius);
  }
  s.band_disks = band.size();
  s.band_median_area = median_by_area(band);
  s.inside_median_area = median_by_area(inside);
  s.segregation_ks_area = ks_by_area(band, inside);
  return s;
}

}  // namespace frontpack
