// edge_sweep.hpp. GCC 12 reports -Wmaybe-uninitialized for a std::pair built inside the
// arrangement traits' Compare_y_at_x_right_2 (CGAL 5.5, Arr_non_caching_segment_basic_traits_2),
// only when ASan's instrumentation changes the inlining; the pair is initialised on every path. The
// warning is silenced here, for this file only.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif

#include "edge_sweep.hpp"

#include <CGAL/Arr_non_caching_segment_traits_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Surface_sweep_2_algorithms.h>

namespace frontpack::detail {

bool edge_interiors_disjoint(const std::vector<Point>& v, const std::vector<std::uint32_t>& next) {
  // The exact-constructions kernel: the sweep decides from predicates on the input points as
  // long as it finds nothing, and it stops at the first intersection, which it constructs.
  using EK = CGAL::Exact_predicates_exact_constructions_kernel;
  std::vector<EK::Segment_2> segments;
  segments.reserve(v.size());
  for (std::size_t e = 0; e < v.size(); ++e) {
    const Point a = v[e];
    const Point b = v[next[e]];
    segments.emplace_back(EK::Point_2(a.x, a.y), EK::Point_2(b.x, b.y));
  }
  CGAL::Arr_non_caching_segment_traits_2<EK> traits;
  return !CGAL::do_curves_intersect(segments.begin(), segments.end(), traits);
}

}  // namespace frontpack::detail
