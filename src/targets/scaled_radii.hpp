// The radii of a fill to a target fraction: the request's radii scaled up by s >= 1, and the way
// back from a placed (scaled) radius to the drawn radius it came from, exactly.
#pragma once

#include <memory>

#include "frontpack/sizes.hpp"

namespace frontpack::detail {

/// The distribution of fl(s * r), r drawn from `base`: the same variates give the same radii of
/// `base`, each scaled by s (a double >= 1).
[[nodiscard]] Radii scaled_radii(const Radii& base, double s);

/// The radius r of `base` that the scaled distribution turned into `placed` = fl(s * r): the
/// class radius for discrete classes and curves' sieve radii, else the largest double r with
/// fl(s * r) == placed near placed / s. Never above `placed` (s >= 1 and rounding is monotone),
/// so the disk shrunk to r stays inside its placed disk.
[[nodiscard]] double unscaled_radius(const RadiusDistribution& base, double s, double placed);

}  // namespace frontpack::detail
