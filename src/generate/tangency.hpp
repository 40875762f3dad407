// Tangent positions (Sec. 2.1, Sec. 3): where a new disk touches the elements of a front segment.
// Header-only and CGAL-free: every candidate is computed here.
#pragma once

#include <cmath>
#include <limits>

#include "generate/scale.hpp"

namespace frontpack::detail {

/// The centre (px, py) of a disk touching two disks from outside: at distance ra from (ax, ay) and
/// rb from (bx, by) (their radii plus the new one's, and the clearance), on the left of a -> b if
/// `left`, else on the right. False if there is none (the disks are too far apart or one holds
/// the other), or if the centres coincide. The lengths are taken at `scale` (see LengthScale).
inline bool tangent_to_two(double ax, double ay, double ra, double bx, double by, double rb, bool left,
                           const LengthScale& scale, double& px, double& py) noexcept {
  const double dx = (bx - ax) * scale.k;
  const double dy = (by - ay) * scale.k;
  ra *= scale.k;
  rb *= scale.k;
  const double d2 = dx * dx + dy * dy;
  if (!(d2 > 0)) {
    return false;
  }
  // With q = ra^2 - rb^2 + d2 (2 d times the distance from a to the chord) and
  // H = 4 ra^2 d2 - q^2 (2 d times the half-chord, squared), the centre is
  // a + (q (dx, dy) +- sqrt(H) (-dy, dx)) / (2 d2): one square root and one division, independent
  // of each other, where normalising first takes two square roots in a row.
  const double q = ra * ra - rb * rb + d2;
  const double big_h = 4 * ra * ra * d2 - q * q;
  if (!(big_h >= 0 && big_h <= std::numeric_limits<double>::max())) {
    return false;
  }
  const double s = left ? std::sqrt(big_h) : -std::sqrt(big_h);
  const double f = 0.5 / d2 * scale.inv_k;
  px = ax + (q * dx - s * dy) * f;
  py = ay + (q * dy + s * dx) * f;
  return true;
}

}  // namespace frontpack::detail
