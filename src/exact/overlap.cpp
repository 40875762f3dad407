// The CGAL-free facade of the exact disk predicates (exact/overlap.hpp), for the generators.
#include "exact/overlap.hpp"

#include "exact/predicates.hpp"

namespace frontpack::detail {

namespace {

template <class NT>
CGAL::Uncertain<CGAL::Comparison_result> centre_distance_with_gap(const NT& x1, const NT& y1, const NT& x2,
                                                                  const NT& y2, const NT& r1, const NT& r2,
                                                                  const NT& gap) {
  const NT dx = x1 - x2;
  const NT dy = y1 - y2;
  const NT s = r1 + r2 + gap;
  return CGAL::compare(dx * dx + dy * dy, s * s);
}

}  // namespace

bool disks_overlap_exact(Point c1, double r1, Point c2, double r2) {
  return compare_centre_distance(c1, c2, r1, r2) == CGAL::SMALLER;
}

bool disks_closer_than_exact(Point c1, double r1, Point c2, double r2, double gap) {
  return filtered<CGAL::Comparison_result>([&](auto tag) {
           using NT = decltype(tag);
           return centre_distance_with_gap(NT(c1.x), NT(c1.y), NT(c2.x), NT(c2.y), NT(r1), NT(r2), NT(gap));
         }) == CGAL::SMALLER;
}

}  // namespace frontpack::detail
