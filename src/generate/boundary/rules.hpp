// The boundary front's rules (boundary_front.cpp): the void classes, how many moves each kind of
// gap gets (cases (b)-(d) of Sec. 2.2), when an interior front gap closes over the disk in its way,
// and how many radii the end of a run may skip; each with the measurements that chose it
// (docs/boundary-method.md has them in context). Header-only and CGAL-free.
#pragma once

#include <cstddef>

namespace frontpack::detail::boundary_rules {

// Void buckets: log-spaced radius classes between rmin and rmax. Finer classes match each radius
// to a void barely larger than it (at rmax / rmin = 10, 24 classes gave the comb an interior of
// 0.836, 128 give 0.842); the cost per disk grows by about a tenth.
constexpr int kClasses = 128;
// Alternatives tried per gap (cases (b)-(d): the candidate moved to touch the element in its way
// and one of its parents). None for a front gap or a void in the interior: there a move places
// few of the disks it tries, and the radii it would have placed find the voids instead (moves
// cost the interior 0.01 of packing fraction on every shape: 0.842-0.852 with one move per front
// gap, 0.849-0.864 without). One, though, where the element in the way is a wall or
// a reflex vertex (kWallCut): the moved disk then touches the boundary, and a smooth curve's band
// stays as dense as its interior (without it a 100,000-vertex circle's band packed 0.66 against
// 0.84 inside). Gaps on a wall or a reflex vertex get three, and so do voids there: with one per
// void the band of a rough boundary (big_polygon) packed 0.023 below its interior, with three
// 0.015.
//
// An interior front gap blocked by a disk whose pocket no radius of the distribution fits (the
// pocket between the gap's two elements and the disk, below rmin) would be dropped, and the front
// would leave a hole there: no other gap faces it. It gets kClose moves instead, which close the
// front over the blocker as the paper's cases (b)-(d) do (Sec. 2.2). At wide size ranges such
// pockets are rare and the rule changes little (rmax / rmin = 10: interior 0.865 either way); at
// narrow ones almost every blocked gap is one, and without it the front left holes where a large
// disk fits (bidisperse 1:1.4: interior 0.746 without, 0.809 with two moves, 0.795 with one, 0.809
// with three; docs/density.md). Closing at larger pockets too (below the distribution's 30% or 60%
// quantile) took 0.01-0.015 from the interior at rmax / rmin = 3 and 10; closing voids as well
// changed nothing but the cost (1.3-1.8 times the time per disk at ratios 1.4-3). Not with a
// constant radius: there the front grows a crystal from every wall, a blocked gap is one of its
// interstices, and closing over it breaks the crystal (a 10 x 10 square of radius 0.025: interior
// 0.892 without, 0.788 with).
//
// At narrow size ranges (rmax / rmin <= 2) the front closes over every blocker whose pocket cannot
// take the largest radius (below rmax), not only those no radius fits (close_below()): there a
// pocket between rmin and rmax takes a disk only when the next radius drawn happens to be small,
// and kept as a void it left a hole in the front meanwhile. 10 x 10 square, seeds 1 and 2, interior
// with pockets below rmin / below rmax: bidisperse 1:1.4 0.8102, 0.8093 / 0.8145, 0.8135 (rattlers
// 1.2% / 0.6%); uniform 1:1.4 0.8132, 0.8137 / 0.8169, 0.8173; uniform 1:2 0.814, 0.814 / 0.8157,
// 0.8152 (rattlers 4.5% / 1.2%). From about 2.1 up it costs: uniform 1:2.2 0.8174 / 0.8161,
// 1:2.5 0.8241 / 0.8189, 1:3 0.8379 / 0.825 (with pockets below 2 rmin).
[[nodiscard]] constexpr double close_below(double rmin, double rmax) noexcept {
  return rmax <= 2 * rmin ? rmax : rmin;
}
constexpr int kMoves = 0;
constexpr int kClose = 2;
constexpr int kWallCut = 1;
constexpr int kWallMoves = 3;
constexpr int kVoidMoves = 3;
// The end of a run: the last voids, where the fronts met, are filled with the radii that fit
// them, skipping those that fit none, at most one radius in kSkipPer placed. Without it the seam
// where the fronts met last stayed sparse (the centre of a 10 x 10 square, uniform radii
// 0.0019-0.019, 207k disks: 0.706 of a disk of radius 0.1 covered, 0.807 from 0.1 to 0.2, against
// 0.868 around); skipping 1 in 1000 gave 0.829 and 0.852, 1 in 100 0.870 and 0.879, with the KS
// distance by area from the request 0.0017 -> 0.0018 (measured without the cavity pass).
constexpr std::size_t kSkipPer = 100;

}  // namespace frontpack::detail::boundary_rules
