// The fill to a target fraction (targets.hpp, docs/fraction.md): a dense fill measures what the
// method reaches; a fill with the radii scaled up by s, each disk shrunk back to its drawn radius,
// is looser by 1 / s^2; the densest neighbourhoods are thinned to the fraction asked.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "common/format.hpp"
#include "frontpack/certify.hpp"
#include "targets/scaled_radii.hpp"
#include "targets/targets.hpp"
#include "targets/thinning.hpp"

namespace frontpack::detail {

namespace {

// The tolerance promised (FillOptions::fraction) and the band the thinning aims at inside it.
constexpr double kTolerance = 0.002;
constexpr double kAimBelow = 0.0015;
// The loose fill's excess over F before thinning: enough that the looser fill's own scatter
// (its fraction is phi / s^2 within a few thousandths) still leaves something to thin, small
// enough that the thinning removes a disk here and there (each removal adds to the scatter of
// the local density what it takes from the mean).
constexpr double kExcess = 0.008;

}  // namespace

Packing fill_to_fraction(const Domain& domain, const FillOptions& options, const PlainFill& plain) {
  const double f = *options.fraction;
  const double area = domain.area();
  FillOptions o = options;
  o.fraction.reset();
  TargetReport t;
  t.fraction_requested = f;
  t.area_filled = area;

  Packing dense = plain(domain, o, o.max_disks);
  t.fills = 1;
  const double phi = disk_area(dense.disks) / area;
  t.fraction_dense = phi;
  if (dense.truncated || dense.cancelled) {
    // Stopped by max_disks or the caller: what it has, as it is (Packing::truncated, cancelled).
    t.fraction_achieved = phi;
    dense.target = t;
    return dense;
  }
  if (phi < f - kTolerance) {
    throw OptionError("fraction " + format_double(f) + ": the " + to_string(o.method) + " method reaches " +
                      format_double(std::round(phi * 1e4) / 1e4) + " for " + o.radii.describe() +
                      " in this domain (measured by its fill with seed " + std::to_string(o.seed) +
                      "); ask for at most that, or for a wider size distribution (denser)");
  }
  double before = f * (1 + kExcess);

  Packing loose;
  double s = 1;
  const RadiusDistribution& base = o.radii.distribution();
  for (int attempt = 0; attempt < 3 && before < phi; ++attempt) {
    s = std::sqrt(phi / before);
    FillOptions scaled = o;
    scaled.radii = scaled_radii(o.radii, s);
    loose = plain(domain, scaled, o.max_disks);
    ++t.fills;
    for (Disk& d : loose.disks) {
      d.radius = unscaled_radius(base, s, d.radius);
    }
    const double got = disk_area(loose.disks) / area;
    if (got >= f || loose.truncated || loose.cancelled) {
      break;
    }
    // Short of F (the looser fill's fraction differs a little from phi / s^2): less loose.
    before *= (f * (1 + kExcess)) / got;
    s = 1;
  }
  if (s == 1) {
    loose = std::move(dense);  // the dense fill itself, thinned
  }
  t.scale = s;
  const double rmax = o.radii.max();
  t.removed = thin_to_area(domain, loose.disks, (f + kTolerance - kAimBelow) * area,
                           (2 * kTolerance - kAimBelow) * area, 4 * rmax);
  // Shrunk disks lie in the certified placed ones; the certificate is checked again regardless.
  const CertifyReport check = certify(domain, loose.disks, o.stop);
  if (!check.outside.empty() || !check.overlapping.empty()) {
    throw Error("fill to a fraction: the shrunk packing failed its certificate (a defect: please report it)");
  }
  t.fraction_achieved = disk_area(loose.disks) / area;
  loose.target = t;
  return loose;
}

}  // namespace frontpack::detail
