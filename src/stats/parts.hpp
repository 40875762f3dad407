// The parts of measure() (include/frontpack/stats.hpp), one file each: stratified sampling of the
// fractions and the coverage profile (sampling.cpp), contacts (contacts.cpp), size statistics
// (sizes.cpp, histogram.cpp), the largest empty circle (empty_circle.cpp) and the hole counts
// (holes.cpp) on the clearance field (clearance.hpp), the cell coverage (coverage.cpp).
#pragma once

#include <cmath>
#include <cstddef>
#include <span>
#include <stop_token>
#include <vector>

#include "domain/edge_distance.hpp"
#include "frontpack/stats.hpp"
#include "periodic/disk_images.hpp"

namespace frontpack::detail {

// A length scale (a power of two) that brings lengths of the order of `length` to about 1 when
// they are so small or so large that their squares leave the range of doubles; 1 otherwise (so
// that ordinary figures are the ones computed without it, bit for bit).
inline double square_safe_scale(double length) noexcept {
  if (!(length > 0) || !std::isfinite(length) || (length >= 0x1p-400 && length <= 0x1p400)) {
    return 1;
  }
  return std::ldexp(1.0, -std::clamp(std::ilogb(length), -1000, 1000));
}

// The area weight of radius x, r^2 at a scale k from square_safe_scale() (the weights are only
// ever compared with or divided by one another).
inline double weight(double x, double k) noexcept {
  const double y = x * k;
  return y * y;
}

/// Disk-disk contacts within `tol`: s.contacts, s.overlaps, s.max_overlap; degree[k] counts disk
/// k's contacts (k < images.originals()). Uses s.sizes.rmax. The images must reach 2 rmax + tol.
void count_contacts(const DiskImages& images, double tol, PackingStats& s, std::vector<std::size_t>& degree,
                    const std::stop_token& stop);

/// Wall contacts of one disk: distinct closest points of the edges it touches within `tol`.
std::size_t wall_contacts(const EdgeDistanceIndex& edges, const Disk& d, double tol);

/// The interior and band fractions by stratified sampling of about `samples` points, the band
/// being the points within w of the boundary; with unit > 0 also the coverage profile in bins of
/// `unit` (s.coverage_unit, s.coverage_profile). In a periodic cell `disks` are DiskImages::all()
/// with a reach of rmax at least.
void sample_fractions(const Domain& domain, std::span<const Disk> disks, const EdgeDistanceIndex& edges, double w,
                      std::size_t samples, double unit, PackingStats& s, const std::stop_token& stop);

class Clearance;

/// The largest empty circle, to within `tolerance` (empty_circle.cpp); `upper` receives an upper
/// bound of f on each grid cell of f.
EmptyCircle largest_empty_circle(const Clearance& f, double tolerance, std::vector<double>& upper,
                                 const std::stop_token& stop);

/// The number of holes that take a disk of radius rho (holes.cpp). `cell_upper`: upper bounds
/// of f on the grid cells of f (largest_empty_circle()'s), or empty. The squares it examines are
/// estimated first and held to `budget` (LimitError), and stopped there if the estimate was short.
std::size_t count_holes(const Clearance& f, double rho, std::span<const double> cell_upper, const Budget& budget,
                        const std::stop_token& stop);

/// The coverage of the interior cells of side `side` (coverage.cpp), their count over the domain's
/// box held to `budget` first (LimitError). In a periodic cell `disks` are DiskImages::all() with a
/// reach of side + rmax at least (a square wraps across a side).
void measure_cell_coverage(const Domain& domain, std::span<const Disk> disks, const EdgeDistanceIndex& edges, double w,
                           double side, const Budget& budget, CellCoverage& out, const std::stop_token& stop);

/// The radius with half of the area (sum of r^2) at or below it; sorts r. 0 for none.
double median_by_area(std::vector<double>& r);

/// Two-sample Kolmogorov-Smirnov distance by area; a and b sorted. 0 if either is empty.
double ks_by_area(const std::vector<double>& a, const std::vector<double>& b);

}  // namespace frontpack::detail
