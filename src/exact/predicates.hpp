// Exact geometric predicates on doubles.
//
// Orientation comes straight from CGAL's Epick kernel (static filter, then interval, then exact).
// The disk predicates are not kernel predicates, so they are written once as templates over the
// number type and evaluated the way CGAL's Filtered_predicate does: first with interval arithmetic
// (CGAL::Interval_nt, under CGAL::Protect_FPU_rounding), and only when the interval answer is
// uncertain, with CGAL::Mpzf, an exact multiprecision float (all our predicates are polynomial,
// so no division and no rational is needed). The answer is therefore the exact answer for the
// given doubles, whatever their magnitude.
//
// This header includes CGAL: include it only from sources that link CGAL::CGAL (they are compiled
// with -frounding-math).
#pragma once

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Interval_nt.h>
#include <CGAL/Mpzf.h>
#include <CGAL/Uncertain.h>

#include "frontpack/geometry.hpp"

namespace frontpack::detail {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using KPoint = Kernel::Point_2;

inline KPoint to_cgal(Point p) {
  return {p.x, p.y};
}

/// +1 if a, b, c turn left (anticlockwise), -1 if right, 0 if collinear. Exact.
inline int orientation(Point a, Point b, Point c) {
  return static_cast<int>(CGAL::orientation(to_cgal(a), to_cgal(b), to_cgal(c)));
}

/// Sign of (b - a) . (c - a). Exact.
inline int dot_sign(Point a, Point b, Point c) {
  // CGAL::angle(b, a, c) is the sign of (b - a) . (c - a): ACUTE > 0, RIGHT = 0, OBTUSE < 0.
  switch (CGAL::angle(to_cgal(b), to_cgal(a), to_cgal(c))) {
    case CGAL::ACUTE: return 1;
    case CGAL::RIGHT: return 0;
    default: return -1;
  }
}

/// Whether p lies on the closed segment [a, b]. Exact.
inline bool on_segment(Point p, Point a, Point b) {
  if (orientation(a, b, p) != 0) {
    return false;
  }
  const bool in_x = (a.x <= p.x && p.x <= b.x) || (b.x <= p.x && p.x <= a.x);
  const bool in_y = (a.y <= p.y && p.y <= b.y) || (b.y <= p.y && p.y <= a.y);
  return in_x && in_y;
}

/// Evaluates `f(NT{})` first with intervals, then (if uncertain) exactly. `f` must return a
/// CGAL::Uncertain<T> for intervals and something convertible to T for exact numbers.
template <class T, class F>
T filtered(F&& f) {
  {
    CGAL::Protect_FPU_rounding<true> guard;
    const CGAL::Uncertain<T> approx = f(CGAL::Interval_nt<false>{});
    if (CGAL::is_certain(approx)) {
      return CGAL::get_certain(approx);
    }
  }
  return CGAL::make_certain(f(CGAL::Mpzf{}));
}

/// Compares the distance from c to the closed segment [a, b] with r (r >= 0): SMALLER means the
/// open disk of radius r about c meets the segment. Exact.
CGAL::Comparison_result compare_distance_to_segment(Point c, Point a, Point b, double r);

/// Compares |c1 - c2| with r1 + r2: SMALLER means the two closed disks overlap (their interiors
/// intersect); EQUAL means they touch. Exact.
CGAL::Comparison_result compare_centre_distance(Point c1, Point c2, double r1, double r2);

}  // namespace frontpack::detail
