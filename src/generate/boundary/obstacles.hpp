// What a candidate disk of the boundary front runs into: the placed disks in the cells of a grid,
// the walls listed per cell (wall_index.hpp), and the queries a try at a gap asks of them: the
// element a candidate overlaps most deeply (which cases (b)-(d) of Sec. 2.2 then move it to touch),
// or whether it overlaps anything (case (a)). Header-only queries and CGAL-free: every candidate
// asks.
//
// The reflex vertices are nodes (elements a disk can touch) but stay out of the cells: as
// obstacles their walls cover them. A disk closer to a vertex than its radius (plus the margin)
// is as close to the walls that end there, which are in the cell's list or found by the tree,
// and at least as deep in them, and the walls are tried first; so no scan returned one on 5
// shapes, and on the rough ring `big_polygon` they were most of the disks each scan near the
// boundary tested. (Up to rounding: within a few ulps of the threshold the vertex was decided
// exactly and the wall in floating point, and a review's simulation found probes, 0.1-0.4% of
// those placed there on purpose, that only the vertex stopped; each stayed at least 0.999 of
// the margin, half the clearance, from the boundary, which is what the wall test guarantees
// everywhere else, and the certifier decides containment exactly.)
#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "common/huge_pages.hpp"
#include "generate/acceptance.hpp"
#include "generate/boundary/elements.hpp"
#include "generate/boundary/wall_index.hpp"
#include "generate/disk_grid.hpp"
#include "generate/settings.hpp"

namespace frontpack::detail {

class Obstacles {
 public:
  static constexpr std::uint32_t kWallList = 16;  // a cell with more walls than this asks the wall tree

  /// `exact_checks` counts the overlap tests the exact predicate decides (FrontReport).
  Obstacles(const RunFrame& frame, std::size_t& exact_checks) noexcept
      : overlap_(frame.clearance, exact_checks), rmax_(frame.rmax) {}

  /// Builds the grid over the frame's box and the lists of the walls near its cells; checks them
  /// against the memory limit. Returns the bytes they keep for the run.
  std::size_t set_up(const std::vector<Wall>& walls, const RunFrame& frame, const SetupBudget& budget);

  /// Frees the grid and the wall lists (the run is over).
  void release() {
    detail::release(head_cell_);
    index_.release();
  }

  /// Puts node id at (x, y), a candidate that passed the box test, in its cell; returns the node
  /// that headed the cell (the new node's cell_next).
  std::int32_t enter(std::int32_t id, double x, double y) noexcept {
    const std::size_t c = probe_cell(x, y);
    const std::int32_t next = head_cell_[c];
    head_cell_[c] = id;
    return next;
  }

  [[nodiscard]] Probe probe(double x, double y, double r) const noexcept { return overlap_.probe(x, y, r); }
  /// How far the candidate comes into disk o (acceptance.hpp): > 0 if it overlaps.
  double depth(const Probe& p, const BoundaryNode& o) { return overlap_.depth(p, o); }

  /// Whether (x, y) lies inside the polygon (wall_index.hpp); in a periodic cell, between its
  /// walls (set_periodic()).
  [[nodiscard]] bool inside(double x, double y) const noexcept {
    return periodic_ ? y > band_[0] && y < band_[1] : index_.inside(x, y);
  }
  /// A periodic cell: inside() is ylo < y < yhi (its walls, or none: infinite bounds), since its
  /// walls are no ring.
  void set_periodic(double ylo, double yhi) noexcept {
    periodic_ = true;
    band_ = {ylo, yhi};
  }
  /// The wall nearest to (x, y) (wall_index.hpp).
  std::int32_t nearest(double x, double y, double& d2, std::int32_t best) const noexcept {
    return index_.nearest(x, y, d2, best);
  }

  // Whether a disk in the grid cell of (x, y) lies within rho of it (a disk of radius rho there
  // would overlap it): a quick first test before a scan, for the cavity pass.
  [[nodiscard]] bool covered_in_cell(const Elements& el, double x, double y, double rho) const noexcept {
    const std::size_t home = static_cast<std::size_t>(probe_row(y)) * grid_.nx + static_cast<std::size_t>(probe_col(x));
    for (std::int32_t e = head_cell_[home]; e != kNoElement; e = el.node(e).cell_next) {
      const BoundaryNode& o = el.node(e);
      const double reach = o.r + rho;
      if ((o.x - x) * (o.x - x) + (o.y - y) * (o.y - y) < reach * reach) {
        return true;
      }
    }
    return false;
  }

  // The two disks whose surfaces lie nearest (x, y) (least |p - c| - r), among those whose
  // centres lie within reach + rmax of it; kNoElement for each that is missing. Of two as near,
  // the older. For the cavity pass (boundary_front.cpp): once, after the front.
  [[nodiscard]] std::array<std::int32_t, 2> nearest_disks(const Elements& el, double x, double y, double reach) const {
    std::array<std::int32_t, 2> best{kNoElement, kNoElement};
    std::array<double, 2> gap{0, 0};
    const double r_reach = reach + rmax_;
    visit_cells(head_cell_.data(), grid_.nx, el.nodes(), kNoElement, probe_col(x - r_reach), probe_col(x + r_reach),
                probe_row(y - r_reach), probe_row(y + r_reach), [&](std::int32_t d, const BoundaryNode& o) {
                  const double g = std::sqrt((o.x - x) * (o.x - x) + (o.y - y) * (o.y - y)) - o.r;
                  const auto nearer = [&](std::size_t i) {
                    return best[i] == kNoElement || g < gap[i] || (g == gap[i] && d < best[i]);
                  };
                  if (nearer(0)) {
                    best[1] = best[0];
                    gap[1] = gap[0];
                    best[0] = d;
                    gap[0] = g;
                  } else if (nearer(1)) {
                    best[1] = d;
                    gap[1] = g;
                  }
                  return false;
                });
    return best;
  }

  // The element the candidate overlaps most deeply (a disk or a wall; a reflex vertex is no
  // deeper than the walls that end there, up to rounding: see above), or kNoElement.
  // Its parents need no skipping: it touches them at the full clearance, outside the band (at
  // most 3/4 of the clearance) in which depth() and the wall test can see an overlap.
  // With Any, the first element found that the candidate overlaps: for callers that only need to
  // know whether there is one (most candidates that get this far overlap something, and the scan
  // ends there). With `quick`, the gap whose candidate this is, and no wall in the way, the disks
  // in_the_way() tries are asked first, and the first of them in the way is returned: for a gap
  // whose try fails on any disk (no move, which only a wall in the way would start).
  // In a periodic cell the element found may be an image (Elements::real() names its disk).
  template <bool Any = false>
  std::int32_t deepest(const Elements& el, const Probe& p, const Gap* quick = nullptr);

 private:
  // col() and row() for a candidate that passed the box test (try_gap(), fits()): inside the
  // polygon's box grown by the clearance, so that, with a clearance below rmax, everything within
  // its reach (r + rmax and a clearance or two) lies in the grid's margin of 4 rmax, and its cells
  // need no clamping (the same cells, in fewer instructions: the clamps were 6% of the front's).
  // (Not for the one cell of a grid whose margin could not be 4 rmax.)
  [[nodiscard]] std::int64_t probe_col(double x) const noexcept {
    return probes_inside_ ? grid_.col_inside(x) : grid_.col(x);
  }
  [[nodiscard]] std::int64_t probe_row(double y) const noexcept {
    return probes_inside_ ? grid_.row_inside(y) : grid_.row(y);
  }
  [[nodiscard]] std::size_t probe_cell(double x, double y) const noexcept {
    return static_cast<std::size_t>(probe_row(y)) * grid_.nx + static_cast<std::size_t>(probe_col(x));
  }

  // A disk in the way of the candidate for gap (x, y) among those most often there, or
  // kNoElement: the gap's neighbours on the front (the first element of the last gap with x
  // second, the second of the last with y first) and the disks of the candidate's own cell. Most
  // tries fail (on the 1M square, 64% of front gaps and 31% of voids), and 56% of the failures are
  // settled here, for a node or two and one cell head instead of a scan of some 18 cells and 8
  // disks (front 8-13% faster, docs/performance.md).
  // Whatever is found is in the way, so the try fails exactly when the scan would have made it
  // fail; but it is not always the deepest element, and the void the gap leaves is bounded by
  // the pocket this one leaves (a bound all the same), so packings differ from the scan's.
  std::int32_t in_the_way(const Elements& el, std::int32_t x, std::int32_t y, const Probe& p, std::size_t home) {
    const std::int32_t before = el.is_disk(x) ? el.before(x) : kNoElement;
    if (el.is_disk(before) && depth(p, el.near(before, p.x, p.y)) > 0) {
      return before;
    }
    const std::int32_t after = el.is_disk(y) ? el.after(y) : kNoElement;
    if (el.is_disk(after) && depth(p, el.near(after, p.x, p.y)) > 0) {
      return after;
    }
    for (std::int32_t e = head_cell_[home]; e != kNoElement; e = el.node(e).cell_next) {
      if (depth(p, el.node(e)) > 0) {
        return e;
      }
    }
    return kNoElement;
  }

  OverlapTest overlap_;
  double rmax_;
  CellGrid grid_;
  bool probes_inside_ = false;  // probe_col(), probe_row(): no clamping needed
  HugeVector<std::int32_t> head_cell_;
  WallIndex index_;
  bool periodic_ = false;
  std::array<double, 2> band_{0, 0};  // periodic: inside() between these
};

template <bool Any>
std::int32_t Obstacles::deepest(const Elements& el, const Probe& p, const Gap* quick) {
  std::int32_t best = kNoElement;
  double best_depth = 0;
  const auto home_col = static_cast<std::size_t>(probe_col(p.x));
  const auto home_row = static_cast<std::size_t>(probe_row(p.y));
  const double reach = p.r + overlap_.margin();
  const auto [first_wall, end_wall] = index_.near_cell(home_row, home_col);
  if (end_wall == first_wall) {
    // No walls within reach.
  } else if (end_wall - first_wall > kWallList) {
    // A finely divided boundary: the nearest wall, from the tree, is the deepest one.
    double d2 = reach * reach;
    const std::int32_t e = index_.nearest(p.x, p.y, d2);
    if (e != kNoElement) {
      if constexpr (Any) {
        return e;
      }
      best = e;
      best_depth = reach - std::sqrt(d2);
    }
  } else {
    for (std::uint32_t k = first_wall; k < end_wall; ++k) {
      const std::int32_t e = index_.id(k);
      const double d2 = distance2(el.wall(e), p.x, p.y);
      if (d2 < reach * reach) {
        if constexpr (Any) {
          return e;
        }
        const double dd = reach - std::sqrt(d2);
        if (best == kNoElement || dd > best_depth) {
          best = e;
          best_depth = dd;
        }
      }
    }
  }
  if (quick != nullptr && best == kNoElement) {
    if (const std::int32_t e = in_the_way(el, quick->a, quick->b, p, home_row * grid_.nx + home_col); e != kNoElement) {
      return e;
    }
  }
  const double r_reach = (p.r_hi + rmax_) * (1 + 1e-9);  // depth() can say yes up to r_hi + o.r
  const std::int64_t c0 = probe_col(p.x - r_reach);
  const std::int64_t c1 = probe_col(p.x + r_reach);
  const std::int64_t r0 = probe_row(p.y - r_reach);
  const std::int64_t r1 = probe_row(p.y + r_reach);
  visit_cells(head_cell_.data(), grid_.nx, el.nodes(), kNoElement, c0, c1, r0, r1,
              [&](std::int32_t d, const BoundaryNode& o) {
                const double dd = depth(p, o);
                // Of two disks in the way as deep, the older: exact ties are the rule in the band
                // where the exact predicate decides (depth_exact() says only whether), and the first
                // in the order of the scan would depend on the size of the grid's cells.
                if (dd > 0 && (Any || best == kNoElement || dd > best_depth || (dd == best_depth && d < best))) {
                  best = d;
                  best_depth = dd;
                }
                return Any && dd > 0;
              });
  return best;
}

}  // namespace frontpack::detail
