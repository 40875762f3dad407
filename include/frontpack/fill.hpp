// frontpack: filling a domain with disks (Feng, Han & Owen 2003), certified exactly.
//
//   const auto domain = frontpack::Domain::from_wkt_file("shapes/l_shape.wkt");
//   frontpack::FillOptions options;
//   options.radii = frontpack::Radii::uniform(0.01, 0.05);
//   const frontpack::Packing packing = frontpack::fill(domain, options);
//
// Guarantee (for every accepted domain and options): no two disks of packing.disks overlap and
// every disk lies in the closed domain, both decided exactly on the returned doubles by the
// certifier (certify(), frontpack/certify.hpp), whose report is packing.certificate. Touching is allowed.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <stop_token>
#include <tuple>
#include <vector>

#include "frontpack/budget.hpp"
#include "frontpack/certify.hpp"
#include "frontpack/domain.hpp"
#include "frontpack/errors.hpp"
#include "frontpack/fields.hpp"
#include "frontpack/geometry.hpp"
#include "frontpack/method.hpp"
#include "frontpack/sizes.hpp"

namespace frontpack {

/// FillOptions{}.radii written as a radius spec (parse_radii()): what `frontpack fill` draws
/// when given no --radius.
inline constexpr const char* default_radius_spec = "uniform:0.01,0.05";

/// The defaults are the tool's: `frontpack fill DOMAIN` runs fill(domain, FillOptions{}). Each
/// field but `stop` is described once (name, kind, range, help) in frontpack/options.hpp, from
/// which the tool's flags and Python's keywords are made; check_options() there checks them all,
/// and fill() calls it.
struct FillOptions {
  Method method = Method::boundary;
  Radii radii = Radii::uniform(0.01, 0.05);
  std::uint64_t seed = 0;
  /// Front check window M (Sec. 2.4.3): how many front disks are examined before and after the
  /// active segment to decide cases (b)-(d); 0 means the whole front. Overlaps with any other
  /// disk are still found (by a grid over all placed disks) and never emitted.
  std::size_t window = 5;
  /// Closed form: where the first three disks are placed (default: the centre of each
  /// polygon's bounding box). Only with the closed form and a domain of one polygon, inside the
  /// cell if periodic (else OptionError).
  std::optional<Point> start;
  /// Tangent disks are placed at centre distance r1 + r2 + clearance. 0 (the default) means
  /// automatic: 64 * 2^-52 * (largest |coordinate| + 5 rmax), a few ulps of the coordinates, so
  /// that rounding never makes tangent disks overlap (docs/robustness.md); about 2e-14 for a
  /// unit domain. A value you give must be at least 16 * 2^-52 * (largest |coordinate| + 5 rmax)
  /// (else OptionError); give the same value to make two runs comparable (e.g. translated domains).
  double clearance = 0;
  /// Void filling (all methods): the voids the front leaves behind (the segments its cases
  /// (b)-(d) cut off; for the boundary method also the cusps behind each disk) are kept, and each
  /// new disk is tried there first, before the front. Every drawn radius is still placed (the
  /// boundary method skips at most 1% at the very end: FillStats::skipped_radii), so the size
  /// distribution is unchanged. false gives the paper's forms as published; the boundary method
  /// refuses it (OptionError): its voids are part of the method, and without them it left large
  /// empty areas.
  bool fill_voids = true;
  /// Refuse requests whose estimated disk count exceeds this (LimitError), and stop a run that
  /// reaches it (Packing::truncated); 0: no count limit. With memory_limit, the fill's Budget
  /// (frontpack/budget.hpp).
  std::size_t max_disks = Budget{}.max_count;
  /// The memory a run may take, in bytes, so that it is never killed by the operating system
  /// half-way: a request whose estimated disks take more (peak_bytes_per_disk each) is refused up
  /// front, and a run whose grids plus peak_bytes_per_disk per disk generated so far would take
  /// more stops there; both with LimitError. (The estimate assumes a dense packing of the
  /// polygons' boxes; the closed and open forms also generate disks that overhang a box and are
  /// culled, up to 1.7 times the estimate on a box thinner than the disks.) 0 (the default) means
  /// three quarters of the machine's physical memory.
  std::size_t memory_limit = 0;
  /// Once a stop is requested (from another thread, or a signal-handling thread), the run throws
  /// CancelledError within milliseconds, in generation or in certification, and returns nothing.
  std::stop_token stop{};
  /// A target packing fraction F in (0, 1) (total disk area / Domain::area(), as measure()
  /// reports it; of the part below `height` when that is set); none: as dense as the method fills.
  /// The result's fraction is F within 0.002 (Packing::target), its radii are the drawn radii of
  /// `radii` exactly (the size distribution is the request's, as in a dense fill), and it is
  /// certified as every fill. How (docs/fraction.md): a first fill with `radii` measures the
  /// method's dense fraction for this domain and distribution; a second fills with every drawn
  /// radius scaled up by s > 1, each disk then shrunk about its centre back to its drawn radius
  /// (which keeps every disk inside and every pair apart, exactly), and the disks whose
  /// neighbourhoods are densest are removed until the fraction is F. The packing has no contacts:
  /// every disk has a gap around it (a DEM compression brings them into contact). F above the dense
  /// fraction: OptionError naming the fraction reached and the distribution. Costs two or three
  /// fills. Deterministic for a seed.
  std::optional<double> fraction{};
  /// Fill to a count: stop once this many disks are placed (0: no count). The result has exactly
  /// `count` disks unless the domain holds fewer (then the dense fill, Packing::target says so).
  /// The filled region is compact: the open form keeps the `count` disks of a dense fill whose
  /// tops (y + r) are lowest (its front climbs as a ramp, so its first disks would not be level);
  /// the closed form keeps the first `count` disks it placed, a blob grown from its start point. The boundary method
  /// starts on every wall at once, so its first disks line all the walls: it refuses a count (OptionError naming the
  /// forms that take one). Independent of max_disks (a hard limit that truncates), which must not be below it.
  std::size_t count = 0;
  /// Fill to a level: only the part of the domain below y = height (the domain clipped by the
  /// half-plane y <= height, whose new vertices lie on y = height and inside the domain, decided
  /// exactly) is filled; every disk lies in the domain and below the level (y + r <= height).
  /// A level at or below the domain's lowest point: OptionError; at or above its highest point:
  /// the whole domain. A clip that splits a polygon (a U-shape) gives several polygons.
  std::optional<double> height{};
  /// Jam the packing: after the front, disks drawn from `radii` are inserted at random points and
  /// the overlaps relaxed away (FIRE on the harmonic overlap energy, with the walls), round by
  /// round, keeping a round only when no overlap is left, until a round of a few per ten
  /// thousand disks cannot be relaxed (docs/jam.md). Denser where the front is below the jammed
  /// packings of the same radii: bidisperse 1:1.4 from about 0.815 to 0.835-0.839; at wide size
  /// ranges (rmax / rmin 10), where the front is denser than those, little changes. The relaxation
  /// stops once no two disks overlap, so the disks rest a hair apart (up to about 1e-9 rmax) or
  /// loose, not pressed into contact: fewer contacts than the front's. Certified as every fill.
  /// Every method; every domain, periodic cells included; not with `fraction` or `count`
  /// (OptionError). Costs far more than the front: thousands of relaxation steps over all disks
  /// per round. Deterministic for a seed.
  bool jam = false;
};

/// What a fill to a target fraction, count or level achieved (Packing::target).
struct TargetReport {
  double fraction_requested = 0;
  double fraction_achieved = 0;
  double fraction_dense = 0;
  double scale = 1;
  std::size_t removed = 0;
  std::size_t fills = 0;
  std::size_t count_requested = 0;
  std::size_t count_achieved = 0;
  std::optional<double> height{};
  double area_filled = 0;
  std::size_t outside_original = 0;

  static constexpr auto fields() {
    return std::tuple{
        field("fraction_requested", &TargetReport::fraction_requested, "FillOptions::fraction (0: none)"),
        field("fraction_achieved", &TargetReport::fraction_achieved,
              "total disk area / area filled (the clipped area with a height)"),
        field("fraction_dense", &TargetReport::fraction_dense,
              "the method's dense fraction here, measured by the first fill"),
        field("scale", &TargetReport::scale, "s: the radii of the last fill were the drawn radii times s"),
        field("removed", &TargetReport::removed, "disks removed to reach the fraction"),
        field("fills", &TargetReport::fills, "fills run"),
        field("count_requested", &TargetReport::count_requested, "FillOptions::count (0: none)"),
        field("count_achieved", &TargetReport::count_achieved,
              "with a count: the disks placed, below count_requested when the domain holds no more (the method "
              "filled it whole) or max_disks stopped the generators (Packing::truncated)"),
        field("height", &TargetReport::height, "FillOptions::height (none: no level)"),
        field("area_filled", &TargetReport::area_filled, "Domain::area() of the part filled (the clipped domain)"),
        field("outside_original", &TargetReport::outside_original,
              "disks culled against the unclipped domain (0 expected)")};
  }
};

/// The documented bound on fill()'s peak memory per generated disk (measured 42-61 bytes on the
/// 1M-, 10M- and 100M-disk benchmarks, the boundary method the most; docs/performance.md),
/// besides the generators' grids (4 bytes a cell, at most about 16M cells per polygon; the
/// boundary method's lists of the walls near each cell, 4 bytes per (cell, wall) pair) and the
/// domain. FillOptions::memory_limit counts both.
inline constexpr std::size_t peak_bytes_per_disk = 64;

/// The phases of a run, in order.
enum class Phase : std::uint8_t {
  generate,  ///< the advancing front
  certify,   ///< the exact containment and overlap passes
  jam,       ///< FillOptions::jam: rounds of insertion and relaxation (fraction: of the rounds, roughly)
};

/// "generate", "certify" or "jam".
[[nodiscard]] constexpr const char* to_string(Phase phase) noexcept {
  switch (phase) {
    case Phase::generate: return "generate";
    case Phase::certify: return "certify";
    case Phase::jam: return "jam";
  }
  return "unknown";
}

/// Progress of a run, reported through Generator::on_progress.
struct Progress {
  std::size_t disks = 0;
  double fraction = 0.0;
  double area = 0.0;
  Phase phase = Phase::generate;

  static constexpr auto fields() {
    return std::tuple{
        field("disks", &Progress::disks, "disks generated so far"),
        field("fraction", &Progress::fraction,
              "generating: the fraction of the area to fill that is filled, in [0, 1]: the area of the disks "
              "generated so far over the area a dense packing (0.85) covers in the domain (the boundary method) or "
              "in the polygons' boxes (the paper's forms, which fill the boxes and cull); at most 0.99 before the "
              "front is done, then 1. Certifying: 0 as it starts, 1 at the end. Jamming: of the rounds, roughly"),
        field("area", &Progress::area, "the area of the disks generated so far (culled ones included)"),
        field("phase", &Progress::phase,
              "the phase: 'generate' (the advancing front), 'certify' (the exact containment and overlap passes) "
              "or 'jam' (FillOptions::jam: rounds of insertion and relaxation)")};
  }
};

/// Counters of the advancing front and the jam stage (what the algorithm did, for diagnostics),
/// and the stages' wall times.
struct FillStats {
  std::size_t attempts = 0;
  std::size_t cuts = 0;
  std::size_t blocked_segments = 0;
  std::size_t exact_checks = 0;
  std::size_t void_fills = 0;
  std::size_t skipped_radii = 0;
  std::size_t cavities = 0;
  std::size_t jam_rounds = 0;
  std::size_t jam_inserted = 0;
  std::size_t jam_steps = 0;
  double seconds_front = 0;
  double seconds_jam = 0;
  double seconds_cull = 0;
  double seconds_overlap = 0;

  static constexpr auto fields() {
    return std::tuple{
        field("attempts", &FillStats::attempts, "tangent positions computed").in("generation"),
        field("cuts", &FillStats::cuts, "cases (b)-(d)").in("generation"),
        field("blocked_segments", &FillStats::blocked_segments,
              "segments retired because a disk off the window overlapped")
            .in("generation"),
        field("exact_checks", &FillStats::exact_checks, "overlap tests close enough to need the exact predicate")
            .in("generation"),
        field("void_fills", &FillStats::void_fills, "disks placed in voids left behind the front").in("generation"),
        field("skipped_radii", &FillStats::skipped_radii,
              "radii drawn at the end of a boundary run, when the front was done, that fitted none of the voids "
              "left and were not placed (at most 1% of the disks; docs/boundary-method.md)")
            .in("generation"),
        field("cavities", &FillStats::cavities,
              "points of cavities found after a boundary run's front, each given a void (docs/boundary-method.md)")
            .in("generation"),
        field("jam_rounds", &FillStats::jam_rounds, "FillOptions::jam: rounds of insertion and relaxation")
            .json("rounds")
            .in("jam"),
        field("jam_inserted", &FillStats::jam_inserted, "FillOptions::jam: disks inserted by the rounds kept")
            .json("inserted")
            .in("jam"),
        field("jam_steps", &FillStats::jam_steps, "FillOptions::jam: relaxation steps, every round")
            .json("steps")
            .in("jam"),
        field("seconds_front", &FillStats::seconds_front, "wall time of the advancing front (generation)")
            .json("front")
            .in("seconds"),
        field("seconds_jam", &FillStats::seconds_jam, "FillOptions::jam: wall time of the jam stage")
            .json("jam")
            .in("seconds"),
        field("seconds_cull", &FillStats::seconds_cull, "wall time of the exact containment pass")
            .json("cull")
            .in("seconds"),
        field("seconds_overlap", &FillStats::seconds_overlap, "wall time of the global overlap pass")
            .json("overlap_pass")
            .in("seconds")};
  }
};

struct Packing {
  std::vector<Disk> disks;  ///< certified: pairwise non-overlapping, all inside the domain
  Certificate certificate;
  FillStats stats;
  bool truncated = false;  ///< max_disks was reached
  bool cancelled = false;  ///< the progress callback asked to stop
  /// Set when FillOptions::fraction, count or height is.
  std::optional<TargetReport> target{};
};

/// Fills the domain. Throws OptionError, LimitError, NothingFitsError (no disk placed: never an
/// empty packing, unless cancelled by the progress callback), CancelledError (FillOptions::stop).
[[nodiscard]] Packing fill(const Domain& domain, const FillOptions& options);

/// A fill with control: a progress callback (return false to cancel).
class Generator {
 public:
  Generator(Domain domain, FillOptions options);
  /// Called about every 2^14 disks generated, once the front is done (fraction 1), and as the
  /// certification starts and ends (Phase::certify, fraction 0 and 1), and with FillOptions::jam
  /// every 64 relaxation steps and after each round (Phase::jam, after the front's certification
  /// has ended and before the stage's own starts and ends, fraction 0 and 1 again; false ends the
  /// stage, the round under way undone); returning false while
  /// generating cancels the run, which then returns the certified packing of what was generated
  /// so far, with cancelled = true (later return values are ignored). FillOptions::stop instead
  /// cancels the whole run, certification included.
  void on_progress(std::function<bool(const Progress&)> callback);
  [[nodiscard]] Packing run();

 private:
  Domain domain_;
  FillOptions options_;
  std::function<bool(const Progress&)> progress_;
};

}  // namespace frontpack
