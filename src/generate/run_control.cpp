#include "generate/run_control.hpp"

#include <cmath>
#include <limits>
#include <numbers>
#include <string>

#include "common/packing_density.hpp"
#include "generate/scale.hpp"

namespace frontpack::detail {

double estimate_disks(const Box& box, const RadiusDistribution& radii) {
  // At the estimate's density (common/packing_density.hpp).
  const double mean_square = radii.mean_square();
  const double estimate = kEstimateFraction * box.width() * box.height() / (std::numbers::pi * mean_square);
  if (mean_square >= std::numeric_limits<double>::min() && !std::isnan(estimate)) {
    return estimate;  // E[r^2] normal: the figure is accurate (or 0, or saturated to infinity)
  }
  // E[r^2] underflows (radii below about 1e-154; 0 / 0 for a box as small) or is not a number:
  // the same figure at the scale of rmax (a power of two: exact), with E[(k r)^2] from the
  // quantiles at 1024 midpoints, since mean_square() has lost it.
  const LengthScale scale(radii.max());
  double sum = 0;
  constexpr int kPoints = 1024;
  for (int i = 0; i < kPoints; ++i) {
    const double r = scale.k * radii.quantile((i + 0.5) / kPoints);
    sum += r * r;
  }
  const double scaled_mean_square = sum / kPoints;
  if (!(scaled_mean_square > 0)) {
    return std::numeric_limits<double>::infinity();  // radii too small to square even at their scale
  }
  const double scaled =
      kEstimateFraction * (box.width() * scale.k) * (box.height() * scale.k) / (std::numbers::pi * scaled_mean_square);
  return std::isnan(scaled) ? std::numeric_limits<double>::infinity() : scaled;
}

double bound_disks(const Box& box, double grow, const RadiusDistribution& radii) {
  const Box grown{box.xmin - grow, box.ymin - grow, box.xmax + grow, box.ymax + grow};
  return estimate_disks(grown, radii) / kEstimateFraction;
}

void throw_memory_limit(std::size_t limit, const std::string& what, std::size_t estimate) {
  throw LimitError("the run would need more than the memory limit of " + std::to_string(limit) + " bytes: " + what +
                       "; raise memory_limit (--memory-limit) or use larger radii",
                   estimate);
}

}  // namespace frontpack::detail
