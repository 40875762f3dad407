// Tangent positions (Sec. 2.1, Sec. 3): where a new disk touches the two elements of a front
// segment, disks or walls (the open form's walls, Sec. 3, are disks of infinite radius: lines; the
// boundary front's are the domain's edges). Distances include the clearance: the callers pass
// radii grown by it, and `gap` = the new radius + the clearance. Header-only and CGAL-free: every
// candidate is computed here, by both fronts.
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

/// The centre (px, py) of a disk touching a disk (x, y, r) and a wall's line, both at `gap` (the
/// new radius plus the clearance): on the line {p : n . p = w + gap} (n = (nx, ny), the wall's
/// unit inward normal; the domain side has n . p >= w), at distance r + gap from (x, y); of the
/// two such points, the one at +s along the unit direction (tx, ty) if `forward`, else at -s.
/// `on_line`: the disk's centre lies on the wall's line (a reflex vertex at the wall's end, radius
/// 0), so the new disk touches the wall there and s is 0 (computed, rounding made s^2 negative
/// about half the time). False if the disk is too far from the line.
template <class Line>
inline bool tangent_to_disk_and_wall(double x, double y, double r, const Line& wall, double tx, double ty, double gap,
                                     bool forward, bool on_line, double& px, double& py) noexcept {
  const double a = r + gap;
  const double off = wall.nx * x + wall.ny * y - (wall.w + gap);  // signed distance to the line
  const double s2 = on_line ? 0 : a * a - off * off;
  if (!(s2 >= 0)) {
    return false;
  }
  const double s = forward ? std::sqrt(s2) : -std::sqrt(s2);
  px = x - off * wall.nx + s * tx;
  py = y - off * wall.ny + s * ty;
  return true;
}

/// The centre (px, py) of a disk in the corner of two walls (Sec. 3: D1 in the corner of Bl and
/// Bb): where their lines, moved in by `gap`, cross. False if they are parallel (or the crossing
/// is not finite). `Line` has the unit inward normal (nx, ny) and the offset w = n . (a point on
/// the line).
template <class Line>
inline bool tangent_to_two_walls(const Line& wa, const Line& wb, double gap, double& px, double& py) noexcept {
  const double det = wa.nx * wb.ny - wa.ny * wb.nx;
  if (!(std::abs(det) > 1e-9)) {
    return false;  // parallel
  }
  const double ca = wa.w + gap;
  const double cb = wb.w + gap;
  px = (ca * wb.ny - cb * wa.ny) / det;
  py = (wa.nx * cb - wb.nx * ca) / det;
  return std::isfinite(px) && std::isfinite(py);
}

}  // namespace frontpack::detail
