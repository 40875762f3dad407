// frontpack: the statistics a DEM user checks a packing by (any packing, not only frontpack's).
//
//   const frontpack::PackingStats s = frontpack::measure(domain, packing.disks, {.requested = options.radii});
//   // s.packing_fraction, s.interior_fraction, s.mean_coordination, s.rattlers, s.sizes.ks_area ...
//
// Definitions (docs/distributions.md has them with measured figures):
// - Packing fraction: total disk area / domain area. Disks are taken as given (inside the domain,
//   not overlapping: certify() checks that); nothing is clipped. Void ratio: (1 - phi) / phi.
// - Band and interior: the band is the set of points of the domain within band_width (default
//   2 rmax) of the boundary, the interior the rest of the domain. Their packing fractions (the
//   fraction of the region covered by disks) are estimated by sampling: about `samples` points on
//   a jittered lattice over the domain's bounding box (one point per lattice cell, at a
//   deterministic pseudo-random position in it: stratified sampling, no aliasing with lattice
//   packings), each classified exactly as inside the domain (Domain::locate), then by its
//   floating-point distance to the boundary, and as covered or not. The reported error is the
//   binomial standard error sqrt(phi (1 - phi) / n) of n independent points; stratified sampling
//   never has a larger variance. Measured on the hexagonal lattice (exact 0.906900): errors of
//   1.6e-4, 4.5e-4 and 1.4e-4 at 0.25, 1 and 4 million samples (reported 5.9e-4, 3.0e-4,
//   1.5e-4): disks a few sample spacings across leave most cells cut by a disk's edge.
// - Contacts: two disks are in contact when the gap |c1 - c2| - r1 - r2 <= contact_gap (overlaps
//   count too). Default contact_gap: max(1e-9 rmax, 2^-42 (largest |coordinate| + 5 rmax)), 16
//   times frontpack's automatic clearance (FillOptions::clearance), so that frontpack's tangent
//   disks count as touching at any scale and offset. Coordination number: disk-disk contacts
//   per disk, 2 * contacts / disks. A disk touches the wall when its distance to the boundary
//   minus its radius is <= contact_gap; each distinct touching point counts one wall contact.
// - Rattler: a disk with fewer than 3 contacts, counting disk-disk and wall contacts (in 2D a
//   disk needs 3 to be held in place); one pass, not iterated.
// - Interior disks: disks lying wholly in the interior (distance of the centre to the boundary
//   >= band_width + r); their mean coordination is free of the boundary's missing neighbours.
// - Sizes: the achieved radii against the requested distribution, by number and by area (each
//   disk weighted by r^2); Kolmogorov-Smirnov distances sup |F_achieved - F_requested|; a table
//   per class for discrete and grading-curve requests; a log-spaced histogram.
// - Size segregation: the "band disks", those whose gap to the boundary (the distance of the
//   centre minus the radius) is below band_width / 2 (at the default width, below rmax: the wall
//   layer), against the others. The gap rather than the centre decides, so that every size has
//   the same room to count: by the centre, the small disks of the second layer would count and the
//   large ones beside them not, and a packing with the same mix of sizes in every layer would read
//   as segregated. Their medians by area, and the two-sample Kolmogorov-Smirnov distance by area
//   between their radii: 0 when the walls hold the same mix of sizes as the inside; a generator
//   that fills the cusps along the walls with the small disks shows it (the band then holds more
//   of the fines than the inside, a wall effect of its own).
// - Clearance f(p) = min(s(p), min_i |p - c_i| - r_i), s the signed distance to the boundary
//   (positive inside): the radius of the largest disk centred at p that fits. It is 1-Lipschitz.
// - Largest empty circle: max f over the domain, by branch and bound on a quadtree over a grid of
//   cells of about two mean radii: the bound of f on a square is min_i (farthest point of the
//   square from c_i) - r_i and s(centre) + half-diagonal; squares whose bound is below the best
//   value found are dropped, the others split (children in decreasing order of their bounds)
//   until their bound is within `tolerance` (1% of the smallest radius; a millionth of the
//   domain's size without disks) of the best. `radius` = f(centre), a value reached at a point
//   located exactly inside the domain; `radius_upper` the largest bound left, so radius <= true
//   maximum <= radius_upper <= radius + tolerance (in floating point: distances a few ulps off).
// - Holes at rho: the connected components of {f >= rho} (centres where a disk of radius rho
//   fits), on the leaves of the same quadtree (squares where f < rho dropped, squares where
//   f >= rho throughout kept whole, the rest split to a half-diagonal of rho / 32; leaves
//   touching at an edge or corner joined). Components without a leaf whose centre is certified
//   to have f >= rho are not counted. A hole taking a disk of radius rho (1 + 1/32) is never
//   missed; two holes count as one only when {f >= rho (1 - 1/16)} joins them.
// - Coverage profile: the sample points (the same pass as the band and interior) binned by their
//   distance to the boundary, [k, k + 1) rmax for k = 0..5 and >= 6 rmax; covered fraction and
//   binomial error per bin.
// - Cell coverage: the bounding box cut into squares of side 8 rmax; a square counts when its
//   centre is inside the domain and no edge comes within band_width + its half-diagonal of the
//   centre (so it is wholly in the interior). Its covered fraction is exact: the sum of the
//   disks' intersection areas with it (disks assumed not to overlap), in floating point.
//
// A periodic cell (Domain::periodic): the disks meet the images of the others across the periodic
// sides, and the boundary is the real walls alone (none for Periodicity::xy, the bottom and top
// for Periodicity::x). Contacts across a side count once; wall contacts are with the walls;
// distances (band, interior disks, coverage profile, cell coverage, clearance) are to the walls,
// infinite without any: a cell periodic in x and y has no band (`walls` false, every sample and
// disk interior, the profile's samples all in its last bin, the band and segregation figures 0).
// A disk covers the cell's points within its radius across a side too; the cell coverage's
// squares go on across a periodic side (the last one wraps around, overlapping the first when
// the period is not a multiple of 8 rmax), none dropped there; the clearance measures to the
// nearest image, so the largest empty circle and the holes may wrap across a side (the centre is
// reported in the cell). The images taken are those within the reach each measure needs; a cell
// narrower than that reach gets images of images (several periods), so any width is measured,
// at a cost growing as (reach / period)^2 (beyond 1000 periods: std::invalid_argument).
//
// Cost: linear in the disks and the samples (uniform grids), and in E log E for the domain's E
// edges whatever the disks' size against the edges' length (the distance to the walls is a
// search of a hierarchy of the edges, domain/edge_distance.hpp): about 0.5 s per million samples
// plus 0.1 s per 50,000 disks (one core of an AMD EPYC). What measuring makes is counted before it
// is made and held to `budget` (LimitError): the hole probes (which grow as the
// disks' perimeter over the hole radius: a radius far below the disks' is refused), the coverage
// cells and a periodic cell's images (docs/robustness.md, "Derived counts in the statistics"). On a 958,549-disk
// packing of the unit square (uniform radii 0.0004-0.0006, docs/distributions.md has the command) the largest empty
// circle adds 0.4-0.5 s, the coverage profile and the cell coverage together under 0.1 s, and
// each hole radius 1-2 s (that packing has thousands of holes; a radius above the largest empty
// circle costs nothing).
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <stop_token>
#include <string>
#include <tuple>
#include <vector>

#include "frontpack/budget.hpp"
#include "frontpack/domain.hpp"
#include "frontpack/fields.hpp"
#include "frontpack/geometry.hpp"
#include "frontpack/sizes.hpp"

namespace frontpack {

struct StatsOptions {
  /// The requested radius distribution, for the size comparison (none: achieved sizes only).
  std::optional<Radii> requested;
  /// Contact tolerance on the gap between two disks (or a disk and the boundary); 0: automatic
  /// (see the header comment).
  double contact_gap = 0;
  /// Width of the boundary band; 0: 2 * the largest radius.
  double band_width = 0;
  /// About this many sample points for the interior and band fractions (0: no sampling).
  std::size_t samples = 1'000'000;
  /// Bins of the size histogram (log-spaced in radius).
  std::size_t histogram_bins = 20;
  /// Contacts, coordination, rattlers, wall contacts, interior disks and the band's size
  /// segregation (false: all left 0; about a third of measure()'s cost without the measures below).
  bool contacts = true;
  /// The largest empty circle (PackingStats::largest_empty_circle).
  bool empty_circle = true;
  /// Hole counts (PackingStats::holes) at these radii; empty: the packing's median radius by
  /// number and its largest radius.
  bool holes = true;
  std::vector<double> hole_radii{};
  /// Coverage by distance from the boundary (from the sample points: needs samples > 0).
  bool coverage_profile = true;
  /// Coverage of interior cells (exact disk-square areas), and the side of the cells; 0 (or not a
  /// finite number > 0): 8 * the largest radius. A fixed side compares packings of different
  /// radii cell for cell.
  bool cell_coverage = true;
  double cell_side = 0;
  /// What measuring may make: hole probes, cells, periodic images, each counted
  /// before it is made.
  Budget budget{};
  /// Once a stop is requested, measure() throws CancelledError.
  std::stop_token stop{};
};

/// One class of the per-class table: radii in (previous row's radius, radius]. Fractions in
/// the class, and cumulative ("passing": radius <= this row's radius), by number and by area.
struct SizeClassRow {
  double radius = 0;
  double requested_number = 0;
  double requested_area = 0;
  double achieved_number = 0;
  double achieved_area = 0;
  double requested_number_passing = 0;
  double requested_area_passing = 0;
  double achieved_number_passing = 0;
  double achieved_area_passing = 0;

  static constexpr auto fields() {
    return std::tuple{
        field("radius", &SizeClassRow::radius, "the class's largest radius"),
        field("requested_number", &SizeClassRow::requested_number, "the request's fraction in the class, by number"),
        field("requested_area", &SizeClassRow::requested_area, "the request's fraction in the class, by area"),
        field("achieved_number", &SizeClassRow::achieved_number, "the disks' fraction in the class, by number"),
        field("achieved_area", &SizeClassRow::achieved_area, "the disks' fraction in the class, by area"),
        field("requested_number_passing", &SizeClassRow::requested_number_passing,
              "the request's fraction at or below the radius, by number"),
        field("requested_area_passing", &SizeClassRow::requested_area_passing,
              "the request's fraction at or below the radius, by area"),
        field("achieved_number_passing", &SizeClassRow::achieved_number_passing,
              "the disks' fraction at or below the radius, by number"),
        field("achieved_area_passing", &SizeClassRow::achieved_area_passing,
              "the disks' fraction at or below the radius, by area")};
  }
};

/// How the bins of a radius histogram are spaced: equal ratios (SizeStats::histogram) or equal
/// widths (the tool's picture panel).
enum class BinSpacing : std::uint8_t { log, linear };

/// The bins of a radius histogram over [lo, hi]: bin b is [edges()[b], edges()[b + 1]), the last
/// one closed; edges()[0] is lo and edges()[count()] is hi, exactly. The one binning of radii
/// that measure_sizes() and the tool's pictures share.
class RadiusBins {
 public:
  /// Preconditions: count >= 1, lo <= hi, and lo > 0 for log spacing (else the bins are
  /// meaningless, though bin_of() still returns a bin). log spacing of a range wider than the
  /// doubles' ratios (hi / lo overflows) takes its edges from log(lo).
  RadiusBins(double lo, double hi, std::size_t count, BinSpacing spacing);

  [[nodiscard]] const std::vector<double>& edges() const noexcept { return edges_; }
  [[nodiscard]] std::size_t count() const noexcept { return edges_.size() - 1; }
  /// The bin holding x, settled by comparing x with the edges themselves (the index computed
  /// from x is a first guess that may be off by one at an edge). x below lo, and NaN, give bin 0;
  /// x above hi the last bin.
  [[nodiscard]] std::size_t bin_of(double x) const noexcept;

 private:
  BinSpacing spacing_;
  double lo_;
  double span_;  // log(hi / lo) or hi - lo
  std::vector<double> edges_;
};

/// A histogram bin [lo, hi) (the last one closed): the disks in it and their share of the number
/// and of the area, achieved and (when a request is given) requested.
struct HistogramBin {
  double lo = 0;
  double hi = 0;
  std::size_t count = 0;
  double achieved_number = 0;
  double achieved_area = 0;
  double requested_number = 0;
  double requested_area = 0;

  static constexpr auto fields() {
    return std::tuple{field("lo", &HistogramBin::lo, "the bin's smallest radius"),
                      field("hi", &HistogramBin::hi, "the bin's upper end"),
                      field("count", &HistogramBin::count, "the disks in the bin"),
                      field("achieved_number", &HistogramBin::achieved_number, "their share of the number"),
                      field("achieved_area", &HistogramBin::achieved_area, "their share of the area"),
                      field("requested_number", &HistogramBin::requested_number,
                            "the request's share of the number in the bin (0: no request)"),
                      field("requested_area", &HistogramBin::requested_area,
                            "the request's share of the area in the bin (0: no request)")};
  }
};

/// The radii achieved, against the request when one is given.
struct SizeStats {
  std::size_t count = 0;
  double rmin = 0;
  double rmax = 0;
  double mean = 0;
  double sd = 0;
  double median_number = 0;
  double median_area = 0;
  bool compared = false;
  std::string requested;
  double ks_number = 0;
  double ks_area = 0;
  double ks_number_at = 0;
  double ks_area_at = 0;
  std::vector<SizeClassRow> classes;
  std::vector<HistogramBin> histogram;

  static constexpr auto fields() {
    return std::tuple{
        field("count", &SizeStats::count, "the disks"),
        field("rmin", &SizeStats::rmin, "the smallest radius").json("min"),
        field("rmax", &SizeStats::rmax, "the largest radius").json("max"),
        field("mean", &SizeStats::mean, "mean radius (by number)"),
        field("sd", &SizeStats::sd, "standard deviation of the radius (by number)"),
        field("median_number", &SizeStats::median_number, "radius with half of the disks at or below it")
            .json("median_by_number"),
        field("median_area", &SizeStats::median_area, "radius with half of the disk area at or below it")
            .json("median_by_area"),
        field("compared", &SizeStats::compared, "a requested distribution was given"),
        field("requested", &SizeStats::requested, "its description (RadiusDistribution::describe())"),
        field("ks_number", &SizeStats::ks_number, "sup over r of |achieved - requested| cumulative fraction by number")
            .json("ks_by_number"),
        field("ks_area", &SizeStats::ks_area, "the same by area").json("ks_by_area"),
        field("ks_number_at", &SizeStats::ks_number_at, "a radius where the sup by number is reached")
            .json("ks_by_number_at"),
        field("ks_area_at", &SizeStats::ks_area_at, "a radius where the sup by area is reached").json("ks_by_area_at"),
        field("classes", &SizeStats::classes, "the per-class table: discrete and grading-curve requests only"),
        field("histogram", &SizeStats::histogram, "the log-spaced histogram of the radii")};
  }
};

/// The largest disk that fits in the domain without overlapping any disk: the maximum over the
/// points p of the domain of f(p) = min(distance from p to the boundary, min_i |p - c_i| - r_i).
/// radius = f(centre) <= true maximum <= radius_upper (branch and bound, see the header comment).
struct EmptyCircle {
  bool computed = false;
  double radius = 0;
  double radius_upper = 0;
  Point centre;
  double tolerance = 0;

  static constexpr auto fields() {
    return std::tuple{
        field("computed", &EmptyCircle::computed, "false: switched off, or no domain area"),
        field("radius", &EmptyCircle::radius, "f at `centre`, a lower bound of the maximum"),
        field("radius_upper", &EmptyCircle::radius_upper, "an upper bound of the maximum"),
        field("centre", &EmptyCircle::centre, "inside the domain (exact point location)"),
        field("tolerance", &EmptyCircle::tolerance, "the gap aimed at: radius_upper - radius <= tolerance")};
  }
};

/// The number of connected components of {p in the domain : f(p) >= radius}: the holes where a
/// disk of this radius fits (see the header comment for how connectivity is resolved).
struct HoleCount {
  double radius = 0;
  std::size_t count = 0;

  static constexpr auto fields() {
    return std::tuple{field("radius", &HoleCount::radius, "the radius of the disk that fits"),
                      field("count", &HoleCount::count, "the holes where it fits")};
  }
};

/// The covered fraction of the domain's points whose distance to the boundary is in [from, to)
/// (to = infinity for the last bin), from the sample points.
struct CoverageBin {
  double from = 0;
  double to = 0;
  double fraction = 0;
  double error = 0;
  std::size_t samples = 0;

  static constexpr auto fields() {
    return std::tuple{field("from", &CoverageBin::from, "the bin's smallest distance to the boundary"),
                      field("to", &CoverageBin::to, "its upper end (infinity for the last bin)"),
                      field("fraction", &CoverageBin::fraction, "covered fraction; 0 if no sample fell in the bin"),
                      field("error", &CoverageBin::error, "binomial standard error"),
                      field("samples", &CoverageBin::samples, "the sample points in the bin")};
  }
};

/// The covered fractions of the square cells of side cell_side (8 rmax by default) that lie wholly
/// in the interior: their number, the 1st, 5th and 50th percentiles (nearest rank) and the
/// standard deviation (over the cells), and the map of them, where seams and sparse patches show.
/// The cells over the domain's box are held to StatsOptions::budget (LimitError past it).
struct CellCoverage {
  double cell_side = 0;
  std::size_t cells = 0;
  double p1 = 0;
  double p5 = 0;
  double p50 = 0;
  double sd = 0;
  Point origin{};
  std::size_t nx = 0;
  std::size_t ny = 0;
  std::vector<double> map;

  static constexpr auto fields() {
    return std::tuple{
        field("cell_side", &CellCoverage::cell_side, "the side of the cells"),
        field("cells", &CellCoverage::cells, "0: not computed, or no cell wholly in the interior"),
        field("p1", &CellCoverage::p1, "the 1st percentile of the cells' covered fractions"),
        field("p5", &CellCoverage::p5, "the 5th percentile"),
        field("p50", &CellCoverage::p50, "the median"),
        field("sd", &CellCoverage::sd, "their standard deviation"),
        field("origin", &CellCoverage::origin, "the lower-left corner of the map's first cell"),
        field("nx", &CellCoverage::nx, "the map's cells across"),
        field("ny", &CellCoverage::ny, "the map's cells up"),
        field("map", &CellCoverage::map,
              "the covered fraction of the cell whose lower-left corner is origin + (i, j) cell_side is map[j * nx + "
              "i], NaN where that cell is not wholly in the interior (exactly `cells` of them are not NaN); in a "
              "periodic cell the last column or row wraps around the period; empty when not computed")};
  }
};

struct PackingStats {
  std::size_t disks = 0;
  double domain_area = 0;
  double disk_area = 0;
  double packing_fraction = 0;
  double void_ratio = 0;

  bool walls = true;
  double band_width = 0;
  double interior_fraction = 0;
  double band_fraction = 0;
  double interior_error = 0;
  double band_error = 0;
  double interior_area = 0;
  double band_area = 0;
  std::size_t interior_samples = 0;
  std::size_t band_samples = 0;

  double contact_gap = 0;
  std::size_t contacts = 0;
  std::size_t overlaps = 0;
  double max_overlap = 0;
  std::size_t wall_contacts = 0;
  double mean_coordination = 0;
  std::vector<std::size_t> coordination_histogram;
  std::size_t rattlers = 0;
  double mean_coordination_without_rattlers = 0;
  std::size_t interior_disks = 0;
  double interior_coordination = 0;

  std::size_t band_disks = 0;
  double band_median_area = 0;
  double inside_median_area = 0;
  double segregation_ks_area = 0;

  EmptyCircle largest_empty_circle;
  std::vector<HoleCount> holes;
  double coverage_unit = 0;
  std::vector<CoverageBin> coverage_profile;
  CellCoverage cell_coverage;

  SizeStats sizes;

  // The field list in three parts (each under the 80-line rule), defined before fields() so that
  // their return types are known there.
  static constexpr auto overall_fields() {
    using S = PackingStats;
    return std::tuple{
        field("disks", &S::disks, "the disks measured"),
        field("domain_area", &S::domain_area, "Domain::area()"),
        field("disk_area", &S::disk_area, "sum of pi r^2"),
        field("packing_fraction", &S::packing_fraction, "disk_area / domain_area"),
        field("void_ratio", &S::void_ratio, "(1 - phi) / phi (infinity for no disks)"),
        field("walls", &S::walls, "false: a cell periodic in x and y, no boundary hence no band"),
        field("band_width", &S::band_width, "the width of the band used"),
        field("interior_fraction", &S::interior_fraction, "sampled; 0 if the interior got no sample"),
        field("band_fraction", &S::band_fraction, "sampled; 0 if the band got no sample"),
        field("interior_error", &S::interior_error, "binomial standard error (an upper bound, see above)")
            .json("interior_fraction_error"),
        field("band_error", &S::band_error, "binomial standard error of band_fraction").json("band_fraction_error"),
        field("interior_area", &S::interior_area, "sampled estimate of the interior's area"),
        field("band_area", &S::band_area, "sampled estimate of the band's area"),
        field("interior_samples", &S::interior_samples, "sample points in the interior"),
        field("band_samples", &S::band_samples, "sample points in the band")};
  }
  static constexpr auto contact_fields() {
    using S = PackingStats;
    return std::tuple{
        field("contact_gap", &S::contact_gap, "the contact tolerance used"),
        field("contacts", &S::contacts, "disk-disk pairs in contact"),
        field("overlaps", &S::overlaps, "pairs whose gap is below -contact_gap"),
        field("max_overlap", &S::max_overlap, "largest -gap among them (0 if none)"),
        field("wall_contacts", &S::wall_contacts, "disk-boundary contacts"),
        field("mean_coordination", &S::mean_coordination, "2 contacts / disks"),
        field("coordination_histogram", &S::coordination_histogram, "[k]: disks with k disk-disk contacts"),
        field("rattlers", &S::rattlers, "disks with < 3 contacts (walls included)"),
        field("mean_coordination_without_rattlers", &S::mean_coordination_without_rattlers,
              "disk-disk contacts of non-rattlers, per non-rattler"),
        field("interior_disks", &S::interior_disks, "disks wholly in the interior"),
        field("interior_coordination", &S::interior_coordination, "their mean number of disk-disk contacts"),
        field("band_disks", &S::band_disks, "disks closer than band_width / 2 to the boundary"),
        field("band_median_area", &S::band_median_area, "median radius by area of the band disks (0: none)")
            .json("band_median_by_area"),
        field("inside_median_area", &S::inside_median_area, "the same for the other disks")
            .json("inside_median_by_area"),
        field("segregation_ks_area", &S::segregation_ks_area,
              "two-sample KS distance by area, band disks against the others")
            .json("segregation_ks_by_area")};
  }
  static constexpr auto void_fields() {
    using S = PackingStats;
    return std::tuple{
        field("largest_empty_circle", &S::largest_empty_circle, "the largest disk that fits (EmptyCircle)"),
        field("holes", &S::holes, "one per radius asked, in the order asked"),
        field("coverage_unit", &S::coverage_unit, "the unit of the profile's bins: rmax"),
        field("coverage_profile", &S::coverage_profile,
              "[k, k + 1) coverage_unit for k = 0..5, then [6, inf): the coverage by distance from the boundary"),
        field("cell_coverage", &S::cell_coverage, "the coverage of interior cells (CellCoverage)"),
        field("sizes", &S::sizes, "the radii achieved, against the request (SizeStats)").json("radius")};
  }
  static constexpr auto fields() { return std::tuple_cat(overall_fields(), contact_fields(), void_fields()); }
};

/// Measures a packing. Disks must have finite centres and finite radii > 0 (else
/// std::invalid_argument naming the disk). Deterministic: the same input gives the same output.
[[nodiscard]] PackingStats measure(const Domain& domain, std::span<const Disk> disks, const StatsOptions& options = {});

/// Size statistics of radii alone, against an optional request (nullptr: none).
[[nodiscard]] SizeStats measure_sizes(std::span<const double> radii, const RadiusDistribution* requested,
                                      std::size_t histogram_bins = 20);

}  // namespace frontpack
