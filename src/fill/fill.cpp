// fill(): the orchestration. The limits are checked (limits.hpp), the advancing front fills each
// polygon's bounding box (Sec. 2.4.5; generate/), and the certifier culls and checks the result
// exactly (certify/).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <limits>
#include <span>
#include <string>
#include <vector>

#include "certify/certify.hpp"
#include "common/rng.hpp"
#include "common/stop.hpp"
#include "fill/limits.hpp"
#include "fill/progress_meter.hpp"
#include "frontpack/fill.hpp"
#include "frontpack/options.hpp"
#include "generate/boundary/boundary_front.hpp"
#include "generate/front_report.hpp"
#include "generate/paper_front.hpp"
#include "generate/run_control.hpp"
#include "generate/settings.hpp"
#include "jam/jam.hpp"
#include "targets/targets.hpp"

namespace frontpack {

namespace {

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// What every polygon's generator is asked (its tick is the progress meter's, per polygon).
detail::FrontSettings front_settings(const Domain& domain, const FillOptions& options, const RadiusDistribution& radii,
                                     double clearance, std::size_t generation_cap, std::size_t memory_bytes) {
  detail::FrontSettings req;
  req.method = options.method;
  req.radii = &radii;
  req.window = options.window;
  req.start = options.start;  // check_options(): with a start point, the domain is one polygon
  req.clearance = clearance;
  req.max_disks = std::min(options.max_disks, generation_cap);
  req.memory_limit = memory_bytes;
  req.bytes_per_disk = peak_bytes_per_disk;
  req.fill_voids = options.fill_voids;
  req.periodicity = domain.periodicity();
  req.stop = options.stop;
  return req;
}

// The generators' reports over the polygons: counters summed, a stop in any polygon ends the run.
void add_report(detail::FrontReport& sum, const detail::FrontReport& r) {
  sum.attempts += r.attempts;
  sum.cuts += r.cuts;
  sum.blocked_segments += r.blocked_segments;
  sum.exact_checks += r.exact_checks;
  sum.void_fills += r.void_fills;
  sum.skipped_radii += r.skipped_radii;
  sum.cavities += r.cavities;
  sum.truncated = sum.truncated || r.truncated;
  sum.cancelled = sum.cancelled || r.cancelled;
}

// The generators, one per polygon in order, appending to `raw`; part_end[p] ends polygon p's disks
// there. A run that would take more than its memory throws LimitError.
detail::FrontReport generate(const Domain& domain, const detail::FrontSettings& settings, detail::Rng& rng,
                             detail::ProgressMeter& meter, std::vector<Disk>& raw, std::vector<std::size_t>& part_end) {
  detail::FrontReport sum;
  for (std::size_t p = 0; p < domain.num_polygons() && !sum.truncated && !sum.cancelled; ++p) {
    detail::FrontSettings req = settings;
    req.tick = meter.tick();
    const detail::FrontReport report = settings.method == Method::boundary
                                           ? detail::advance_boundary(req, domain.polygons()[p], rng, raw)
                                           : detail::advance_front(req, domain.bbox(p), rng, raw);
    if (report.over_memory) {
      detail::throw_memory_limit(settings.memory_limit,
                                 "it had generated " + std::to_string(raw.size()) + " disks, " +
                                     std::to_string(settings.bytes_per_disk) + " bytes each at the peak, besides " +
                                     std::to_string(report.fixed_bytes) + " bytes of grids",
                                 raw.size());
    }
    add_report(sum, report);
    meter.polygon_done(std::span<const Disk>(raw).subspan(part_end.empty() ? 0 : part_end.back()));
    part_end.push_back(raw.size());
  }
  return sum;
}

// The public counters of the front (FillStats), from its report.
void record_front(FillStats& stats, const detail::FrontReport& r) {
  stats.attempts = r.attempts;
  stats.cuts = r.cuts;
  stats.blocked_segments = r.blocked_segments;
  stats.exact_checks = r.exact_checks;
  stats.void_fills = r.void_fills;
  stats.skipped_radii = r.skipped_radii;
  stats.cavities = r.cavities;
}

// The jam stage on the front's certified disks, then their second certification, added to the
// packing's certificate and timings. The stage moves certified disks and inserts more; none
// leaves its polygon, so the second certification asks only whether each lies in the domain
// (certify/cull.hpp). Progress: the front's certification ends, the stage runs, and its
// certification starts.
void jam_and_certify(const Domain& domain, const FillOptions& options, const RadiusDistribution& radii,
                     double clearance, detail::Rng& rng, const detail::ProgressMeter& meter, std::vector<Disk>& raw,
                     Packing& packing) {
  meter.finish(raw.size());
  const detail::JamReport jam =
      detail::jam(domain, radii, clearance, options.max_disks, rng, raw, meter.jam_tick(), options.stop);
  packing.cancelled = jam.cancelled;
  packing.stats.jam_rounds = jam.rounds;
  packing.stats.jam_inserted = jam.inserted;
  packing.stats.jam_steps = jam.steps;
  packing.stats.seconds_jam = jam.seconds;
  meter.certifying(raw.size());
  const detail::CertifyResult after = detail::certify_fill(domain, raw, {}, options.stop);
  packing.certificate.generated += jam.inserted;
  packing.certificate.culled += after.certificate.culled;
  packing.certificate.dropped += after.certificate.dropped;
  packing.certificate.candidate_pairs = after.certificate.candidate_pairs;
  packing.stats.seconds_cull += after.seconds_cull;
  packing.stats.seconds_overlap += after.seconds_overlap;
}

// The plain fill: the checks and limits, the generators, the certification, and with
// FillOptions::jam the jam stage and a second certification. The Packing is assembled from the
// stages' reports.
Packing run_plain(const Domain& domain, const FillOptions& options,
                  const std::function<bool(const Progress&)>& progress, std::size_t generation_cap) {
  // Again for each run: a target's runs fill with other options (scaled radii, a clipped domain).
  check_options(domain, options);
  const double clearance = detail::clearance_for(domain, options);
  const RadiusDistribution& radii = options.radii.distribution();
  const detail::RunBudget budget = detail::check_limits(domain, options, radii, generation_cap);

  Packing packing;
  auto t0 = std::chrono::steady_clock::now();
  std::vector<Disk> raw;
  raw.reserve(static_cast<std::size_t>(budget.estimate * 1.2) + 64);
  detail::Rng rng(options.seed);
  std::vector<std::size_t> part_end;  // raw[part_end[p - 1] .. part_end[p]) came from polygon p
  detail::ProgressMeter meter(domain, options.method, progress, options.stop);
  const detail::FrontReport front =
      generate(domain, front_settings(domain, options, radii, clearance, generation_cap, budget.memory_bytes), rng,
               meter, raw, part_end);
  record_front(packing.stats, front);
  packing.truncated = front.truncated;
  packing.cancelled = front.cancelled;

  detail::throw_if_stopped(options.stop);
  packing.stats.seconds_front = seconds_since(t0);
  meter.generated(raw.size());
  const detail::CertifyResult certified = detail::certify_fill(domain, raw, part_end, options.stop);
  packing.certificate = certified.certificate;
  packing.stats.seconds_cull = certified.seconds_cull;
  packing.stats.seconds_overlap = certified.seconds_overlap;
  if (options.jam && !packing.truncated && !packing.cancelled) {
    jam_and_certify(domain, options, radii, clearance, rng, meter, raw, packing);
  }
  packing.disks = std::move(raw);
  meter.finish(packing.certificate.generated);
  return packing;
}

// A fill to a fraction, count or level runs the plain fill (targets/targets.hpp).
Packing run_fill(const Domain& domain, const FillOptions& options,
                 const std::function<bool(const Progress&)>& progress) {
  check_options(domain, options);
  Packing p = !detail::has_target(options)
                  ? run_plain(domain, options, progress, options.max_disks)
                  : detail::fill_with_targets(domain, options,
                                              [&progress](const Domain& d, const FillOptions& o, std::size_t cap) {
                                                return run_plain(d, o, progress, cap);
                                              });
  if (p.target) {
    // A fill to a level culls against the unclipped domain too (targets.hpp): the certificate
    // counts those disks with its own culls.
    p.certificate.culled += p.target->outside_original;
  }
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
