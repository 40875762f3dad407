// The targets' dispatch and the fill to a level (targets.hpp).
#include "targets/targets.hpp"

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "domain/level_clip.hpp"
#include "frontpack/certify.hpp"

namespace frontpack::detail {

namespace {

// Whether y + r <= level, exactly: the sum's rounding error (two-sum, exact) settles a tie.
bool below_level(const Disk& d, double level) {
  const double s = d.centre.y + d.radius;
  const double bb = s - d.centre.y;
  const double e = (d.centre.y - (s - bb)) + (d.radius - bb);
  return s < level || (s == level && e <= 0);
}

}  // namespace

double disk_area(const std::vector<Disk>& disks) {
  double a = 0;
  for (const Disk& d : disks) {
    a += std::numbers::pi * d.radius * d.radius;
  }
  return a;
}

bool has_target(const FillOptions& options) noexcept {
  return options.fraction.has_value() || options.count > 0 || options.height.has_value();
}

Packing fill_with_targets(const Domain& domain, const FillOptions& options, const PlainFill& plain) {
  if (options.height) {
    const Domain part = clip_below(domain, *options.height);
    FillOptions inner = options;
    inner.height.reset();
    Packing p = has_target(inner) ? fill_with_targets(part, inner, plain) : plain(part, inner, inner.max_disks);
    // The clip lies in the domain up to rounding slivers: certify against the domain itself too,
    // and keep only what it holds and what lies below the level.
    const CertifyReport report = certify(domain, p.disks, options.stop);
    std::vector<std::uint8_t> drop(p.disks.size(), 0);
    for (const std::size_t i : report.outside) {
      drop[i] = 1;
    }
    std::size_t kept = 0;
    for (std::size_t i = 0; i < p.disks.size(); ++i) {
      const Disk& d = p.disks[i];
      if (drop[i] == 0 && below_level(d, *options.height)) {
        p.disks[kept++] = d;
      }
    }
    const std::size_t outside = p.disks.size() - kept;
    p.disks.resize(kept);
    TargetReport t = p.target.value_or(TargetReport{});
    t.height = *options.height;
    t.area_filled = part.area();
    t.outside_original = outside;
    t.fraction_achieved = disk_area(p.disks) / part.area();
    t.fills = t.fills == 0 ? 1 : t.fills;
    p.target = t;
    return p;
  }
  if (options.fraction) {
    return fill_to_fraction(domain, options, plain);
  }
  return fill_to_count(domain, options, plain);
}

}  // namespace frontpack::detail
