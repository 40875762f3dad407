// Size statistics: moments, medians, KS distances against a request, per-class table, histogram.
#include <algorithm>
#include <cmath>
#include <vector>

#include "common/radix_sort.hpp"
#include "stats/parts.hpp"

namespace frontpack {

namespace detail {

// The radius with half of the area (sum of r^2) at or below it; sorts r. 0 for none.
double median_by_area(std::vector<double>& r) {
  detail::sort_non_negative(r);
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

}  // namespace detail

using detail::square_safe_scale;
using detail::weight;

namespace {

// The radii sorted, with their area weights (r^2) at a scale k where they neither overflow nor
// underflow, and the total of those weights.
struct Sorted {
  std::vector<double> r;
  double k = 1;
  double total_area = 0;
  double sum = 0;  // of the radii
};

Sorted sort_radii(std::span<const double> radii) {
  Sorted sr;
  sr.r.assign(radii.begin(), radii.end());
  detail::sort_non_negative(sr.r);
  sr.k = square_safe_scale(!sr.r.empty() ? sr.r.back() : 1);
  for (const double x : sr.r) {
    sr.total_area += weight(x, sr.k);
    sr.sum += x;
  }
  return sr;
}

// Range, mean, standard deviation and the medians by number and by area; n > 0.
void moments(const Sorted& sr, SizeStats& s) {
  const std::vector<double>& r = sr.r;
  const double k = sr.k;
  const std::size_t n = r.size();
  s.rmin = r.front();
  s.rmax = r.back();
  s.mean = sr.sum / static_cast<double>(n);
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
    if (acc >= sr.total_area / 2) {
      s.median_area = x;
      break;
    }
  }
}

// KS distances by number and by area over the distinct radii: compare both sides of each jump;
// n > 0.
void ks_distances(const Sorted& sr, const RadiusDistribution& requested, SizeStats& s) {
  const std::vector<double>& r = sr.r;
  const std::size_t n = r.size();
  double count_before = 0;
  double area_before = 0;
  for (std::size_t i = 0; i < n;) {
    const double x = r[i];
    double area_here = 0;
    std::size_t m = i;
    while (m < n && r[m] == x) {
      area_here += weight(x, sr.k);
      ++m;
    }
    const double fn_lo = count_before / static_cast<double>(n);
    const double fn_hi = static_cast<double>(m) / static_cast<double>(n);
    const double fa_lo = area_before / sr.total_area;
    const double fa_hi = (area_before + area_here) / sr.total_area;
    const double below = std::nextafter(x, 0.0);
    const double dn = std::max(std::abs(fn_hi - requested.cdf(x)), std::abs(fn_lo - requested.cdf(below)));
    const double da = std::max(std::abs(fa_hi - requested.area_cdf(x)), std::abs(fa_lo - requested.area_cdf(below)));
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
void class_table(const Sorted& sr, const RadiusDistribution& requested, SizeStats& s) {
  const std::vector<double>& r = sr.r;
  const std::size_t n = r.size();
  const std::vector<double> classes = requested.class_radii();
  std::size_t next = 0;
  double count = 0;
  double area = 0;
  SizeClassRow previous;
  for (const double c : classes) {
    while (next < n && r[next] <= c) {
      count += 1;
      area += weight(r[next], sr.k);
      ++next;
    }
    SizeClassRow row;
    row.radius = c;
    row.requested_number_passing = requested.cdf(c);
    row.requested_area_passing = requested.area_cdf(c);
    row.achieved_number_passing = n > 0 ? count / static_cast<double>(n) : 0;
    row.achieved_area_passing = sr.total_area > 0 ? area / sr.total_area : 0;
    row.requested_number = row.requested_number_passing - previous.requested_number_passing;
    row.requested_area = row.requested_area_passing - previous.requested_area_passing;
    row.achieved_number = row.achieved_number_passing - previous.achieved_number_passing;
    row.achieved_area = row.achieved_area_passing - previous.achieved_area_passing;
    s.classes.push_back(row);
    previous = row;
  }
}

// Histogram, log-spaced over the achieved and requested ranges (none when both are empty).
void histogram(const Sorted& sr, const RadiusDistribution* requested, std::size_t histogram_bins, SizeStats& s) {
  const std::vector<double>& r = sr.r;
  const std::size_t n = r.size();
  double lo = n > 0 ? s.rmin : INFINITY;
  double hi = n > 0 ? s.rmax : -INFINITY;
  if (requested != nullptr) {
    lo = std::min(lo, requested->min());
    hi = std::max(hi, requested->max());
  }
  if (histogram_bins == 0 || !(lo <= hi)) {
    return;
  }
  const RadiusBins edges(lo, hi, lo == hi ? 1 : histogram_bins, BinSpacing::log);
  const std::size_t bins = edges.count();
  for (std::size_t b = 0; b < bins; ++b) {
    HistogramBin bin;
    bin.lo = edges.edges()[b];
    bin.hi = edges.edges()[b + 1];
    s.histogram.push_back(bin);
  }
  for (const double x : r) {
    HistogramBin& bin = s.histogram[edges.bin_of(x)];
    ++bin.count;
    bin.achieved_number += 1 / static_cast<double>(n);
    bin.achieved_area += weight(x, sr.k) / sr.total_area;
  }
  if (requested == nullptr) {
    return;
  }
  for (std::size_t b = 0; b < bins; ++b) {
    HistogramBin& bin = s.histogram[b];
    const double below = std::nextafter(bin.lo, 0.0);
    const double top = b + 1 == bins ? bin.hi : std::nextafter(bin.hi, 0.0);
    bin.requested_number = requested->cdf(top) - (b == 0 ? 0.0 : requested->cdf(below));
    bin.requested_area = requested->area_cdf(top) - (b == 0 ? 0.0 : requested->area_cdf(below));
  }
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
  const Sorted sr = sort_radii(radii);
  const bool any = !sr.r.empty();
  if (any) {
    moments(sr, s);
  }
  if (requested != nullptr && any) {
    ks_distances(sr, *requested, s);
  }
  if (requested != nullptr) {
    class_table(sr, *requested, s);
  }
  histogram(sr, requested, histogram_bins, s);
  return s;
}

}  // namespace frontpack
