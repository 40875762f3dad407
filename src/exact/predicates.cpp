#include "exact/predicates.hpp"

#include <algorithm>
#include <cmath>

namespace frontpack::detail {

namespace {

template <class NT>
CGAL::Uncertain<CGAL::Comparison_result> distance_to_segment(const NT& cx, const NT& cy, const NT& ax, const NT& ay,
                                                             const NT& bx, const NT& by, const NT& r) {
  using CGAL::Uncertain;
  const NT dx = bx - ax;
  const NT dy = by - ay;
  const NT wx = cx - ax;
  const NT wy = cy - ay;
  const NT r2 = r * r;
  // Which part of the segment is nearest: a, b, or its interior. All branches are decided
  // exactly; an uncertain branch returns "uncertain" so that the exact number type decides.
  const NT t = wx * dx + wy * dy;
  const auto before_a = t <= NT(0);
  if (!CGAL::is_certain(before_a)) {
    return Uncertain<CGAL::Comparison_result>::indeterminate();
  }
  if (CGAL::get_certain(before_a)) {
    return CGAL::compare(wx * wx + wy * wy, r2);
  }
  const NT len2 = dx * dx + dy * dy;
  const auto after_b = t >= len2;
  if (!CGAL::is_certain(after_b)) {
    return Uncertain<CGAL::Comparison_result>::indeterminate();
  }
  if (CGAL::get_certain(after_b)) {
    const NT ux = cx - bx;
    const NT uy = cy - by;
    return CGAL::compare(ux * ux + uy * uy, r2);
  }
  // Interior: distance^2 = cross^2 / len2; compare without dividing.
  const NT cross = dx * wy - dy * wx;
  return CGAL::compare(cross * cross, r2 * len2);
}

template <class NT>
CGAL::Uncertain<CGAL::Comparison_result> centre_distance(const NT& x1, const NT& y1, const NT& x2, const NT& y2,
                                                         const NT& r1, const NT& r2) {
  const NT dx = x1 - x2;
  const NT dy = y1 - y2;
  const NT s = r1 + r2;
  return CGAL::compare(dx * dx + dy * dy, s * s);
}

}  // namespace

CGAL::Comparison_result compare_distance_to_segment(Point c, Point a, Point b, double r) {
  return filtered<CGAL::Comparison_result>([&](auto tag) {
    using NT = decltype(tag);
    return distance_to_segment(NT(c.x), NT(c.y), NT(a.x), NT(a.y), NT(b.x), NT(b.y), NT(r));
  });
}

CGAL::Comparison_result compare_centre_distance(Point c1, Point c2, double r1, double r2) {
  // Semi-static filter. With u = 2^-53, the computed d2 = dx^2 + dy^2 has relative error at most
  // 4u, s2 = (r1 + r2)^2 at most 3u, and their difference adds u: |error| <= 5u (d2 + s2), plus
  // at most 16 subnormal units (2^-1070) of absolute error if products underflow. Outside
  // max(8u (d2 + s2), 2^-1000) the sign is certain (where 3u (d2 + s2) < 2^-1070, d2 + s2 is below
  // 2^-1017 and the error below 2^-1066); inside it, or on overflow, intervals and then exact
  // arithmetic decide. The floor is a normal number, not 16 * denorm_min(): GCC (with CGAL's
  // -frounding-math) converts that from an x87 constant at run time, and storing the subnormal
  // costs Intel processors a microcode assist on every pair (measured: a third of the boundary
  // method's pipeline on a Xeon; docs/design-notes.md).
  {
    const double dx = c1.x - c2.x;
    const double dy = c1.y - c2.y;
    const double s = r1 + r2;
    const double d2 = dx * dx + dy * dy;
    const double s2 = s * s;
    const double diff = d2 - s2;
    const double size = d2 + s2;
    if (std::isfinite(diff) && std::isfinite(size)) {
      const double bound = std::max(8 * 0x1p-53 * size, 0x1p-1000);
      if (diff > bound) {
        return CGAL::LARGER;
      }
      if (diff < -bound) {
        return CGAL::SMALLER;
      }
    }
  }
  return filtered<CGAL::Comparison_result>([&](auto tag) {
    using NT = decltype(tag);
    return centre_distance(NT(c1.x), NT(c1.y), NT(c2.x), NT(c2.y), NT(r1), NT(r2));
  });
}

}  // namespace frontpack::detail
