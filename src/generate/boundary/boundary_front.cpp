// The boundary-conforming advancing front (generate/boundary/boundary_front.hpp): the open form's walls (Sec. 3)
// generalised to every edge of every ring, with reflex vertices as zero-radius obstacles; the
// front, kept as unlinked gaps, starts at the corners of every ring and advances inwards; cases
// (b)-(d) of Sec. 2.2 are decided by geometry (a move to touch the element in the way); the voids
// the front leaves (Sec. 2.2's holes) take later, smaller disks, bucketed by the Apollonius
// pocket each can hold. Element ids: a node (disk or reflex vertex) is >= 0, wall e is -(e + 1).
// This file is the driver: the gaps and voids, and a try at a gap (cases (a)-(d)). Where the front
// starts: seeding.hpp; the elements and the positions touching two of them: elements.hpp; what a
// candidate runs into: obstacles.hpp; what a void can still take: pocket.hpp.
// The method, what it guarantees and where it deviates from the paper, and why:
// docs/boundary-method.md. Its density: docs/density.md; its cost: docs/performance.md.
#include "generate/boundary/boundary_front.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <optional>
#include <utility>

#include "common/packing_density.hpp"
#include "generate/acceptance.hpp"
#include "generate/boundary/cavities.hpp"
#include "generate/boundary/elements.hpp"
#include "generate/boundary/obstacles.hpp"
#include "generate/boundary/pocket.hpp"
#include "generate/boundary/rules.hpp"
#include "generate/boundary/seeding.hpp"
#include "generate/boundary/slide.hpp"
#include "generate/boundary/wall_index.hpp"
#include "generate/boundary/walls.hpp"
#include "generate/run_control.hpp"
#include "generate/void_buckets.hpp"

namespace frontpack::detail {

namespace {

using namespace boundary_rules;  // NOLINT(google-build-using-namespace): the rules are this file's
constexpr std::int32_t kNone = kNoElement;

// Voids are part of the method: fill() refuses FillOptions::fill_voids = false for it (without
// them every gap a drawn radius did not fit was dropped, and the packing kept large empty areas).
class BoundaryFront {
 public:
  BoundaryFront(const FrontSettings& req, const Polygon& polygon, Rng& rng, std::vector<Disk>& out)
      : req_(req),
        rng_(rng),
        out_(out),
        control_(req.max_disks, req.tick),
        out_before_(out.size()),
        frame_(*req.radii, req.clearance, outer_box(polygon)),
        cell_(outer_box(polygon)),
        elements_(frame_),
        obstacles_(frame_, report_.exact_checks) {
    box_ = Box{-frame_.clearance, -frame_.clearance, frame_.width + frame_.clearance, frame_.height + frame_.clearance};
    classes_ = RadiusClasses<kClasses>(frame_.rmin, frame_.rmax);
    close_below_ = close_below(frame_.rmin, frame_.rmax);

    const double estimate = estimate_disks(outer_box(polygon), *req.radii);
    // (Every disk lies in the polygon: at most its box's area, bound_disks(), 1.18 estimates.)
    elements_.reserve(count_of(estimate * 1.3 + 64, 1e9));
    const bool periodic = req.periodicity != Periodicity::none;
    if (periodic) {
      elements_.set_periodic(PeriodicWrap{true, req.periodicity == Periodicity::xy, frame_.width, frame_.height});
    }
    Seeding seeding = periodic ? seed_periodic_cell(frame_, req.periodicity) : seed_at_corners(polygon, frame_);
    ring_first_ = std::move(seeding.ring_first);
    rough_ = std::move(seeding.rough);
    any_rough_ = seeding.any_rough;
    polygon_area_ = seeding.area;
    elements_.set_boundary(std::move(seeding.walls), std::move(seeding.corners), seeding.corner_at);
    for (const Gap& g : seeding.gaps) {
      push_gap(g);
    }
    const SetupBudget budget{req_.memory_limit, estimate};
    fixed_bytes_ = obstacles_.set_up(elements_.walls(), frame_, budget);
    if (req.periodicity == Periodicity::xy) {
      obstacles_.set_periodic(-INFINITY, INFINITY);
    } else if (periodic) {
      obstacles_.set_periodic(0, frame_.height);
    }
    if (req_.memory_limit != 0) {
      budget.check(fixed_bytes_, "the grid and the lists of the walls near its cells");
      control_.limit_memory(req_.memory_limit - fixed_bytes_, req_.bytes_per_disk);
    }
  }

  FrontReport run() {
    double r = draw();
    int cls = class_of(r);  // r's void class (r stays until it is placed)
    for (;;) {
      if (control_.stop(placed(), area_ * frame_.unit.inv_k * frame_.unit.inv_k, report_)) {
        break;
      }
      Gap g{kNone, kNone};
      bool in_void = false;
      const Next next = next_gap(cls, g, in_void);
      if (next == Next::none) {
        const Done d = front_done(r);
        if (d == Done::end) {
          break;
        }
        if (d == Done::next_radius) {
          r = draw();
          cls = class_of(r);
        }
        continue;
      }
      if (next == Next::gap) {
        try_and_keep(g, in_void, r, cls);
      }
    }
    finish();
    return report_;
  }

 private:
  enum class Next : std::uint8_t { gap, overtaken, none };
  // The gap to try r of class cls in next: voids first, those on a rough wall before the others,
  // the tightest class whose radii all exceed r, the most recent void in it (in_void); then the
  // first layer along every wall; then the front. An overtaken front gap is kept as a void
  // (overtaken). none: the front is done and no void can take r.
  Next next_gap(int cls, Gap& g, bool& in_void) {
    int k = any_rough_ ? voids_[1].first_above(cls) : -1;
    std::size_t side = 1;
    if (k < 0) {
      k = voids_[0].first_above(cls);
      side = 0;
    }
    in_void = k >= 0;
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
        push_void(g, kClasses - 1, o);
        return Next::overtaken;
      }
    } else {
      return Next::none;
    }
    return Next::gap;
  }

  enum class Done : std::uint8_t { next_radius, same_radius, end };
  // The front is done and no void can take r. If the walls could not start a front (a boundary
  // rougher than the smallest disk: nothing fits in its corners) and the polygon is far from full,
  // a seed pair of disks starts one inside, growing outwards. Otherwise r is skipped while voids
  // are left, up to one radius in kSkipPer placed, and then the run ends. (Skipping without a
  // bound fills every void, but only by distorting the size distribution towards small radii:
  // uniform 1:10 packed 0.894 with a KS by area of 0.028.)
  Done front_done(double r) {
    if (seed(r)) {
      area_ += r * r;
      return Done::next_radius;
    }
    if (!cavities_searched_) {
      cavities_searched_ = true;
      if (find_cavities()) {
        return Done::same_radius;
      }
    }
    if (skipped_ < (placed() - out_before_) / kSkipPer && !(voids_[0].empty() && voids_[1].empty())) {
      // The voids left where the fronts met last (a seam of 0.71 against 0.87 around) take
      // the radii that fit them; a radius that fits none is skipped, up to 1 in kSkipPer.
      ++skipped_;
      ++report_.skipped_radii;
      return Done::next_radius;
    }
    return Done::end;
  }

  // Tries r at gap g; placed, the next radius is drawn, else the gap may still take a smaller
  // disk, at most as large as the pocket between its elements and the disk in the way.
  void try_and_keep(Gap g, bool in_void, double& r, int& cls) {
    if (const GapTry t = try_gap(g, r, in_void); t.placed) {
      area_ += r * r;
      r = draw();
      cls = class_of(r);
    } else if (cls > 0 && !t.hopeless) {
      if (t.capped) {
        keep_void(g, cls, t.blocker, t.cap);
      } else {
        push_void(g, cls, t.blocker);
      }
    }
  }

  // The front, the voids and the grid are done with: free them before the output grows (peak
  // memory: the nodes and the output are then all that is left).
  void finish() {
    release(fifo_);
    release(wall_fifo_);
    for (auto& side : voids_) {
      side.release();
    }
    elements_.release_links();
    obstacles_.release();
    elements_.move_out(frame_.origin, frame_.unit.inv_k, out_, cell_);
    report_.fixed_bytes = fixed_bytes_;
  }

  [[nodiscard]] std::size_t placed() const noexcept {
    return elements_.size() - static_cast<std::size_t>(elements_.corner_count()) - elements_.images() + out_before_;
  }
  [[nodiscard]] const PeriodicWrap& wrap() const noexcept { return elements_.wrap(); }
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
    if (is_disk(g.a) && elements_.after(g.a) != g.b) {
      return elements_.after(g.a);
    }
    if (is_disk(g.b) && elements_.before(g.b) != g.a) {
      return elements_.before(g.b);
    }
    return kNone;
  }
  [[nodiscard]] bool fifo_empty() const noexcept { return head_ == fifo_.size() && wall_head_ == wall_fifo_.size(); }
  [[nodiscard]] bool on_wall(std::int32_t e) const noexcept { return elements_.on_wall(e); }  // a wall or a corner
  // Records gap g as the last one with its first disk first and its second disk second
  // (overtaker()).
  void link(Gap g) noexcept { elements_.link(g.a, g.b); }
  void push_gap(Gap g) {
    link(g);
    if (on_wall(g.a) || on_wall(g.b)) {
      wall_fifo_.push_back(g);
    } else {
      fifo_.push_back(g);
    }
  }
  [[nodiscard]] static bool is_wall(std::int32_t e) noexcept { return Elements::is_wall(e); }
  [[nodiscard]] bool is_disk(std::int32_t e) const noexcept { return elements_.is_disk(e); }
  [[nodiscard]] int class_of(double r) const noexcept { return classes_.of(r); }
  double draw() { return frame_.draw(rng_); }

  // ------------------------------------------------------------------------------------------
  // The elements (elements.hpp) and what is in a candidate's way (obstacles.hpp).

  // A new disk at (x, y), a candidate that passed the box test. In a periodic cell, brought into
  // the cell, with images within kImageReach rmax of it: a probe in the cell scans r + rmax and a
  // few clearances (deepest()), the cavity pass's nearest_disks() 3 rmax.
  static constexpr double kImageReach = 3;
  std::int32_t add_node(double x, double y, double r) {
    if (wrap().any()) {
      x = wrap().wrap_x(x);
      y = wrap().wrap_y(y);
    }
    const auto id = static_cast<std::int32_t>(elements_.size());
    const std::int32_t n = elements_.add_disk(x, y, r, obstacles_.enter(id, x, y));
    if (wrap().any()) {
      elements_.add_images(
          n, kImageReach * frame_.rmax + 2 * frame_.clearance,
          [this](std::int32_t image, double ix, double iy) { return obstacles_.enter(image, ix, iy); });
    }
    return n;
  }
  [[nodiscard]] Probe probe(double x, double y, double r) const noexcept { return obstacles_.probe(x, y, r); }
  bool tangent(std::int32_t a, std::int32_t b, double r, double& px, double& py) const noexcept {
    return elements_.tangent(a, b, r, px, py);
  }

  // Keeps gap g as a void for radii below class k, and below the pocket left by `blocker`.
  void push_void(Gap g, int k, std::int32_t blocker) {
    keep_void(g, k, blocker, blocker != kNone ? pocket(elements_, g.a, g.b, blocker) : -1);
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

  // Cavities the fronts closed around (cavities.hpp): each point found gets a void. Returns
  // whether one was kept.
  bool find_cavities() {
    const std::vector<Gap> found = cavity_gaps(obstacles_, elements_, frame_, placed() - out_before_, req_.stop);
    for (const Gap& g : found) {
      keep_void(g, kClasses - 1, kNone, -1);
    }
    report_.cavities += found.size();
    return !found.empty();
  }

  // ------------------------------------------------------------------------------------------
  // Seeds: two touching disks (r and a second drawn radius) at a point inside the polygon where
  // they fit (seed_pair_at()), with the gaps on both sides of the pair. Tried only while the disks
  // cover less than half of what a dense packing would, at most kSeeds times. Returns whether the
  // pair was placed.
  static constexpr int kSeeds = 16;

  bool seed(double r) {
    if (seeds_ >= kSeeds || std::numbers::pi * area_ >= 0.5 * kRandomDenseFraction * polygon_area_) {
      return false;
    }
    ++seeds_;
    const double r2 = draw();
    // In a periodic cell, the pair (side by side in x) must clear its own images: a cell narrower
    // than that, or a clearance near its size (coordinates whose ulps near the cell's size), gets no
    // seed. (fill() requires 10 rmax; the fill fuzzer found such a cell far from the origin.)
    const double c = frame_.clearance;
    if ((wrap().x && !(2 * (r + r2 + c) <= frame_.width)) ||
        (wrap().y && !(2 * std::max(r, r2) + c <= frame_.height))) {
      return false;
    }
    if (seeds_ == 1 && wrap().x && !wrap().y) {
      return seed_walls(r, r2);
    }
    // A torus's first pair lies at the cell's centre (nothing else is there yet), so that the front
    // meets itself along the sides x = 0 and y = 0, as the closed form's does (Sec. 2.1).
    const std::optional<Point> at =
        seeds_ == 1 && wrap().y
            ? std::optional<Point>{Point{(frame_.width - r - r2 - frame_.clearance) / 2, frame_.height / 2}}
            : seed_pair_at(obstacles_, elements_, frame_, rng_, r, r2);
    if (!at) {
      return false;
    }
    const std::int32_t a = add_node(at->x, at->y, r);
    const std::int32_t b = add_node(at->x + r + r2 + frame_.clearance, at->y, r2);
    area_ += r2 * r2;
    push_gap(Gap{a, b});
    push_gap(Gap{b, a});
    return true;
  }

  // A shear cell's first disks (seed_on_walls()), each with a gap before and after it along its
  // wall: the first layer grows along each wall both ways, around the cell.
  bool seed_walls(double r, double r2) {
    const std::array<std::optional<Point>, 2> at = seed_on_walls(frame_, rng_, r, r2);
    for (std::size_t k = 0; k < 2; ++k) {
      if (at[k]) {
        const std::int32_t n = add_node(at[k]->x, at[k]->y, k == 0 ? r : r2);
        area_ += k == 1 ? r2 * r2 : 0;
        push_gap(Gap{wall_id(k), n});
        push_gap(Gap{n, wall_id(k)});
      }
    }
    return at[0].has_value();
  }

  // ------------------------------------------------------------------------------------------
  // Placing a disk of radius r in gap g.

  // Whether the pocket behind parents x and y (disks or reflex vertices) that a move (cases
  // (b)-(d)) brought together is worth keeping as a void. Behind them lies the element the move
  // replaced; their pocket rarely takes a disk, and beyond 4 rmin almost never: on the 3 x 3
  // square such voids were tried 178k times for 3k disks (1 in 67k beyond 8 rmin).
  [[nodiscard]] bool worth_a_void(std::int32_t x, std::int32_t y) const noexcept {
    const BoundaryNode& a = elements_.node(x);
    const BoundaryNode b = elements_.near(y, a);
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
    bool capped = false;           // cap computed: the pocket the blocker leaves (pocket())
    double cap = -1;
  };

  GapTry try_gap(const Gap& g, double r, bool in_void) {
    GapTry result;
    std::int32_t x = g.a;
    std::int32_t y = g.b;
    double px = 0;
    double py = 0;
    ++report_.attempts;
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
      slide(elements_, obstacles_, ring_first_, x, y, r, px, py);
      if (wrap().any()) {
        // A periodic cell: the candidate brought into it (where its images' neighbours are).
        px = wrap().wrap_x(px);
        py = wrap().wrap_y(py);
      }
      const bool in_x = wrap().x || (px - r >= box_.xmin && px + r <= box_.xmax);
      const bool in_y = wrap().y || (py - r >= box_.ymin && py + r <= box_.ymax);
      if (!(in_x && in_y)) {
        return result;  // outside the polygon's box, so outside the polygon
      }
      const Probe p = probe(px, py, r);
      // At the last move, only whether anything is in the way matters (but not at the first: the
      // element it finds bounds the void the gap leaves, the deepest one if the grid is scanned).
      // In the interior, the disks most often in the way are tried before the scan (in_the_way()).
      const Gap first{x, y};
      const std::int32_t d = elements_.real(
          move == moves && move > 0 ? obstacles_.deepest<true>(elements_, p)
                                    : obstacles_.deepest(elements_, p, move == 0 && !walled ? &first : nullptr));
      if (d == kNone) {
        if (!elements_.supported_by(x, px, py) || !elements_.supported_by(y, px, py)) {
          return result;
        }
        // Touching a disk, a candidate that crosses no wall is inside: the two disks cover the
        // segment between their centres. Touching only walls and reflex vertices, it can lie
        // wholly outside where the domain is thinner than the clearance (a spike two edges a few
        // ulps apart): its centre must then be inside.
        if (!is_disk(x) && !is_disk(y) && !obstacles_.inside(px, py)) {
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
      } else if (move == 0 && !walled && !in_void && frame_.rmin < frame_.rmax) {
        // A front gap blocked by a disk: kept as a void if some radius fits its pocket, else
        // closed over the disk (kClose).
        result.capped = true;
        result.cap = pocket(elements_, x, y, d);
        if (result.cap < close_below_) {
          moves = kClose;
        }
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
      const std::array<double, 2> caps =
          is_wall(g.bound) ? std::array<double, 2>{pocket(elements_, x, n, g.bound), pocket(elements_, n, y, g.bound)}
                           : pocket_pair(elements_, x, n, y, g.bound);
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
    if (replaced != kNone && !is_wall(x) && !is_wall(y) && worth_a_void(x, y)) {
      // The pocket on the far side of a pair from a move (cases (b)-(d)), bounded by the
      // parent the last move replaced, which lies there (bounded by n, 29k first tries of
      // these voids on the 3 x 3 square placed nothing, 95% of them blocked by that parent).
      // (The pocket behind a pair that made a gap is not kept: bounded by the element behind
      // their gap, 266k of them on the 3 x 3 square were tried 9.6k times, and the densities
      // stayed the same without them.)
      push_void(Gap{y, x}, kClasses - 1, replaced);
    }
    // The cusp between the new disk, a wall parent and the other parent.
    if (is_wall(x) && !is_wall(y)) {
      push_void(Gap{n, x}, kClasses - 1, y);
    } else if (is_wall(y) && !is_wall(x)) {
      push_void(Gap{y, n}, kClasses - 1, x);
    }
    report_.void_fills += in_void ? 1U : 0U;
  }

  // Moves candidate (px, py) of radius r, in the way of d, to touch d and one of its parents x and
  // y instead: d replaces the parent, which goes to `replaced`. False if there is no such position.
  bool move_to_touch(std::int32_t d, double r, std::int32_t& x, std::int32_t& y, double& px, double& py,
                     std::int32_t& replaced) {
    // Cases (b)-(d) by geometry: touch d and one of the parents instead, whichever of the
    // two positions is nearer the first.
    ++report_.cuts;
    double ax = 0;
    double ay = 0;
    double bx = 0;
    double by = 0;
    const bool ok_a = tangent(x, d, r, ax, ay);
    const bool ok_b = tangent(d, y, r, bx, by);
    ++report_.attempts;
    if (!ok_a && !ok_b) {
      return false;
    }
    // (In a periodic cell the shortest displacement: the positions are each near their parents.)
    const PeriodicWrap& w = wrap();
    const double da = ok_a ? w.dx(ax - px) * w.dx(ax - px) + w.dy(ay - py) * w.dy(ay - py) : INFINITY;
    const double db = ok_b ? w.dx(bx - px) * w.dx(bx - px) + w.dy(by - py) * w.dy(by - py) : INFINITY;
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
  Rng& rng_;
  std::vector<Disk>& out_;
  FrontReport report_;  // counters and why the run stopped: what run() returns
  RunControl control_;
  std::size_t out_before_;  // out_.size() until the run moves the nodes out (placed())
  RunFrame frame_;
  RadiusClasses<kClasses> classes_;
  Box box_;                      // the polygon's box (local coordinates) grown by the clearance
  Box cell_;                     // the polygon's box (a periodic cell's bounds, for keep_in_cell())
  double close_below_ = 0;       // an interior front gap closes over a blocker whose pocket is below this
  std::size_t fixed_bytes_ = 0;  // the grid's and the wall lists', for the memory limit
  double area_ = 0;
  double polygon_area_ = 0;  // shoelace, for the seeding rule
  int seeds_ = 0;
  std::size_t skipped_ = 0;
  bool cavities_searched_ = false;

  Elements elements_;  // walls, reflex vertices, disks

  std::vector<Gap> fifo_;
  std::vector<Gap> wall_fifo_;  // gaps on a wall or a reflex vertex (grows with the perimeter only)
  std::size_t wall_head_ = 0;
  std::size_t head_ = 0;
  std::array<VoidBuckets<Gap, kClasses>, 2> voids_;  // [1]: on a rough wall

  Obstacles obstacles_;                  // the grid and the wall lists
  std::vector<std::size_t> ring_first_;  // the first wall of each ring
  std::vector<std::uint8_t> rough_;
  bool any_rough_ = false;  // a rough wall exists (else no void is kept on side 1)
};

}  // namespace

FrontReport advance_boundary(const FrontSettings& settings, const Polygon& polygon, Rng& rng, std::vector<Disk>& out) {
  BoundaryFront front(settings, polygon, rng, out);
  return front.run();
}

}  // namespace frontpack::detail
