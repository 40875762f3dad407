// The acceptance test both generators run on every candidate disk (Sec. 2.2, case (a): the new
// disk overlaps nothing): floating point outside a narrow band around the keep-out distance, the
// exact predicate inside it. Header-only and CGAL-free (exact/overlap.hpp is the facade to the
// exact predicate): it runs tens of times per disk.
#pragma once

#include <cmath>

#include <cstddef>

#include "exact/overlap.hpp"

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

/// Whether a candidate comes closer to a placed disk o than r + o.r + margin: "overlaps" for the
/// generators. The margin (half the clearance) keeps every accepted pair apart by more than the
/// rounding of the output (box corner + local position) can take away, so that no pair overlaps
/// in the coordinates written out; tangent placements, at the full clearance, always pass (so a
/// candidate's parents need no skipping). Outside a band of a quarter of the clearance around that
/// distance floating point decides; inside it, the exact predicate does, on the very doubles
/// (counted in the counter the test is given, FrontReport::exact_checks). A Node is anything with
/// members x, y and r.
class OverlapTest {
 public:
  OverlapTest(double clearance, std::size_t& exact_checks) noexcept
      : margin_(clearance / 2), band_(clearance / 4), exact_checks_(&exact_checks) {}

  [[nodiscard]] double margin() const noexcept { return margin_; }
  [[nodiscard]] double band() const noexcept { return band_; }
  [[nodiscard]] Probe probe(double x, double y, double r) const noexcept { return Probe::at(x, y, r, margin_, band_); }

  /// Whether the candidate overlaps o (the paper's fronts: whether is all they ask).
  template <class Node>
  [[gnu::always_inline]] bool overlaps(const Probe& p, const Node& o) {
    return measure<false>(p, o) > 0;
  }

  /// How far the candidate comes into o's keep-out distance r + o.r + margin: > 0 if it overlaps
  /// (the boundary front keeps the deepest element in the way). Where the exact predicate decides,
  /// only the sign is known: 2^-1000 if it overlaps.
  template <class Node>
  [[gnu::always_inline]] double depth(const Probe& p, const Node& o) {
    return measure<true>(p, o);
  }

 private:
  // -1 for clear; for an overlap, its depth (Depth) or 1.
  template <bool Depth, class Node>
  [[gnu::always_inline]] double measure(const Probe& p, const Node& o) {
    const double dx = p.x - o.x;
    const double dy = p.y - o.y;
    const double d2 = dx * dx + dy * dy;
    const double hi = p.r_hi + o.r;
    if (d2 >= hi * hi) {
      return -1;
    }
    const double lo = p.r_lo + o.r;
    if (lo > 0 && d2 < lo * lo) {
      if constexpr (Depth) {
        return p.r + o.r + margin_ - std::sqrt(d2);
      } else {
        return 1;
      }
    }
    return exact(p, o) ? 0x1p-1000 : -1;
  }

  // Out of line, so that the scan loops keep the disks they test in registers (inlined, the
  // call's arguments made them copy every disk to the stack).
  template <class Node>
  [[gnu::noinline, gnu::cold]] bool exact(const Probe& p, const Node& o) {
    ++*exact_checks_;
    return disks_closer_than_exact({p.x, p.y}, p.r, {o.x, o.y}, o.r, margin_);
  }

  double margin_;
  double band_;
  std::size_t* exact_checks_;
};

}  // namespace frontpack::detail
