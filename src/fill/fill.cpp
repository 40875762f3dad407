// fill(): the orchestration. The limits are checked (limits.hpp), the advancing front fills each
// polygon's bounding box (Sec. 2.4.5; generate/), and the certifier culls and checks the result
// exactly (certify/).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <string>

#include "certify/certify.hpp"
#include "common/format.hpp"
#include "common/rng.hpp"
#include "common/stop.hpp"
#include "fill/limits.hpp"
#include "fill/progress_meter.hpp"
#include "frontpack/fill.hpp"
#include "generate/boundary/boundary_front.hpp"
#include "generate/paper_front.hpp"
#include "generate/run_control.hpp"
#include "generate/settings.hpp"
#include "jam/jam.hpp"
#include "targets/targets.hpp"

namespace frontpack {

namespace {

// A periodic cell: the boundary method and the closed form wrap around it (the open form, which
// grows from the bottom of a box with walls, does not).
void check_periodic(const Domain& domain, const FillOptions& o, double clearance) {
  if (domain.periodicity() == Periodicity::none) {
    return;
  }
  if (o.method == Method::open) {
    throw OptionError(
        "a periodic cell is filled by the boundary method or the closed form; the open form does not wrap around a "
        "cell");
  }
  // Each front segment and each disk's reach are a few times the larger of rmax and the clearance
  // (tangent disks are placed the clearance apart): at 10 times it their images are far enough
  // apart that the nearest image is the one meant (generate/periodic_wrap.hpp). The clearance is a
  // few ulps of the coordinates, so it is the larger only for a cell far from the origin against
  // its size (at 1.4e10 it is 2e-4: a cell a few ulps across had a tangent disk placed many periods
  // away, and the nearest image made it overlap its neighbours).
  const Box cell = domain.bbox();
  const bool precision = clearance > o.radii.max();
  const double least = 10 * std::max(o.radii.max(), clearance);
  const bool narrow =
      cell.xmax - cell.xmin < least || (domain.periodicity() == Periodicity::xy && cell.ymax - cell.ymin < least);
  if (narrow) {
    const std::string size =
        detail::format_double(cell.xmax - cell.xmin) + " x " + detail::format_double(cell.ymax - cell.ymin);
    if (!precision) {
      throw OptionError("a periodic cell must be at least 10 rmax = " + detail::format_double(least) +
                        " across each periodic direction; it is " + size);
    }
    throw OptionError(
        "a periodic cell must be at least 10 times the clearance that keeps tangent disks apart "
        "exactly at its coordinates (largest |coordinate| " +
        detail::format_double(domain.max_abs_coordinate()) + ": clearance " + detail::format_double(clearance) +
        ", larger than rmax), " + detail::format_double(least) + ", across each periodic direction; it is " + size +
        ": move the cell near the origin, by whole periods");
  }
  if (o.start &&
      (o.start->x < cell.xmin || o.start->x >= cell.xmax || o.start->y < cell.ymin || o.start->y >= cell.ymax)) {
    throw OptionError("the start point must lie in the periodic cell");
  }
}

void check_options(const FillOptions& o) {
  (void)o.radii.distribution();  // throws if empty
  if (o.start && (!std::isfinite(o.start->x) || !std::isfinite(o.start->y))) {
    throw OptionError("start point must be finite");
  }
  if (o.method == Method::boundary && !o.fill_voids) {
    // Its voids are half of the method: without them every gap that a drawn radius does not fit
    // is dropped, and the packing keeps large empty areas (packing fraction 0.63-0.65).
    throw OptionError(
        "fill_voids = false gives the paper's forms as published (methods closed and open); the "
        "boundary method keeps its voids always (without them it leaves large empty areas)");
  }
}

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

Packing run_plain(const Domain& domain, const FillOptions& options,
                  const std::function<bool(const Progress&)>& progress, std::size_t generation_cap) {
  check_options(options);
  const double clearance = detail::clearance_for(domain, options);
  check_periodic(domain, options, clearance);
  const RadiusDistribution& radii = options.radii.distribution();
  const detail::RunBudget budget = detail::check_limits(domain, options, radii, generation_cap);
  const std::size_t memory_bytes = budget.memory_bytes;

  Packing packing;
  auto t0 = std::chrono::steady_clock::now();
  std::vector<Disk> raw;
  raw.reserve(static_cast<std::size_t>(budget.estimate * 1.2) + 64);
  detail::Rng rng(options.seed);
  std::vector<std::size_t> part_end;  // raw[part_end[p - 1] .. part_end[p]) came from polygon p
  detail::ProgressMeter meter(domain, options.method, progress, options.stop);
  for (std::size_t p = 0; p < domain.num_polygons() && !packing.truncated && !packing.cancelled; ++p) {
    detail::FrontSettings req;
    req.method = options.method;
    req.radii = &radii;
    req.window = options.window;
    if (options.start && domain.num_polygons() == 1) {
      req.start = options.start;
    }
    req.clearance = clearance;
    req.max_disks = std::min(options.max_disks, generation_cap);
    req.memory_limit = memory_bytes;
    req.fill_voids = options.fill_voids;
    req.periodicity = domain.periodicity();
    req.tick = meter.tick();
    req.stop = options.stop;
    detail::FrontResult result;
    if (options.method == Method::boundary) {
      result = detail::advance_boundary(req, domain.polygons()[p], rng, raw, packing.stats);
    } else {
      result = detail::advance_front(req, domain.bbox(p), rng, raw, packing.stats);
    }
    if (result.over_memory) {
      detail::throw_memory_limit(memory_bytes,
                                 "it had generated " + std::to_string(raw.size()) + " disks, " +
                                     std::to_string(peak_bytes_per_disk) + " bytes each at the peak, besides " +
                                     std::to_string(result.fixed_bytes) + " bytes of grids",
                                 raw.size());
    }
    packing.truncated = packing.truncated || result.truncated;
    packing.cancelled = packing.cancelled || result.cancelled;
    meter.polygon_done(std::span<const Disk>(raw).subspan(part_end.empty() ? 0 : part_end.back()));
    part_end.push_back(raw.size());
  }

  detail::throw_if_stopped(options.stop);
  packing.stats.seconds_front = seconds_since(t0);
  meter.generated(raw.size());
  packing.certificate = detail::certify_fill(domain, raw, part_end, options.stop, packing.stats);
  if (options.jam && !packing.truncated && !packing.cancelled) {
    // The jam stage moves certified disks and inserts more; none leaves its polygon, so the
    // second certification asks only whether each lies in the domain (certify/cull.hpp).
    // Progress: the front's certification ends, the stage runs, and its certification starts.
    meter.finish(raw.size());
    packing.cancelled = !detail::jam(domain, radii, clearance, options.max_disks, rng, raw, meter.jam_tick(),
                                     options.stop, packing.stats);
    meter.certifying(raw.size());
    FillStats second = packing.stats;
    const Certificate after = detail::certify_fill(domain, raw, {}, options.stop, second);
    packing.certificate.generated += packing.stats.jam_inserted;
    packing.certificate.culled += after.culled;
    packing.certificate.dropped += after.dropped;
    packing.certificate.candidate_pairs = after.candidate_pairs;
    packing.stats.seconds_cull += second.seconds_cull;
    packing.stats.seconds_overlap += second.seconds_overlap;
  }
  packing.disks = std::move(raw);
  meter.finish(packing.certificate.generated);
  return packing;
}

// A fill to a fraction, count or level runs the plain fill (target/targets.hpp).
Packing run_fill(const Domain& domain, const FillOptions& options,
                 const std::function<bool(const Progress&)>& progress) {
  Packing p = !detail::has_target(options)
                  ? run_plain(domain, options, progress, options.max_disks)
                  : detail::fill_with_targets(domain, options,
                                              [&progress](const Domain& d, const FillOptions& o, std::size_t cap) {
                                                return run_plain(d, o, progress, cap);
                                              });
  if (p.disks.empty() && !p.cancelled) {
    detail::throw_nothing_fits(domain, options, p);
  }
  return p;
}

}  // namespace

Packing fill(const Domain& domain, const FillOptions& options) {
  return run_fill(domain, options, {});
}

Generator::Generator(Domain domain, FillOptions options) : domain_(std::move(domain)), options_(std::move(options)) {}

void Generator::on_progress(std::function<bool(const Progress&)> callback) {
  progress_ = std::move(callback);
}

Packing Generator::run() {
  return run_fill(domain_, options_, progress_);
}

}  // namespace frontpack
