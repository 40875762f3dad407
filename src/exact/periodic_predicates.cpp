#include "exact/periodic_predicates.hpp"

#include "exact/predicates.hpp"

namespace frontpack::detail {

namespace {

// |k| <= 2^53 converts to a double exactly.
double exact_double(std::int64_t k) {
  return static_cast<double>(k);
}

}  // namespace

int compare_image_distance(Point c1, Point c2, double r1, double r2, std::int64_t kx, std::int64_t ky,
                           const Box& cell) {
  const double fx = exact_double(kx);
  const double fy = exact_double(ky);
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
    return (NT(lo) <= NT(v) - NT(r)) & (NT(v) + NT(r) <= NT(hi));
  });
}

}  // namespace frontpack::detail
