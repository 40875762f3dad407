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
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "common/budget.hpp"
#include "common/format.hpp"
#include "common/stop.hpp"
#include "periodic/disk_images.hpp"
#include "stats/clearance.hpp"
#include "stats/parts.hpp"

namespace frontpack {

namespace {

using detail::count_contacts;
using detail::EdgeDistanceIndex;
using detail::ks_by_area;
using detail::median_by_area;
using detail::sample_fractions;
using detail::square_safe_scale;
using detail::wall_contacts;

// measure() on the domain and the disks scaled by k (a power of two > 1: exact), with the lengths
// and areas it reports scaled back: for lengths so small that their squares underflow.
PackingStats measure_scaled(const Domain& domain, std::span<const Disk> disks, const StatsOptions& options, double k) {
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
  o.cell_side *= k;
  for (double& rho : o.hole_radii) {
    rho *= k;
  }
  const Box c = domain.bbox();
  const Domain scaled_domain =
      domain.periodicity() == Periodicity::none
          ? Domain::from_polygons(std::move(polygons))
          : Domain::periodic({c.xmin * k, c.ymin * k, c.xmax * k, c.ymax * k}, domain.periodicity());
  PackingStats s = measure(scaled_domain, scaled, o);
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
  EmptyCircle& e = s.largest_empty_circle;
  e.radius *= inv;
  e.radius_upper *= inv;
  e.tolerance *= inv;
  e.centre = {e.centre.x * inv, e.centre.y * inv};
  for (HoleCount& h : s.holes) {
    h.radius *= inv;
  }
  s.coverage_unit *= inv;
  for (CoverageBin& bin : s.coverage_profile) {
    bin.from *= inv;
    bin.to *= inv;
  }
  s.cell_coverage.cell_side *= inv;
  s.cell_coverage.origin = {s.cell_coverage.origin.x * inv, s.cell_coverage.origin.y * inv};
  s.sizes =
      measure_sizes(radii, options.requested ? &options.requested->distribution() : nullptr, options.histogram_bins);
  return s;
}

// The side of the cell coverage's cells: the one asked for, or 8 rmax.
double cell_side(const StatsOptions& options, double rmax) {
  return options.cell_side > 0 && std::isfinite(options.cell_side) ? options.cell_side : 8 * rmax;
}

// The hole radii asked for, or the defaults.
std::vector<double> hole_radii(const StatsOptions& options, const PackingStats& s, std::size_t disks) {
  std::vector<double> radii = options.hole_radii;
  if (radii.empty() && disks > 0) {
    radii = {s.sizes.median_number, s.sizes.rmax};
  }
  return radii;
}

// How far from a periodic cell the images of the disks must reach for the measures asked for:
// rmax for the sampling (a disk covering a point of the cell), 2 rmax + the contact gap for the
// contacts, the cells' side + rmax for the cell coverage (a square reaching across a side, and a
// disk), and for the clearance rmax + its grid's side (about 2 mean radii) + the largest value of
// f that matters: 2 rmax for the largest empty circle's first try (measure_voids() widens the
// images when it is larger), or the largest hole radius (f is at most half the cell's diagonal).
double image_reach(const StatsOptions& options, const PackingStats& s, std::span<const double> radii,
                   const detail::Periods& periods) {
  const double rmax = s.sizes.rmax;
  const double f_max = 0.5 * std::hypot(periods.lx, periods.ly);
  double reach = options.samples > 0 ? rmax : 0;
  if (options.contacts) {
    reach = std::max(reach, 2 * rmax + s.contact_gap);
  }
  if (options.cell_coverage) {
    reach = std::max(reach, cell_side(options, rmax) + rmax);
  }
  if (options.empty_circle) {
    reach = std::max(reach, 5 * rmax);
  }
  if (options.holes) {
    for (const double rho : radii) {
      reach = std::max(reach, 3 * rmax + std::min(rho, f_max));
    }
  }
  return reach;
}

// The largest empty circle, the holes and the cell coverage. `images`: the disks with their images
// within `reach` of a periodic cell.
void measure_voids(const Domain& domain, std::span<const Disk> disks, const detail::DiskImages& images, double reach,
                   const EdgeDistanceIndex& edges, const StatsOptions& options, PackingStats& s) {
  const std::vector<double> radii = hole_radii(options, s, disks.size());
  const bool holes = options.holes && !radii.empty();
  const detail::Periods periods(domain);
  // A cell periodic in x and y without disks has no wall either: f is unbounded.
  if ((options.empty_circle || holes) && (edges.has_walls() || !disks.empty())) {
    std::optional<detail::DiskImages> wider;
    std::optional<detail::Clearance> f;
    f.emplace(domain, images, edges);
    // f from the images is exact where it is at most reach - rmax - the grid's side
    // (stats/clearance.hpp). Beyond, the nearest disk may be an image left out: then f is measured
    // again with every image that can be the nearest, f being at most half the cell's diagonal
    // (a disk's nearest translate is no farther; Periodicity::x: the nearer wall is no farther).
    const double rmax = s.sizes.rmax;
    const double exact_to = reach - rmax - f->side();
    const double all = rmax + f->side() + 0.5 * std::hypot(periods.lx, periods.ly) * (1 + 1e-9);
    const auto widen = [&] {
      wider.emplace(periods, disks, all, options.budget);
      f.emplace(domain, *wider, edges);
    };
    const bool can_widen = periods.any() && all > reach;
    const double largest_rho = holes ? *std::max_element(radii.begin(), radii.end()) : 0;
    if (can_widen && !options.empty_circle && !(largest_rho <= exact_to)) {
      widen();
    }
    const Box b = domain.bbox();
    // 1% of the smallest radius; without disks a millionth of the domain's size.
    const double tolerance = disks.empty() ? 1e-6 * std::max(b.width(), b.height()) : 0.01 * s.sizes.rmin;
    std::vector<double> cell_upper;  // stays empty without the empty circle
    if (options.empty_circle) {
      s.largest_empty_circle = detail::largest_empty_circle(*f, tolerance, cell_upper, options.stop);
      // (The holes then need no more: a radius above the circle's upper bound has none.)
      if (can_widen && !(s.largest_empty_circle.radius_upper <= exact_to)) {
        widen();
        s.largest_empty_circle = detail::largest_empty_circle(*f, tolerance, cell_upper, options.stop);
      }
      if (periods.any()) {
        s.largest_empty_circle.centre = detail::wrap(periods, s.largest_empty_circle.centre);
      }
    }
    if (holes) {
      for (const double rho : radii) {
        // No hole takes a disk larger than the largest empty circle.
        const bool none =
            s.largest_empty_circle.computed ? rho > s.largest_empty_circle.radius_upper : options.empty_circle;
        if (!s.holes.empty() && s.holes.back().radius == rho) {
          s.holes.push_back(s.holes.back());  // (the default radii of equal disks)
          continue;
        }
        s.holes.push_back({rho, none ? 0 : detail::count_holes(*f, rho, cell_upper, options.budget, options.stop)});
      }
    }
  }
  if (options.cell_coverage && !disks.empty()) {
    detail::measure_cell_coverage(domain, images.all(), edges, s.band_width, cell_side(options, s.sizes.rmax),
                                  options.budget, s.cell_coverage, options.stop);
  }
}

// The largest |coordinate| or radius and the largest radius of the disks; throws
// std::invalid_argument naming the first disk without a finite centre and a finite radius > 0.
std::pair<double, double> checked_extents(std::span<const Disk> disks) {
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
  return {largest, largest_radius};
}

// Areas, sizes, the packing fraction and void ratio, and the band width and contact gap that the
// later measures use (the options' or their defaults from the largest radius).
void measure_areas_and_sizes(const Domain& domain, std::span<const Disk> disks, const StatsOptions& options,
                             PackingStats& s) {
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
  s.packing_fraction =
      s.disk_area == 0 ? 0 : s.disk_area / s.domain_area;  // (no disk: 0, also where the area underflows)
  s.void_ratio = !(s.packing_fraction > 0)           ? std::numeric_limits<double>::infinity()
                 : std::isfinite(s.packing_fraction) ? (1 - s.packing_fraction) / s.packing_fraction
                                                     : -1.0;  // disk areas beyond the doubles (radii of 1e308)
  const double rmax = s.sizes.rmax;
  s.band_width = options.band_width > 0 ? options.band_width : 2 * rmax;
  s.contact_gap =
      options.contact_gap > 0
          ? options.contact_gap
          : std::max(1e-9 * rmax, 0x1p-42 * std::min(domain.max_abs_coordinate() + 5 * rmax,
                                                     std::numeric_limits<double>::max()));  // (finite for any radius)
}

// Contacts between disks (with their images) and with the walls, the coordination histogram,
// rattlers, and the mean coordinations overall, without rattlers and in the interior.
void measure_contacts(std::span<const Disk> disks, const detail::DiskImages& images, const EdgeDistanceIndex& edges,
                      const StatsOptions& options, PackingStats& s) {
  const double w = s.band_width;
  std::vector<std::size_t> degree(disks.size(), 0);
  count_contacts(images, s.contact_gap, s, degree, options.stop);
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
}

// Segregation: the sizes of the band disks against those inside, by area.
void measure_segregation(std::span<const Disk> disks, const EdgeDistanceIndex& edges, PackingStats& s) {
  const double w = s.band_width;
  std::vector<double> band;
  std::vector<double> inside;
  // A band disk comes within w / 2 of the boundary: its gap to the walls, not its centre, decides,
  // so every size has the same room to count (by its centre, a small disk a layer behind the wall
  // layer would be a band disk and a large one beside it not, and a packing mixed alike in every
  // layer would read as segregated).
  for (const Disk& d : disks) {
    (edges.closer_than(d.centre, d.radius + w / 2) ? band : inside).push_back(d.radius);
  }
  s.band_disks = band.size();
  s.band_median_area = median_by_area(band);
  s.inside_median_area = median_by_area(inside);
  s.segregation_ks_area = ks_by_area(band, inside);
}

}  // namespace

PackingStats measure(const Domain& domain, std::span<const Disk> disks, const StatsOptions& options) {
  const auto [largest, largest_radius] = checked_extents(disks);
  // A domain and disks so small that areas and squared distances underflow (a domain at 1e-200):
  // measured at the scale of 1, unless a disk would then overflow.
  if (const double k = square_safe_scale(domain.max_abs_coordinate() + 5 * largest_radius);
      k > 1 && std::isfinite(largest * k)) {
    return measure_scaled(domain, disks, options, k);
  }
  PackingStats s;
  measure_areas_and_sizes(domain, disks, options, s);
  // The sample points are the caller's own number (StatsOptions::samples), made a row at a time:
  // no memory grows with them, and holding them to max_count would let a small max_count for the
  // disks (fill --max-disks) refuse the statistics of the packing it allowed.
  // The walls (a periodic cell's real walls alone) and the disks with their images across the
  // periodic sides: what every measure below sees of the domain.
  const EdgeDistanceIndex edges(domain);
  s.walls = edges.has_walls();
  const detail::Periods periods(domain);
  const double reach = image_reach(options, s, hole_radii(options, s, disks.size()), periods);
  const detail::DiskImages images(periods, disks, reach, options.budget);
  sample_fractions(domain, images.all(), edges, s.band_width, options.samples,
                   options.coverage_profile ? s.sizes.rmax : 0, s, options.stop);
  measure_voids(domain, disks, images, reach, edges, options, s);
  if (disks.empty() || !options.contacts) {
    return s;
  }
  measure_contacts(disks, images, edges, options, s);
  measure_segregation(disks, edges, s);
  return s;
}

}  // namespace frontpack
