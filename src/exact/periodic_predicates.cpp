#include "exact/periodic_predicates.hpp"

#include <type_traits>

#include <algorithm>
#include <cmath>

#include "exact/predicates.hpp"

namespace frontpack::detail {

namespace {

// |k| <= 2^53 converts to a double exactly.
double exact_double(std::int64_t k) {
  return static_cast<double>(k);
}

// The semi-static filter of compare_image_distance(): the sign when double arithmetic with error
// bounds decides it, else 0 (then intervals and exact arithmetic decide). With u = 2^-53 and
// M = |c1| + |c2| + |k| (|lo| + |hi|) on an axis, every intermediate of d = c1 - (c2 + k (hi - lo))
// is below M in magnitude and d takes at most 4 roundings, so the computed d is within 4u M < E =
// 2^-50 M of the exact one. The bounds below widen each further rounding by more than u (2^-51 or
// 2^-50 relative on non-negative quantities), and 2^-1000 absorbs subnormal products; inputs below
// 2^-400 or above 2^400 are left to the exact path.
int image_filter(Point c1, Point c2, double r1, double r2, double fx, double fy, const Box& cell) {
  const double mx = std::abs(c1.x) + std::abs(c2.x) + std::abs(fx) * (std::abs(cell.xmin) + std::abs(cell.xmax));
  const double my = std::abs(c1.y) + std::abs(c2.y) + std::abs(fy) * (std::abs(cell.ymin) + std::abs(cell.ymax));
  const double s = r1 + r2;
  if (!(mx < 0x1p400 && my < 0x1p400 && s < 0x1p400 && s > 0x1p-400)) {
    return 0;
  }
  const double dx = std::abs((c1.x - c2.x) - fx * (cell.xmax - cell.xmin));
  const double dy = std::abs((c1.y - c2.y) - fy * (cell.ymax - cell.ymin));
  const double ex = 0x1p-50 * mx;
  const double ey = 0x1p-50 * my;
  constexpr double up = 1 + 0x1p-50;
  constexpr double down = 1 - 0x1p-50;
  const double dx_lo = std::max(dx - ex, 0.0) * down;
  const double dy_lo = std::max(dy - ey, 0.0) * down;
  const double dx_hi = (dx + ex) * up;
  const double dy_hi = (dy + ey) * up;
  const double d2_lo = (dx_lo * dx_lo + dy_lo * dy_lo) * down;
  const double d2_hi = (dx_hi * dx_hi + dy_hi * dy_hi) * up + 0x1p-1000;
  const double s_lo = s * down;
  const double s_hi = s * up;
  const double s2_lo = s_lo * s_lo * down;
  const double s2_hi = s_hi * s_hi * up;
  if (d2_lo > s2_hi) {
    return 1;
  }
  if (d2_hi < s2_lo) {
    return -1;
  }
  return 0;
}

}  // namespace

int compare_image_distance(Point c1, Point c2, double r1, double r2, std::int64_t kx, std::int64_t ky,
                           const Box& cell) {
  const double fx = exact_double(kx);
  const double fy = exact_double(ky);
  if (const int sign = image_filter(c1, c2, r1, r2, fx, fy, cell); sign != 0) {
    return sign;
  }
  const CGAL::Comparison_result result = filtered<CGAL::Comparison_result>([&](auto tag) {
    using NT = decltype(tag);
    const NT dx = NT(c1.x) - (NT(c2.x) + NT(fx) * (NT(cell.xmax) - NT(cell.xmin)));
    const NT dy = NT(c1.y) - (NT(c2.y) + NT(fy) * (NT(cell.ymax) - NT(cell.ymin)));
    const NT s = NT(r1) + NT(r2);
    return CGAL::compare(dx * dx + dy * dy, s * s);
  });
  return static_cast<int>(result);
}

int wrapped_side(double v, std::int64_t k, double lo, double hi) {
  const double fk = exact_double(k);
  const auto below = filtered<bool>([&](auto tag) {
    using NT = decltype(tag);
    return NT(v) - NT(fk) * (NT(hi) - NT(lo)) < NT(lo);
  });
  if (below) {
    return -1;
  }
  const auto above = filtered<bool>([&](auto tag) {
    using NT = decltype(tag);
    return NT(v) - NT(fk) * (NT(hi) - NT(lo)) >= NT(hi);
  });
  return above ? 1 : 0;
}

bool between_walls(double v, double r, double lo, double hi) {
  return filtered<bool>([&](auto tag) {
    using NT = decltype(tag);
    const auto above_floor = NT(lo) <= NT(v) - NT(r);
    const auto below_ceiling = NT(v) + NT(r) <= NT(hi);
    // Intervals give CGAL::Uncertain<bool>, whose & is three-valued; exact numbers give bool.
    if constexpr (std::is_same_v<std::decay_t<decltype(above_floor)>, bool>) {
      return above_floor && below_ceiling;
    } else {
      return above_floor & below_ceiling;
    }
  });
}

}  // namespace frontpack::detail
