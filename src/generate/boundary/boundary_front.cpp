// The boundary-conforming advancing front (generate/boundary/boundary_front.hpp): the open form's walls (Sec. 3)
// generalised to every edge of every ring, with reflex vertices as zero-radius obstacles; the
// front, kept as unlinked gaps, starts at the corners of every ring and advances inwards; cases
// (b)-(d) of Sec. 2.2 are decided by geometry (a move to touch the element in the way); the voids
// the front leaves (Sec. 2.2's holes) take later, smaller disks, bucketed by the Apollonius
// pocket each can hold. Element ids: a node (disk or reflex vertex) is >= 0, wall e is -(e + 1).
// The method, what it guarantees and where it deviates from the paper, and why:
// docs/boundary-method.md. Its density: docs/density.md; its cost: docs/performance.md.
#include "generate/boundary/boundary_front.hpp"

#include "generate/boundary/pocket.hpp"
#include "generate/boundary/wall_index.hpp"
#include "generate/boundary/walls.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <numeric>
#include <string>
#include <tuple>
#include <type_traits>
#include <utility>

#include "common/huge_pages.hpp"
#include "generate/acceptance.hpp"
#include "generate/disk_grid.hpp"
#include "generate/run_control.hpp"
#include "generate/scale.hpp"
#include "generate/tangency.hpp"
#include "generate/void_buckets.hpp"

namespace frontpack::detail {

namespace {

constexpr std::int32_t kNone = kNoElement;
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
constexpr int kMoves = 0;
constexpr int kWallCut = 1;
constexpr int kWallMoves = 3;
constexpr int kVoidMoves = 3;
constexpr std::uint32_t kWallList = 16;  // a cell with more walls than this asks the wall tree

class BoundaryFront {
  struct Node {
    double x, y, r;
    std::int32_t cell_next;
    std::int32_t after;  // the second element of the last front gap with this disk first (overtaker())
  };
  struct Gap {
    std::int32_t a, b;
    // A void's third element, the one that bounds it (keep_void()): a disk that a and b touch
    // no larger than the pocket between the three clears it. kNone on the front, and for a void
    // kept without one.
    std::int32_t bound = kNone;
  };

 public:
  BoundaryFront(const FrontSettings& req, const Polygon& polygon, Rng& rng, std::vector<Disk>& out, FillStats& stats)
      : req_(req),
        polygon_(polygon),
        rng_(rng),
        out_(out),
        stats_(stats),
        control_(req.max_disks, req.tick),
        out_before_(out.size()),
        frame_(*req.radii, req.clearance, outer_box(polygon)),
        overlap_(frame_.clearance, stats) {
    box_ = Box{-frame_.clearance, -frame_.clearance, frame_.width + frame_.clearance, frame_.height + frame_.clearance};
    classes_ = RadiusClasses<kClasses>(frame_.rmin, frame_.rmax);

    estimate_ = estimate_disks(outer_box(polygon), *req.radii);
    // (Every disk lies in the polygon: at most its box's area, bound_disks(), 1.18 estimates.)
    const auto reserve = count_of(estimate_ * 1.3 + 64, 1e9);
    nodes_.reserve(reserve);
    before_.reserve(reserve);
    setup_walls();
    setup_grid();
    for (const Wall& w : walls_) {
      polygon_area_ += (w.ax * w.by - w.bx * w.ay) / 2;  // holes (clockwise) subtract
    }
  }

  // The polygon's bounding box (its outer ring's).
  static Box outer_box(const Polygon& polygon) noexcept {
    Box box;
    for (const Point& p : polygon.outer) {
      box.extend(p);
    }
    return box;
  }

  FrontResult run() {
    FrontResult result;
    double r = draw();
    int cls = class_of(r);  // r's void class (r stays until it is placed)
    for (;;) {
      if (control_.stop(placed(), area_ * frame_.unit.inv_k * frame_.unit.inv_k, result)) {
        break;
      }
      Gap g{kNone, kNone};
      // Voids first, those on a rough wall before the others, the tightest class whose radii all
      // exceed r, the most recent void in it.
      int k = any_rough_ ? voids_[1].first_above(cls) : -1;
      std::size_t side = 1;
      if (k < 0) {
        k = voids_[0].first_above(cls);
        side = 0;
      }
      if (k >= 0) {
        g = voids_[side].pop(k);
      } else if (wall_head_ < wall_fifo_.size()) {
        g = wall_fifo_[wall_head_++];  // the first layer along every wall comes first
      } else if (!fifo_empty()) {
        g = fifo_[head_++];
        if (head_ > 4096 && head_ * 2 > fifo_.size()) {  // drop the consumed half (amortised O(1))
          fifo_.erase(fifo_.begin(), fifo_.begin() + static_cast<std::ptrdiff_t>(head_));
          head_ = 0;
        }
        if (const std::int32_t o = overtaker(g); o != kNone) {
          if (req_.fill_voids) {
            push_void(g, kClasses - 1, o);
          }
          continue;
        }
      } else {
        // The front is done and no void can take r. If the walls could not start a front (a
        // boundary rougher than the smallest disk: nothing fits in its corners) and the polygon
        // is far from full, a seed pair of disks starts one inside, growing outwards. Otherwise
        // the run ends here. (Skipping r and drawing smaller radii for the voids left would fill
        // them, but only by distorting the size distribution towards small radii.)
        if (seed(r)) {
          area_ += r * r;
          r = draw();
          cls = class_of(r);
          continue;
        }
        break;
      }
      if (const GapTry t = try_gap(g, r, k >= 0); t.placed) {
        area_ += r * r;
        r = draw();
        cls = class_of(r);
      } else if (req_.fill_voids && cls > 0 && !t.hopeless) {
        // r did not fit: the gap may still take a smaller disk, at most as large as the pocket
        // between its elements and the disk in the way.
        push_void(g, cls, t.blocker);
      }
    }
    // The front, the voids and the grid are done with: free them before the output grows (peak
    // memory: the nodes and the output are then all that is left).
    release(fifo_);
    release(wall_fifo_);
    for (auto& side : voids_) {
      side.release();
    }
    release(before_);
    release(head_cell_);
    index_.release();
    move_out(nodes_, corners_.size(), frame_.origin, frame_.unit.inv_k, out_);
    result.fixed_bytes = fixed_bytes_;
    return result;
  }

 private:
  [[nodiscard]] std::size_t placed() const noexcept {
    return nodes_.size() - static_cast<std::size_t>(corner_count_) + out_before_;
  }
  // Whether front gap g has been overtaken: a later gap paired its first disk with another second
  // element, or its second disk with another first one. Mostly a disk placed since then touching
  // one of them on g's free side has covered the gap (in the paper's list, g's segment was cut),
  // so its first position is taken; the gap is kept as a void instead, for the smaller radii that
  // may still fit. (Two thirds of the front's gaps used to fail all their moves; without the
  // overtaken ones the 1M-disk square needs 12% fewer overlap scans, and the density moves less
  // than from seed to seed.) The later pairing can also come from a void filled behind g (a fifth
  // of the cases with radii 0.002-0.02); testing its side as well changed neither the cost (-0.8%)
  // nor the densities beyond their noise, so it is not tested.
  //
  // Returns the element that overtook g (its first disk's new partner, else its second's), or
  // kNone if g is still on the front. (Neither link is ever kNone once g was queued: pushing g
  // set both.)
  [[nodiscard]] std::int32_t overtaker(Gap g) const noexcept {
    if (is_disk(g.a) && nodes_[static_cast<std::size_t>(g.a)].after != g.b) {
      return nodes_[static_cast<std::size_t>(g.a)].after;
    }
    if (is_disk(g.b) && before_[static_cast<std::size_t>(g.b)] != g.a) {
      return before_[static_cast<std::size_t>(g.b)];
    }
    return kNone;
  }
  [[nodiscard]] bool fifo_empty() const noexcept { return head_ == fifo_.size() && wall_head_ == wall_fifo_.size(); }
  [[nodiscard]] bool on_wall(std::int32_t e) const noexcept { return e < corner_count_; }  // a wall or a corner
  // Records gap g as the last one with its first disk first and its second disk second
  // (overtaker()).
  void link(Gap g) noexcept {
    if (is_disk(g.a)) {
      nodes_[static_cast<std::size_t>(g.a)].after = g.b;
    }
    if (is_disk(g.b)) {
      before_[static_cast<std::size_t>(g.b)] = g.a;
    }
  }
  void push_gap(Gap g) {
    link(g);
    if (on_wall(g.a) || on_wall(g.b)) {
      wall_fifo_.push_back(g);
    } else {
      fifo_.push_back(g);
    }
  }
  [[nodiscard]] static bool is_wall(std::int32_t e) noexcept { return e < 0; }
  // Against a copy of corners_.size() (the vector's size is a subtraction and a shift; with it,
  // these tests were 7% of the front's instructions on a 67k-disk square, under callgrind).
  [[nodiscard]] bool is_disk(std::int32_t e) const noexcept { return e >= corner_count_; }
  [[nodiscard]] bool is_corner(std::int32_t e) const noexcept {
    return static_cast<std::uint32_t>(e) < static_cast<std::uint32_t>(corner_count_);
  }
  [[nodiscard]] int class_of(double r) const noexcept { return classes_.of(r); }
  double draw() { return frame_.draw(rng_); }

  // ------------------------------------------------------------------------------------------
  // Walls, reflex vertices and the initial gaps.

  void setup_walls() {
    auto add_ring = [&](const Ring& ring) {
      const std::size_t n = ring.size();
      const auto first = static_cast<std::int32_t>(walls_.size());
      for (std::size_t i = 0; i < n; ++i) {
        const Point a = local(ring[i]);
        const Point b = local(ring[(i + 1) % n]);
        walls_.push_back(make_wall(a.x, a.y, b.x, b.y));
      }
      // Corner at vertex i + 1, between wall i (in) and wall i + 1 (out). The front starts at
      // every corner sharper than kSlideTurn; along gentler ones the wall layer slides from one
      // wall to the next (slide()), so a finely divided curve is not started at each of its
      // vertices (the ring's sharpest vertex starts it if none is sharp).
      ring_first_.push_back(static_cast<std::size_t>(first));
      rough_.resize(walls_.size(), 0);
      std::size_t sharpest = 0;
      double sharpest_turn = -1;
      bool started = false;
      auto start_at = [&](std::size_t i, bool convex, std::int32_t v) {
        const std::int32_t in = -(first + static_cast<std::int32_t>(i) + 1);
        const std::int32_t out = -(first + static_cast<std::int32_t>((i + 1) % n) + 1);
        if (convex) {
          push_gap(Gap{in, out});
        } else {
          push_gap(Gap{in, v});
          push_gap(Gap{v, out});
        }
        started = true;
      };
      std::vector<std::int32_t> vertex(n, kNone);  // the reflex vertex's node, per vertex
      for (std::size_t i = 0; i < n; ++i) {
        const Wall& wi = walls_[static_cast<std::size_t>(first) + i];
        const Wall& wo = walls_[static_cast<std::size_t>(first) + (i + 1) % n];
        const double cross = wi.tx * wo.ty - wi.ty * wo.tx;  // > 0: left turn, a convex corner
        const double dot = wi.tx * wo.tx + wi.ty * wo.ty;    // the cosine of the turn
        // A key that grows with the turn over [0, pi] (its sine, then 2 minus it), from * and -
        // alone: with std::atan2, whose last bit differs between C libraries, the vertex that
        // starts a ring without a corner could too.
        const double turn = dot > 0 ? std::abs(cross) : 2 - std::abs(cross);
        const bool sharp = dot <= kCosSlideTurn;  // turns by kSlideTurn or more
        const bool convex = cross > 1e-12;
        if (!convex) {
          vertex[i] = static_cast<std::int32_t>(corners_.size());
          corners_.push_back(Corner{wi.tx, wi.ty, wo.tx, wo.ty});
          corner_count_ = static_cast<std::int32_t>(corners_.size());
          corner_at_.push_back(Point{wi.bx, wi.by});
        }
        if (sharp && wi.len < 2 * frame_.rmax) {
          rough_[static_cast<std::size_t>(first) + i] = 1;
        }
        if (sharp && wo.len < 2 * frame_.rmax) {
          rough_[static_cast<std::size_t>(first) + (i + 1) % n] = 1;
        }
        if (turn > sharpest_turn) {
          sharpest_turn = turn;
          sharpest = i;
        }
        if (sharp) {
          start_at(i, convex, vertex[i]);
        }
      }
      if (!started && n > 0) {
        const Wall& wi = walls_[static_cast<std::size_t>(first) + sharpest];
        const Wall& wo = walls_[static_cast<std::size_t>(first) + (sharpest + 1) % n];
        start_at(sharpest, wi.tx * wo.ty - wi.ty * wo.tx > 1e-12, vertex[sharpest]);
      }
    };
    add_ring(polygon_.outer);
    for (const Ring& hole : polygon_.holes) {
      add_ring(hole);
    }
    any_rough_ = std::find(rough_.begin(), rough_.end(), 1) != rough_.end();
  }

  [[nodiscard]] Point local(Point p) const noexcept { return frame_.local(p); }

  // ------------------------------------------------------------------------------------------
  // The grid: placed disks in linked cells (reflex vertices are nodes, but not in the cells: see
  // below); per cell, the walls within reach of it (a disk of radius <= rmax centred in the cell
  // can only cross those).

  void setup_grid() {
    grid_ = CellGrid(0, 0, frame_.width, frame_.height, frame_.rmax);
    probes_inside_ = frame_.clearance < frame_.rmax && !grid_.coarse;
    // The memory limit (FrontSettings::memory_limit) counts what is built here: the cell heads
    // (4 bytes a cell) and 12 bytes a block of cells; the (cell, wall) pairs, 16 bytes each while
    // they are listed (8, and as much again while the list moves or is copied grouped), then 12
    // (the grouped copy and the lists kept) with 1,028 bytes a walled block; then
    // peak_bytes_per_disk per disk. On a sliver 1e-7 high these lists, sized by the grid's cells
    // and not by the disks, were most of the run's memory (565 MB for 1.1M disks).
    const SetupBudget budget{req_.memory_limit, estimate_};
    const std::size_t need = grid_.cells() * sizeof(std::int32_t) + WallIndex::block_bytes(grid_);
    budget.check(need, "the grid over the polygon's box has " + std::to_string(grid_.cells()) + " cells");
    head_cell_.assign(grid_.cells(), kNone);

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
    for (std::size_t v = 0; v < corners_.size(); ++v) {
      nodes_.push_back(Node{corner_at_[v].x, corner_at_[v].y, 0, kNone, kNone});
      before_.push_back(kNone);
    }

    // Walls per cell: those meeting the cell grown by rmax + the clearance (wall_index.cpp).
    const double reach = (frame_.rmax + frame_.clearance) * (1 + 1e-9) + 4 * frame_.clearance;
    index_.build(walls_, grid_, reach, need, budget);
    // What stays for the run; the disks have the rest of the limit.
    fixed_bytes_ = head_cell_.size() * sizeof(std::uint32_t) + index_.bytes();
    if (req_.memory_limit != 0) {
      budget.check(fixed_bytes_, "the grid and the lists of the walls near its cells");
      control_.limit_memory(req_.memory_limit - fixed_bytes_);
    }
  }

  [[nodiscard]] std::int64_t col(double x) const noexcept { return grid_.col(x); }
  [[nodiscard]] std::int64_t row(double y) const noexcept { return grid_.row(y); }
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

  std::int32_t add_node(double x, double y, double r) {
    const auto id = static_cast<std::int32_t>(nodes_.size());
    const std::size_t c = probe_cell(x, y);
    nodes_.push_back(Node{x, y, r, head_cell_[c], kNone});
    before_.push_back(kNone);
    head_cell_[c] = id;
    return id;
  }

  // ------------------------------------------------------------------------------------------
  // Tangent positions: a disk of radius r touching elements a and b (at the clearance), on the
  // left of a -> b. False if there is none.

  bool tangent(std::int32_t a, std::int32_t b, double r, double& px, double& py) const noexcept {
    const double g = r + frame_.clearance;
    if (!is_wall(a) && !is_wall(b)) {
      const Node& an = nodes_[static_cast<std::size_t>(a)];
      const Node& bn = nodes_[static_cast<std::size_t>(b)];
      return tangent_to_two(an.x, an.y, an.r + g, bn.x, bn.y, bn.r + g, /*left=*/true, frame_.scale, px, py);
    }
    if (is_wall(a) && is_wall(b)) {
      return tangent_to_two_walls(walls_[wall_index(a)], walls_[wall_index(b)], g, px, py);
    }
    // A wall and a node: before the node along the wall if the wall comes first, after it
    // otherwise. A reflex vertex at the wall's end lies on its line.
    const bool wall_first = is_wall(a);
    const Wall& wl = walls_[wall_index(wall_first ? a : b)];
    const std::int32_t d = wall_first ? b : a;
    const Node& dn = nodes_[static_cast<std::size_t>(d)];
    return tangent_to_disk_and_wall(dn.x, dn.y, dn.r, wl, wl.tx, wl.ty, g, !wall_first, ends(wl, d), px, py);
  }

  // ------------------------------------------------------------------------------------------
  // Overlap tests.

  [[nodiscard]] Probe probe(double x, double y, double r) const noexcept { return overlap_.probe(x, y, r); }
  // How far the candidate comes into disk o (acceptance.hpp): > 0 if it overlaps.
  double depth(const Probe& p, const Node& o) { return overlap_.depth(p, o); }

  // The element the candidate overlaps most deeply (a disk or a wall; a reflex vertex is no
  // deeper than the walls that end there, up to rounding: setup_grid()), or kNone.
  // Its parents need no skipping: it touches them at the full clearance, outside the band (at
  // most 3/4 of the clearance) in which depth() and the wall test can see an overlap.
  // With Any, the first element found that the candidate overlaps: for callers that only need to
  // know whether there is one (most candidates that get this far overlap something, and the scan
  // ends there). With `quick`, the gap whose candidate this is, and no wall in the way, the disks
  // in_the_way() tries are asked first, and the first of them in the way is returned: for a gap
  // whose try fails on any disk (no move, which only a wall in the way would start).
  template <bool Any = false>
  std::int32_t deepest(const Probe& p, const Gap* quick = nullptr) {
    std::int32_t best = kNone;
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
      if (e != kNone) {
        if constexpr (Any) {
          return e;
        }
        best = e;
        best_depth = reach - std::sqrt(d2);
      }
    } else {
      for (std::uint32_t k = first_wall; k < end_wall; ++k) {
        const std::int32_t e = index_.id(k);
        const Wall& wl = walls_[wall_index(e)];
        const double d2 = distance2(wl, p.x, p.y);
        if (d2 < reach * reach) {
          if constexpr (Any) {
            return e;
          }
          const double dd = reach - std::sqrt(d2);
          if (best == kNone || dd > best_depth) {
            best = e;
            best_depth = dd;
          }
        }
      }
    }
    if (quick != nullptr && best == kNone) {
      if (const std::int32_t e = in_the_way(quick->a, quick->b, p, home_row * grid_.nx + home_col); e != kNone) {
        return e;
      }
    }
    const double r_reach = (p.r_hi + frame_.rmax) * (1 + 1e-9);  // depth() can say yes up to r_hi + o.r
    const std::int64_t c0 = probe_col(p.x - r_reach);
    const std::int64_t c1 = probe_col(p.x + r_reach);
    const std::int64_t r0 = probe_row(p.y - r_reach);
    const std::int64_t r1 = probe_row(p.y + r_reach);
    visit_cells(head_cell_.data(), grid_.nx, nodes_.data(), kNone, c0, c1, r0, r1, [&](std::int32_t d, const Node& o) {
      const double dd = depth(p, o);
      // Of two disks in the way as deep, the older: exact ties are the rule in the band where
      // the exact predicate decides (depth_exact() says only whether), and the first in the
      // order of the scan would depend on the size of the grid's cells.
      if (dd > 0 && (Any || best == kNone || dd > best_depth || (dd == best_depth && d < best))) {
        best = d;
        best_depth = dd;
      }
      return Any && dd > 0;
    });
    return best;
  }

  // A disk in the way of the candidate for gap (x, y) among those most often there, or kNone: the
  // gap's neighbours on the front (the first element of the last gap with x second, the second of
  // the last with y first) and the disks of the candidate's own cell. Most tries fail (on the 1M
  // square, 64% of front gaps and 31% of voids), and 56% of the failures are settled here, for a
  // node or two and one cell head instead of a scan of some 18 cells and 8 disks (front 8-13%
  // faster, docs/performance.md).
  // Whatever is found is in the way, so the try fails exactly when the scan would have made it
  // fail; but it is not always the deepest element, and the void the gap leaves is bounded by
  // the pocket this one leaves (a bound all the same), so packings differ from the scan's.
  std::int32_t in_the_way(std::int32_t x, std::int32_t y, const Probe& p, std::size_t home) {
    const std::int32_t before = is_disk(x) ? before_[static_cast<std::size_t>(x)] : kNone;
    if (is_disk(before) && depth(p, nodes_[static_cast<std::size_t>(before)]) > 0) {
      return before;
    }
    const std::int32_t after = is_disk(y) ? nodes_[static_cast<std::size_t>(y)].after : kNone;
    if (is_disk(after) && depth(p, nodes_[static_cast<std::size_t>(after)]) > 0) {
      return after;
    }
    for (std::int32_t e = head_cell_[home]; e != kNone; e = nodes_[static_cast<std::size_t>(e)].cell_next) {
      if (depth(p, nodes_[static_cast<std::size_t>(e)]) > 0) {
        return e;
      }
    }
    return kNone;
  }

  // Whether the candidate really touches parent e where it should: its foot on a wall lies on the
  // edge, and it is not in the outside wedge of a reflex vertex (there it would be outside the
  // domain, touching the corner from without).
  [[nodiscard]] bool supported_by(std::int32_t e, double px, double py) const noexcept {
    if (is_wall(e)) {
      const Wall& wl = walls_[wall_index(e)];
      const double u = (px - wl.ax) * wl.tx + (py - wl.ay) * wl.ty;
      return u >= -frame_.clearance && u <= wl.len + frame_.clearance;
    }
    if (is_corner(e)) {
      const Corner& c = corners_[static_cast<std::size_t>(e)];
      const Node& v = nodes_[static_cast<std::size_t>(e)];
      const double dx = px - v.x;
      const double dy = py - v.y;
      const bool right_of_in = c.ux1 * dy - c.uy1 * dx < 0;
      const bool right_of_out = c.ux2 * dy - c.uy2 * dx < 0;
      return !(right_of_in && right_of_out);
    }
    return true;
  }

  // ------------------------------------------------------------------------------------------
  // The void a failed gap leaves: the radius of the circle touching nodes a, b and d from
  // outside, on the left of a -> b (Apollonius' problem; a, b, d disks or reflex vertices), or -1
  // if there is none or it is not computed (a wall among them, centres collinear). A disk touching
  // a and b no larger than that clears d: it is the most the gap can take with d in the way.
  [[nodiscard]] double pocket(std::int32_t a, std::int32_t b, std::int32_t d) const noexcept {
    if (d == kNone) {
      return -1;
    }
    const int walls = (is_wall(a) ? 1 : 0) + (is_wall(b) ? 1 : 0) + (is_wall(d) ? 1 : 0);
    if (walls == 1) {
      return pocket_at_wall(a, b, d);
    }
    if (walls == 2) {
      return pocket_at_walls(a, b, d);
    }
    if (walls != 0) {
      return -1;
    }
    const Node& na = nodes_[static_cast<std::size_t>(a)];
    const Node& nb = nodes_[static_cast<std::size_t>(b)];
    const Node& nd = nodes_[static_cast<std::size_t>(d)];
    return pocket_of_nodes<double>(na.x, na.y, na.r, nb.x, nb.y, nb.r, nd.x, nd.y, nd.r, frame_.scale);
  }

  // pocket(x, n, d) and pocket(n, y, d) for disks x, n, y and a node d that is no wall: the two
  // pockets a disk n placed in void (x, y) bounded by d leaves. In the lanes of a vector, in two
  // thirds of the instructions of two calls and with their two long chains of dependent
  // operations as one; the same bits (a lane that the vector leaves undecided, NaN, is computed
  // alone).
  [[nodiscard]] std::array<double, 2> pocket_pair(std::int32_t x, std::int32_t n, std::int32_t y,
                                                  std::int32_t d) const noexcept {
    const Node& a = nodes_[static_cast<std::size_t>(x)];
    const Node& m = nodes_[static_cast<std::size_t>(n)];
    const Node& b = nodes_[static_cast<std::size_t>(y)];
    const Node& o = nodes_[static_cast<std::size_t>(d)];
    const V2 rho = pocket_of_nodes<V2>(V2{a.x, m.x}, V2{a.y, m.y}, V2{a.r, m.r}, V2{m.x, b.x}, V2{m.y, b.y},
                                       V2{m.r, b.r}, lanes<V2>(o.x), lanes<V2>(o.y), lanes<V2>(o.r), frame_.scale);
    std::array<double, 2> caps{rho[0], rho[1]};
    if (x == d) {
      caps[0] = -1;
    } else if (std::isnan(caps[0])) [[unlikely]] {
      caps[0] = pocket(x, n, d);
    }
    if (y == d) {
      caps[1] = -1;
    } else if (std::isnan(caps[1])) [[unlikely]] {
      caps[1] = pocket(n, y, d);
    }
    return caps;
  }

  // pocket() with one wall among the three: the circle of radius rho at distance rho from the
  // wall's line (inside) touching the two nodes from outside; the smallest such rho.
  [[nodiscard]] double pocket_at_wall(std::int32_t a, std::int32_t b, std::int32_t d) const noexcept {
    std::int32_t w = a;
    std::int32_t i = b;
    std::int32_t j = d;
    if (is_wall(b)) {
      w = b;
      i = a;
    } else if (is_wall(d)) {
      w = d;
      i = a;
      j = b;
    }
    const Wall& wl = walls_[wall_index(w)];
    if (ends(wl, j)) {
      std::swap(i, j);
    }
    const Node& ni = nodes_[static_cast<std::size_t>(i)];
    const Node& nj = nodes_[static_cast<std::size_t>(j)];
    if (ends(wl, i)) {
      return ends(wl, j) ? -1 : pocket_at_wall_end(wl, ni, nj);
    }
    return pocket_at_line(wl, ni, nj);
  }

  // Whether node e is a reflex vertex at an end of wall wl (node coordinates and wall ends come
  // from the same ring points, so equality is exact).
  [[nodiscard]] bool ends(const Wall& wl, std::int32_t e) const noexcept {
    if (!is_corner(e)) {
      return false;
    }
    const Node& v = nodes_[static_cast<std::size_t>(e)];
    return (v.x == wl.ax && v.y == wl.ay) || (v.x == wl.bx && v.y == wl.by);
  }

  // pocket() with two walls among the three (a crevice of a rough boundary, or a corner with a disk
  // in the way): the circle of radius rho at distance rho from both walls' lines (inside) touching
  // the node from outside; the smallest such rho. Its centre moves along a line as rho grows. The
  // walls are segments: where the circle's foot on a wall's line falls off the segment, a vertex
  // and not the line bounds the pocket, and none is computed (-1).
  [[nodiscard]] double pocket_at_walls(std::int32_t a, std::int32_t b, std::int32_t d) const noexcept {
    std::int32_t w1 = a;
    std::int32_t w2 = b;
    std::int32_t i = d;
    if (!is_wall(a)) {
      w1 = d;
      i = a;
    } else if (!is_wall(b)) {
      w2 = d;
      i = b;
    }
    const Wall& p = walls_[wall_index(w1)];
    const Wall& q = walls_[wall_index(w2)];
    return pocket_at_two_walls(p, q, nodes_[static_cast<std::size_t>(i)]);
  }

  // Keeps gap g as a void for radii below class k, and below the pocket left by `blocker`.
  void push_void(Gap g, int k, std::int32_t blocker) {
    keep_void(g, k, blocker, blocker != kNone ? pocket(g.a, g.b, blocker) : -1);
  }
  // push_void() with the pocket `cap` already computed (-1: none).
  void keep_void(Gap g, int k, std::int32_t blocker, double cap) {
    if (cap >= 0) {
      k = cap < frame_.rmin ? 0 : std::min(k, class_of(cap));
    }
    if (k > 0) {
      g.bound = blocker;
      // Voids on a rough wall are kept apart and tried first.
      const std::size_t side =
          (is_wall(g.a) && rough_[wall_index(g.a)] != 0) || (is_wall(g.b) && rough_[wall_index(g.b)] != 0) ? 1 : 0;
      voids_[side].push(k, g);
    }
  }

  // ------------------------------------------------------------------------------------------
  // Seeds: two touching disks (r and a second drawn radius) at a point inside the polygon where
  // they fit, with the gaps on both sides of the pair. Tried only while the disks cover less than
  // half of what a dense packing would, at most kSeeds times, each at up to kSeedTries points
  // drawn in the polygon's box. Returns whether the pair was placed.
  static constexpr int kSeeds = 16;
  static constexpr int kSeedTries = 256;

  bool seed(double r) {
    if (seeds_ >= kSeeds || std::numbers::pi * area_ >= 0.5 * 0.82 * polygon_area_) {
      return false;
    }
    ++seeds_;
    const double r2 = draw();
    for (int t = 0; t < kSeedTries; ++t) {
      const double sx = frame_.width * rng_.uniform();
      const double sy = frame_.height * rng_.uniform();
      const double tx = sx + r + r2 + frame_.clearance;
      if (!index_.inside(sx, sy) || !fits(sx, sy, r) || !fits(tx, sy, r2)) {
        continue;
      }
      // The pair apart by the clearance, as tangent disks are (this cannot fail; checked before
      // the first disk is placed, so that nothing is left behind if it did).
      if (depth(probe(tx, sy, r2), Node{sx, sy, r, kNone, 0}) > 0) {
        continue;
      }
      const std::int32_t a = add_node(sx, sy, r);
      const std::int32_t b = add_node(tx, sy, r2);
      area_ += r2 * r2;
      push_gap(Gap{a, b});
      push_gap(Gap{b, a});
      return true;
    }
    return false;
  }

  // Whether a disk at (x, y) of radius r crosses no wall and overlaps no disk (with its centre
  // inside the polygon, it then lies inside).
  bool fits(double x, double y, double r) {
    if (!(x - r >= 0 && x + r <= frame_.width && y - r >= 0 && y + r <= frame_.height)) {
      return false;
    }
    return deepest<true>(probe(x, y, r)) == kNone;
  }

  // ------------------------------------------------------------------------------------------
  // Placing a disk of radius r in gap g.

  // The ring wall e belongs to.
  [[nodiscard]] std::size_t ring_of(std::int32_t e) const noexcept {
    const std::size_t i = wall_index(e);
    return static_cast<std::size_t>(std::upper_bound(ring_first_.begin(), ring_first_.end(), i) - ring_first_.begin()) -
           1;
  }

  // A candidate touching a wall and a node whose foot on the wall lies beyond the edge: along a
  // gently turning boundary (a curve divided into many short edges) it touches the next wall
  // instead. It is recomputed against the wall nearest to it, if that wall is on the same ring
  // and turned by less than kSlideTurn from the first, a few times over; otherwise it is left as
  // it is, for supported_by() to refuse.
  void slide(std::int32_t& x, std::int32_t& y, double r, double& px, double& py) {
    for (int k = 0; k < 4; ++k) {
      if (is_wall(x) == is_wall(y)) {
        return;
      }
      const bool wall_first = is_wall(x);
      const std::int32_t w = wall_first ? x : y;
      if (supported_by(w, px, py)) {
        return;
      }
      double d2 = distance2(walls_[wall_index(w)], px, py);
      const std::int32_t e = index_.nearest(px, py, d2, w);
      if (e == kNone || e == w || ring_of(e) != ring_of(w)) {
        return;
      }
      const Wall& a = walls_[wall_index(w)];
      const Wall& b = walls_[wall_index(e)];
      if (a.tx * b.tx + a.ty * b.ty < kCosSlideTurn) {
        return;
      }
      double qx = 0;
      double qy = 0;
      if (!(wall_first ? tangent(e, y, r, qx, qy) : tangent(x, e, r, qx, qy))) {
        return;
      }
      (wall_first ? x : y) = e;
      px = qx;
      py = qy;
    }
  }

  // Whether the pocket behind parents x and y (disks or reflex vertices) that a move (cases
  // (b)-(d)) brought together is worth keeping as a void. Behind them lies the element the move
  // replaced; their pocket rarely takes a disk, and beyond 4 rmin almost never: on the 3 x 3
  // square such voids were tried 178k times for 3k disks (1 in 67k beyond 8 rmin).
  [[nodiscard]] bool worth_a_void(std::int32_t x, std::int32_t y) const noexcept {
    const Node& a = nodes_[static_cast<std::size_t>(x)];
    const Node& b = nodes_[static_cast<std::size_t>(y)];
    const double dx = a.x - b.x;
    const double dy = a.y - b.y;
    const double reach = a.r + b.r + 4 * frame_.rmin;
    return dx * dx + dy * dy < reach * reach;
  }

  // What a try at a gap came to: placed, or why not.
  struct GapTry {
    bool placed = false;
    bool hopeless = false;         // no disk of the radius tried or smaller touches both elements
    std::int32_t blocker = kNone;  // an element in the way at the gap's first position, if one was met
  };

  GapTry try_gap(const Gap& g, double r, bool in_void) {
    GapTry result;
    std::int32_t x = g.a;
    std::int32_t y = g.b;
    double px = 0;
    double py = 0;
    ++stats_.attempts;
    if (!tangent(x, y, r, px, py)) {
      // No disk this small touches both (too far apart, or one holds the other, or parallel
      // walls): no smaller one does either. The gap is not kept as a void for smaller radii,
      // where it would fail the same way every time until the lowest class dropped it.
      result.hopeless = true;
      return result;
    }
    const bool walled = on_wall(x) || on_wall(y);
    std::int32_t replaced = kNone;  // the parent the last move replaced
    int moves = walled ? (in_void ? kVoidMoves : kWallMoves) : kMoves;
    for (int move = 0; move <= moves; ++move) {
      slide(x, y, r, px, py);
      if (!(px - r >= box_.xmin && px + r <= box_.xmax && py - r >= box_.ymin && py + r <= box_.ymax)) {
        return result;  // outside the polygon's box, so outside the polygon
      }
      const Probe p = probe(px, py, r);
      // At the last move, only whether anything is in the way matters (but not at the first: the
      // element it finds bounds the void the gap leaves, the deepest one if the grid is scanned).
      // In the interior, the disks most often in the way are tried before the scan (in_the_way()).
      const Gap first{x, y};
      const std::int32_t d =
          move == moves && move > 0 ? deepest<true>(p) : deepest(p, move == 0 && !walled ? &first : nullptr);
      if (d == kNone) {
        if (!supported_by(x, px, py) || !supported_by(y, px, py)) {
          return result;
        }
        // Touching a disk, a candidate that crosses no wall is inside: the two disks cover the
        // segment between their centres. Touching only walls and reflex vertices, it can lie
        // wholly outside where the domain is thinner than the clearance (a spike two edges a few
        // ulps apart): its centre must then be inside.
        if (!is_disk(x) && !is_disk(y) && !index_.inside(px, py)) {
          return result;
        }
        queue_around(g, x, y, add_node(px, py, r), replaced, in_void, walled);
        result.placed = true;
        return result;
      }
      if (move == 0) {
        result.blocker = d;
      }
      if (move == 0 && !walled && on_wall(d)) {
        moves = kWallCut;  // the boundary in the way: move to touch it
      }
      if (move == moves || d == x || d == y || !move_to_touch(d, r, x, y, px, py, replaced)) {
        return result;
      }
    }
    return result;
  }

  // After a disk n was placed in gap g touching x and y (g's elements, or after moves, with
  // `replaced` the parent the last move replaced): the gaps on both sides of n go on the front,
  // or are kept as voids, and the pockets the placement closed off are kept as voids.
  void queue_around(const Gap& g, std::int32_t x, std::int32_t y, std::int32_t n, std::int32_t replaced, bool in_void,
                    bool walled) {
    if (in_void && !walled && replaced == kNone && g.bound != kNone) {
      // A disk in a void leaves two smaller pockets, between it, a parent and the element
      // that bounded the void: kept as voids, not queued on the front, if that element
      // still bounds them below rmax. (Queued, 335k of them were tried on the 3 x 3 square
      // a layer later, when their neighbourhood had left the cache, and 10% took a disk.)
      // Not after a move: the new parent can be a wall cut in, and pocket_at_wall() does
      // not tell its sides apart.
      // Both pockets first, in one computation (pocket_pair()).
      const std::array<Gap, 2> split{Gap{x, n}, Gap{n, y}};
      const std::array<double, 2> caps = is_wall(g.bound)
                                             ? std::array<double, 2>{pocket(x, n, g.bound), pocket(n, y, g.bound)}
                                             : pocket_pair(x, n, y, g.bound);
      for (std::size_t i = 0; i < 2; ++i) {
        if (caps[i] >= 0 && caps[i] < frame_.rmax) {
          link(split[i]);
          keep_void(split[i], kClasses - 1, g.bound, caps[i]);
        } else {
          push_gap(split[i]);
        }
      }
    } else {
      push_gap(Gap{x, n});
      push_gap(Gap{n, y});
    }
    if (req_.fill_voids && replaced != kNone && !is_wall(x) && !is_wall(y) && worth_a_void(x, y)) {
      // The pocket on the far side of a pair from a move (cases (b)-(d)), bounded by the
      // parent the last move replaced, which lies there (bounded by n, 29k first tries of
      // these voids on the 3 x 3 square placed nothing, 95% of them blocked by that parent).
      // (The pocket behind a pair that made a gap is not kept: bounded by the element behind
      // their gap, 266k of them on the 3 x 3 square were tried 9.6k times, and the densities
      // stayed the same without them.)
      push_void(Gap{y, x}, kClasses - 1, replaced);
    }
    if (req_.fill_voids) {
      // The cusp between the new disk, a wall parent and the other parent.
      if (is_wall(x) && !is_wall(y)) {
        push_void(Gap{n, x}, kClasses - 1, y);
      } else if (is_wall(y) && !is_wall(x)) {
        push_void(Gap{y, n}, kClasses - 1, x);
      }
    }
    stats_.void_fills += in_void ? 1U : 0U;
  }

  // Moves candidate (px, py) of radius r, in the way of d, to touch d and one of its parents x and
  // y instead: d replaces the parent, which goes to `replaced`. False if there is no such position.
  bool move_to_touch(std::int32_t d, double r, std::int32_t& x, std::int32_t& y, double& px, double& py,
                     std::int32_t& replaced) {
    // Cases (b)-(d) by geometry: touch d and one of the parents instead, whichever of the
    // two positions is nearer the first.
    ++stats_.cuts;
    double ax = 0;
    double ay = 0;
    double bx = 0;
    double by = 0;
    const bool ok_a = tangent(x, d, r, ax, ay);
    const bool ok_b = tangent(d, y, r, bx, by);
    ++stats_.attempts;
    if (!ok_a && !ok_b) {
      return false;
    }
    const double da = ok_a ? (ax - px) * (ax - px) + (ay - py) * (ay - py) : INFINITY;
    const double db = ok_b ? (bx - px) * (bx - px) + (by - py) * (by - py) : INFINITY;
    if (da <= db) {
      replaced = y;
      y = d;
      px = ax;
      py = ay;
    } else {
      replaced = x;
      x = d;
      px = bx;
      py = by;
    }
    return true;
  }

  const FrontSettings& req_;
  const Polygon& polygon_;
  Rng& rng_;
  std::vector<Disk>& out_;
  FillStats& stats_;
  RunControl control_;
  std::size_t out_before_;  // out_.size() until the run moves the nodes out (placed())
  RunFrame frame_;
  OverlapTest overlap_;
  RadiusClasses<kClasses> classes_;
  Box box_;              // the polygon's box (local coordinates) grown by the clearance
  double estimate_ = 0;  // of the disks the box takes (estimate_disks())
  std::size_t fixed_bytes_ = 0;  // the grid's and the wall lists', for the memory limit
  double area_ = 0;
  double polygon_area_ = 0;  // shoelace, for the seeding rule
  int seeds_ = 0;

  std::vector<Wall> walls_;
  std::vector<Corner> corners_;    // node i < corners_.size() is reflex vertex i (radius 0)
  std::int32_t corner_count_ = 0;  // corners_.size()
  std::vector<Point> corner_at_;
  HugeVector<Node> nodes_;
  HugeVector<std::int32_t> before_;  // per disk: the first element of the last front gap with it second

  std::vector<Gap> fifo_;
  std::vector<Gap> wall_fifo_;  // gaps on a wall or a reflex vertex (grows with the perimeter only)
  std::size_t wall_head_ = 0;
  std::size_t head_ = 0;
  std::array<VoidBuckets<Gap, kClasses>, 2> voids_;  // [1]: on a rough wall

  CellGrid grid_;
  bool probes_inside_ = false;  // probe_col(), probe_row(): no clamping needed
  HugeVector<std::int32_t> head_cell_;
  WallIndex index_;
  std::vector<std::size_t> ring_first_;  // the first wall of each ring
  std::vector<std::uint8_t> rough_;
  bool any_rough_ = false;  // a rough wall exists (else no void is kept on side 1)
};

}  // namespace

FrontResult advance_boundary(const FrontSettings& settings, const Polygon& polygon, Rng& rng, std::vector<Disk>& out,
                             FillStats& stats) {
  BoundaryFront front(settings, polygon, rng, out, stats);
  return front.run();
}

}  // namespace frontpack::detail
