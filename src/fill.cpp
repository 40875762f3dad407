// fill(): the advancing front over each polygon's bounding box (Sec. 2.4.5), then certification:
// exact culling against the domain and the global overlap pass.
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <numbers>
#include <string>

#include "generate/boundary/boundary_front.hpp"
#include "certify/certify.hpp"
#include "common/format.hpp"
#include "generate/paper_front.hpp"
#include "generate/run_control.hpp"
#include "generate/settings.hpp"
#include "frontpack/fill.hpp"
#include "common/rng.hpp"
#include "common/stop.hpp"

namespace frontpack {

namespace {

// The clearance: a few ulps of the largest coordinate any disk centre can have (the domain's,
// plus the margin by which generated disks overhang the filled box), so that neither the
// floating-point tangency nor the rounding of the output (box corner + local position) can make
// tangent disks overlap. docs/robustness.md, "Clearance".
double clearance_for(const Domain& domain, const FillOptions& o) {
  // (At most the largest double: radii beyond about 3.6e307 made it infinite.)
  const double scale = std::min(domain.max_abs_coordinate() + 5 * o.radii.max(), std::numeric_limits<double>::max());
  if (!(scale >= std::numeric_limits<double>::min())) {
    // Every coordinate and radius subnormal: a clearance of a few ulps underflows to 0.
    throw OptionError("the domain and the radii are too small: their size (largest |coordinate| + 5 rmax = " +
                      detail::format_double(scale) +
                      ") must be at least 2.2250738585072014e-308, the smallest normal double, for a clearance of a "
                      "few ulps to separate tangent disks; scale the domain up (by a power of two, which is exact)");
  }
  const double minimum = 16 * 0x1p-52 * scale;
  if (o.clearance == 0) {
    return 4 * minimum;
  }
  if (!std::isfinite(o.clearance) || o.clearance < minimum) {
    throw OptionError("clearance must be 0 (automatic) or a finite number >= " + detail::format_double(minimum) +
                      " for this domain and radius range, got " + detail::format_double(o.clearance));
  }
  return o.clearance;
}

void check_options(const FillOptions& o) {
  (void)o.radii.distribution();  // throws if empty
  if (o.start && (!std::isfinite(o.start->x) || !std::isfinite(o.start->y))) {
    throw OptionError("start point must be finite");
  }
}

// Keeps the disks whose flag equals `keep`, in order, in place (no second copy of the disks).
void keep_where(std::vector<Disk>& disks, const std::vector<std::uint8_t>& flag, std::uint8_t keep) {
  std::size_t kept = 0;
  for (std::size_t i = 0; i < disks.size(); ++i) {
    if (flag[i] == keep) {
      disks[kept++] = disks[i];
    }
  }
  disks.resize(kept);
}

// Physical memory in bytes, or 0 if the system does not say.
double physical_memory() {
  const long pages = ::sysconf(_SC_PHYS_PAGES);
  const long page = ::sysconf(_SC_PAGESIZE);
  return pages > 0 && page > 0 ? static_cast<double>(pages) * static_cast<double>(page) : 0;
}

// Bytes as a count (at most the largest size_t).
std::size_t count_of_bytes(double bytes) {
  return bytes < 0x1p63 ? static_cast<std::size_t>(bytes) : std::size_t{1} << 63;
}

// A count for a message: an integer below 1e15, else in scientific notation.
std::string format_count(double v) {
  if (v < 1e15) {
    return std::to_string(static_cast<std::uint64_t>(v));
  }
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g", v);
  return buf;
}

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

Packing run_fill(const Domain& domain, const FillOptions& options,
                 const std::function<bool(const Progress&)>& progress) {
  check_options(options);
  const RadiusDistribution& radii = options.radii.distribution();
  const double clearance = clearance_for(domain, options);
  double estimate = 0;
  for (std::size_t p = 0; p < domain.num_polygons(); ++p) {
    estimate += detail::estimate_disks(domain.bbox(p), radii);
  }
  // Saturated: an estimate can exceed every integer (1e600 disks for radii of 1e-300).
  const std::size_t count = estimate >= 0 && estimate < 0x1p63 ? static_cast<std::size_t>(estimate)
                                                                : std::numeric_limits<std::size_t>::max();
  // Written so that a NaN fails the checks (estimate_disks() gives none; a check must not rely on it).
  if (!(estimate <= static_cast<double>(options.max_disks))) {
    throw LimitError("the request would generate about " + format_count(estimate) + " disks, more than max_disks = " +
                         std::to_string(options.max_disks) +
                         "; use larger radii or raise max_disks (frontpack fill --max-disks)",
                     count);
  }
  const double memory_limit =
      options.memory_limit != 0 ? static_cast<double>(options.memory_limit) : 0.75 * physical_memory();
  const double memory = estimate * static_cast<double>(peak_bytes_per_disk);
  if (memory_limit > 0 && !(memory <= memory_limit)) {
    throw LimitError("the request would generate about " + format_count(estimate) + " disks, needing about " +
                         format_count(memory) + " bytes of memory, more than the limit of " +
                         format_count(memory_limit) +
                         " bytes; use larger radii or raise memory_limit (frontpack fill --memory-limit)",
                     count);
  }
  // The limit holds during the run too (the estimate is only an estimate: a box far thinner than
  // the disks makes more than it says): the generators count their grids against it and stop
  // their disks short of it, peak_bytes_per_disk each (FrontResult::over_memory, a LimitError).
  const std::size_t memory_bytes = memory_limit >= 1 ? count_of_bytes(memory_limit) : 0;

  Packing packing;
  auto t0 = std::chrono::steady_clock::now();
  std::vector<Disk> raw;
  raw.reserve(static_cast<std::size_t>(estimate * 1.2) + 64);
  detail::Rng rng(options.seed);
  std::vector<std::size_t> part_end;  // raw[part_end[p - 1] .. part_end[p]) came from polygon p
  double to_cover = 0;                // for progress: the area the front is expected to cover
  for (std::size_t p = 0; p < domain.num_polygons(); ++p) {
    to_cover += 0.85 * domain.bbox(p).width() * domain.bbox(p).height();
  }
  double covered_before = 0;  // by the disks of the polygons done
  for (std::size_t p = 0; p < domain.num_polygons() && !packing.truncated && !packing.cancelled; ++p) {
    detail::FrontSettings req;
    req.method = options.method;
    req.radii = &radii;
    req.window = options.window;
    if (options.start && domain.num_polygons() == 1) {
      req.start = options.start;
    }
    req.clearance = clearance;
    req.max_disks = options.max_disks;
    req.memory_limit = memory_bytes;
    req.fill_voids = options.fill_voids;
    const std::stop_token& stop = options.stop;
    if (progress || stop.stop_possible()) {
      // The fraction of the area to cover that is covered: a random dense packing covers about
      // 0.85 of each box (the estimate's density), so this reaches about 1 at the end.
      req.tick = [&](std::size_t total, double r2) {
        if (stop.stop_requested()) {
          return false;
        }
        if (!progress) {
          return true;
        }
        const double covered = covered_before + std::numbers::pi * r2;
        return progress(Progress{total, std::min(0.99, covered / std::max(to_cover, 1e-300)), covered});
      };
    }
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
    for (std::size_t i = part_end.empty() ? 0 : part_end.back(); i < raw.size(); ++i) {
      covered_before += std::numbers::pi * raw[i].radius * raw[i].radius;
    }
    part_end.push_back(raw.size());
  }

  detail::throw_if_stopped(options.stop);
  packing.stats.seconds_front = seconds_since(t0);
  t0 = std::chrono::steady_clock::now();

  // Certification. Sec. 2.4.5: disks not entirely inside the domain are culled (exactly).
  packing.certificate.generated = raw.size();
  // Each polygon's disks must lie in that polygon, not merely in the domain: the boxes of two
  // polygons can overlap, and a disk of one polygon's fill inside the other would overlap that
  // polygon's own disks. (A disk inside the domain lies in exactly one polygon: polygons meet at
  // most at points, and a disk minus a point is connected.)
  {
    std::vector<std::uint8_t> inside(raw.size());
    if (domain.num_polygons() == 1) {
      detail::contains(domain, raw, inside, options.stop);
    } else {
      std::size_t begin = 0;
      for (std::size_t p = 0; p < part_end.size(); ++p) {
        const std::size_t n = part_end[p] - begin;
        if (n > 0) {
          const Domain part = Domain::from_polygons({domain.polygons()[p]});
          detail::contains(part, std::span<const Disk>(raw).subspan(begin, n),
                           std::span<std::uint8_t>(inside).subspan(begin, n), options.stop);
        }
        begin = part_end[p];
      }
    }
    keep_where(raw, inside, 1);
  }
  packing.certificate.culled = packing.certificate.generated - raw.size();
  packing.stats.seconds_cull = seconds_since(t0);
  t0 = std::chrono::steady_clock::now();

  // Sec. 2.4.3's final global search: drop one disk of every overlapping pair (the later one,
  // in the order of the sorted pairs: deterministic). Our generator never produces one.
  std::vector<std::pair<std::size_t, std::size_t>> pairs;
  detail::overlapping_pairs(raw, pairs, packing.certificate.candidate_pairs, options.stop);
  if (!pairs.empty()) {
    std::vector<std::uint8_t> drop(raw.size(), 0);
    for (const auto& [i, j] : pairs) {
      if (drop[i] == 0 && drop[j] == 0) {
        drop[j] = 1;
        ++packing.certificate.dropped;
      }
    }
    keep_where(raw, drop, 0);
  }
  // The capacity reserved beyond the disks generated was never touched and, in a block of its
  // own mapping (above malloc's mmap threshold, at most 32 MiB), costs no memory; a smaller block
  // that malloc recycled may hold touched pages there, at most a fifth of the disks' worth. The
  // culled and dropped disks' places were touched. Give them back only when they are worth a
  // copy (a copy of every disk into memory never touched: 0.2 s of the 10M-disk pipeline's 7 s).
  if (packing.certificate.generated - raw.size() > raw.size() / 8) {
    raw.shrink_to_fit();
  }
  packing.disks = std::move(raw);
  packing.certificate.exact = true;
  packing.stats.seconds_overlap = seconds_since(t0);
  if (progress) {
    (void)progress(Progress{packing.certificate.generated, 1.0, covered_before});
  }
  return packing;
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

const char* to_string(Method method) noexcept {
  switch (method) {
    case Method::closed: return "closed";
    case Method::open: return "open";
    case Method::boundary: return "boundary";
  }
  return "unknown";
}

}  // namespace frontpack
