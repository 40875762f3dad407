// The acceptance test both generators run on every candidate disk (Sec. 2.2, case (a): the new
// disk overlaps nothing): floating point outside a narrow band around the keep-out distance, the
// exact predicate inside it. Header-only and CGAL-free (exact/overlap.hpp is the facade).
#pragma once



namespace frontpack::detail {

/// A candidate disk with the limits of the overlap test's band precomputed: the test runs tens of
/// times per disk. Another disk o is clear beyond r_hi + o.r and overlapping within r_lo + o.r;
/// in between the exact predicate decides (margin = clearance / 2, band = clearance / 4).
struct Probe {
  double x, y, r;
  double r_hi;  // r + margin + band
  double r_lo;  // r + margin - band

  static Probe at(double x, double y, double r, double margin, double band) noexcept {
    return {x, y, r, r + margin + band, r + margin - band};
  }
};

}  // namespace frontpack::detail
