// The advancing front (Feng, Han & Owen 2003, "Filling domains with disks: an advancing front
// approach", IJNME 56:699-713). Section numbers refer to the paper; deviations say why.
//
// Data layout. Every placed disk is a node; in the open form nodes 0, 1, 2 are the walls Bl, Bb,
// Br (disks of infinite radius, Sec. 3). The front is a doubly linked list of nodes (next_/prev_),
// closed in both forms: the open form's list Bl -> ... -> Br is closed by a link Br -> Bl that is
// never a segment. A segment is identified by its first node s (s -> next_[s]).
//
// Overlap detection. The paper checks the new disk against at most M front disks on either side
// of the active segment (Sec. 2.4.3), which misses overlaps with disks further along the front or
// already enclosed by it. Here a uniform grid over all placed disks proves a candidate clear
// (case (a)); when something is in the way, the window walk, as in the paper, decides cases
// (b)-(d). An overlap the walk does not reach (beyond M, or enclosed) retires the segment
// ("blocked"), so the generator never emits an overlap and every step makes progress.

#include "generate/paper_front.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>

#include "generate/cell_grid.hpp"
#include "common/huge_pages.hpp"
#include "common/packing_density.hpp"
#include "exact/overlap.hpp"

namespace frontpack::detail {

double estimate_disks(const Box& box, const RadiusDistribution& radii) {
  // At the estimate's density (common/packing_density.hpp).
  const double mean_square = radii.mean_square();
  const double estimate = kEstimateFraction * box.width() * box.height() / (std::numbers::pi * mean_square);
  if (mean_square >= std::numeric_limits<double>::min() && !std::isnan(estimate)) {
    return estimate;  // E[r^2] normal: the figure is accurate (or 0, or saturated to infinity)
  }
  // E[r^2] underflows (radii below about 1e-154; 0 / 0 for a box as small) or is not a number:
  // the same figure at the scale of rmax (a power of two: exact), with E[(k r)^2] from the
  // quantiles at 1024 midpoints, since mean_square() has lost it.
  const LengthScale scale(radii.max());
  double sum = 0;
  constexpr int kPoints = 1024;
  for (int i = 0; i < kPoints; ++i) {
    const double r = scale.k * radii.quantile((i + 0.5) / kPoints);
    sum += r * r;
  }
  const double scaled_mean_square = sum / kPoints;
  if (!(scaled_mean_square > 0)) {
    return std::numeric_limits<double>::infinity();  // radii too small to square even at their scale
  }
  const double scaled = kEstimateFraction * (box.width() * scale.k) * (box.height() * scale.k) / (std::numbers::pi * scaled_mean_square);
  return std::isnan(scaled) ? std::numeric_limits<double>::infinity() : scaled;
}

double bound_disks(const Box& box, double grow, const RadiusDistribution& radii) {
  const Box grown{box.xmin - grow, box.ymin - grow, box.xmax + grow, box.ymax + grow};
  return estimate_disks(grown, radii) / kEstimateFraction;
}

void throw_memory_limit(std::size_t limit, const std::string& what, std::size_t estimate) {
  throw LimitError("the run would need more than the memory limit of " + std::to_string(limit) + " bytes: " + what +
                       "; raise memory_limit (frontpack fill --memory-limit) or use larger radii",
                   estimate);
}

namespace {

constexpr std::int32_t kNone = -1;
constexpr std::int32_t kLeft = 0;    // Bl
constexpr std::int32_t kBottom = 1;  // Bb
constexpr std::int32_t kRight = 2;   // Br
constexpr std::int32_t kFirstDisk = 3;
constexpr double kListAspect = 4;  // see Front::link
constexpr int kVoidClasses = 16;   // void buckets (log-spaced radius classes), see Front::cut

template <bool Open>
class Front {
  // One record per node, so that an overlap test touches one cache line (aligned to its size: the
  // standard allocator's large blocks start 16 bytes into a line, where every other record would
  // straddle two).
  struct alignas(32) Node {
    double x, y, r;
    std::int32_t cell_next;  // next node in the same grid cell
    std::uint8_t inside;     // centre in the box (the bottom wall counts as inside, side walls not)
    std::uint8_t blocked;    // the segment starting here is retired
  };
  static_assert(sizeof(Node) == 32);

 public:
  Front(const FrontRequest& req, Rng& rng, std::vector<Disk>& out, FillStats& stats)
      : req_(req), rng_(rng), out_(out), stats_(stats), control_(req.max_disks, req.tick) {
    // Work in coordinates local to the box's lower-left corner, so that a translated domain
    // gives the same computation (and small numbers for domains far from the origin).
    // And in the unit of WorkScale (1 but for rmax outside [2^-300, 2^300]).
    unit_ = WorkScale(req.radii->max());
    origin_ = Point{req.box.xmin, req.box.ymin};
    box_ = Box{0, 0, (req.box.xmax - origin_.x) * unit_.k, (req.box.ymax - origin_.y) * unit_.k};
    rmax_ = req.radii->max() * unit_.k;
    clearance_ = req.clearance * unit_.k;
    scale_ = LengthScale(rmax_);
    margin_ = clearance_ / 2;
    band_ = clearance_ / 4;
    window_ = req.window == 0 ? std::numeric_limits<std::size_t>::max() : req.window;
    const double long_side = std::max(box_.width(), box_.height());
    const double short_side = std::min(box_.width(), box_.height());
    list_ = !Open && !(long_side <= kListAspect * short_side);  // NaN-safe: a degenerate box lists
    fill_voids_ = req.fill_voids;
    classes_ = RadiusClasses<kVoidClasses>(req.radii->min() * unit_.k, rmax_);

    // The memory limit: the grid's cell heads, then peak_bytes_per_disk per disk generated.
    grid_ = CellGrid(box_.xmin, box_.ymin, box_.width(), box_.height(), rmax_);
    const std::size_t grid_bytes = grid_.cells() * sizeof(std::int32_t);
    if (req.memory_limit != 0) {
      if (grid_bytes >= req.memory_limit) {
        throw_memory_limit(req.memory_limit,
                           "the grid over a polygon's box (" + std::to_string(grid_.cells()) + " cells) takes " +
                               std::to_string(grid_bytes) + " bytes",
                           count_of(estimate_disks(req.box, *req.radii), 1e18));
      }
      control_.limit_memory(req.memory_limit - grid_bytes);
    }
    fixed_bytes_ = grid_bytes;

    const double estimate = estimate_disks(req.box, *req.radii);
    // Room for every disk the front can make: each lies within 5 rmax and two clearances of the
    // box (a disk on the front within 2 rmax and a clearance of a centre in the box, one in a void
    // within as much again of the front's), bound_disks(). A vector that outgrew its reservation
    // held its old and its new array at once, 96 bytes per node (an open form on a 1e-7 high
    // sliver generated 1.7 times the estimate and took 1.3 GB). Reserved pages cost nothing until
    // written; the disk budget (max_disks, the memory limit) caps it.
    const double bound = bound_disks(req.box, 5 * req.radii->max() + 2 * req.clearance, *req.radii);
    const double room = static_cast<double>(control_.budget() - std::min(control_.budget(), out_.size()));
    const std::size_t reserve =
        count_of(std::min(std::max(std::isfinite(bound) ? bound * 1.1 : 0.0, estimate * 1.3), room) + 64, 1e9);
    nodes_.reserve(reserve + kFirstDisk);
    {  // In one call, the pages of the nodes this box is expected to take (common/huge_pages.hpp).
      const double budget =
          req.max_disks == 0 ? estimate : static_cast<double>(req.max_disks - std::min(req.max_disks, out_.size()));
      const double expected = std::min(std::min(estimate, budget) + kFirstDisk, static_cast<double>(nodes_.capacity()));
      prefault(nodes_, expected >= 0 ? static_cast<std::size_t>(expected) : 0);
    }
    next_.reserve(reserve + kFirstDisk);
    prev_.reserve(reserve + kFirstDisk);
    if (list_) {
      anext_.reserve(reserve + kFirstDisk);
      aprev_.reserve(reserve + kFirstDisk);
    }
    setup_grid();
  }

  FrontResult run() {
    FrontResult result;
    // Walls (open form) or placeholders (closed form) occupy nodes 0..2.
    for (std::int32_t w = 0; w < kFirstDisk; ++w) {
      add_node(0, 0, std::numeric_limits<double>::infinity());
    }
    std::int32_t cur = Open ? start_open() : start_closed();
    if (cur == kNone) {
      return result;
    }
    double r = draw();
    std::size_t skips = 0;
    while (active_ > 0 && skips <= front_size_ + 1) {
      if (control_.stop(placed(), area_ * unit_.inv_k * unit_.inv_k, result)) {
        break;
      }
      if (!segment_active(cur)) {
        cur = advance(cur);
        ++skips;
        continue;
      }
      skips = 0;
      if (vmask_ != 0 && try_voids(r)) {
        area_ += r * r;
        r = draw();
        continue;
      }
      const std::int32_t placed_node = place_on(cur, r);
      if (placed_node == kNone) {
        cur = first_active_from(advance(retired_));  // the radius stays for the next segment
        continue;
      }
      area_ += r * r;
      r = draw();
      // Visit order. Closed form (Fig. 4): after D4 on D1 -> D2, the next segment is D2 -> D3,
      // the one after the new disk's. Open form (Sec. 3): along the layer (D1 -> Bb after D1),
      // and back to Bl -> first disk once a layer reaches the right wall.
      const std::int32_t n = next_[static_cast<std::size_t>(placed_node)];
      if constexpr (Open) {
        cur = n == kRight ? kLeft : placed_node;
      } else {
        cur = first_active_from(n);
      }
    }
    // The front and the grid are done with: free them before the output grows (peak memory).
    release(next_);
    release(prev_);
    release(anext_);
    release(aprev_);
    release(head_);
    for (auto& v : voids_) {
      release(v);
    }
    move_out(nodes_, kFirstDisk, origin_, unit_.inv_k, out_);
    result.fixed_bytes = fixed_bytes_;
    return result;
  }

 private:
  // ------------------------------------------------------------------------------------------
  // Nodes, the grid over placed disks.

  [[nodiscard]] std::size_t placed() const noexcept { return nodes_.size() - kFirstDisk + out_.size(); }

  [[gnu::always_inline]] std::int32_t add_node(double x, double y, double r) {
    const auto id = static_cast<std::int32_t>(nodes_.size());
    std::int32_t link_to = kNone;
    if (id >= kFirstDisk) {
      const std::size_t c = cell_of(x, y);
      link_to = head_[c];
      head_[c] = id;
    }
    const bool in =
        id >= kFirstDisk ? (x >= box_.xmin && x <= box_.xmax && y >= box_.ymin && y <= box_.ymax) : id == kBottom;
    nodes_.push_back(Node{x, y, r, link_to, static_cast<std::uint8_t>(in ? 1 : 0), 0});
    next_.push_back(kNone);
    prev_.push_back(kNone);
    if (list_) {
      anext_.push_back(kNone);
      aprev_.push_back(kNone);
    }
    return id;
  }

  void setup_grid() { head_.assign(grid_.cells(), kNone); }  // (grid_ is set up in the constructor)

  [[nodiscard]] std::int64_t col(double x) const noexcept { return grid_.col(x); }
  [[nodiscard]] std::int64_t row(double y) const noexcept { return grid_.row(y); }
  [[nodiscard]] std::size_t cell_of(double x, double y) const noexcept { return grid_.cell_of(x, y); }

  [[nodiscard]] Probe probe(double x, double y, double r) const noexcept { return Probe::at(x, y, r, margin_, band_); }

  // Whether the candidate comes closer to disk o than r + o.r + margin: "overlaps" for the
  // generator. The margin (half the clearance) keeps every accepted pair apart by more than the
  // rounding of the output (box corner + local position) can take away, so that no pair overlaps
  // in the coordinates written out; tangent placements, at the full clearance, always pass.
  // Outside a narrow band around that distance floating point decides; inside it, the exact
  // predicate does.
  bool overlaps(const Probe& p, const Node& o) {
    const double dx = p.x - o.x;
    const double dy = p.y - o.y;
    const double d2 = dx * dx + dy * dy;
    const double hi = p.r_hi + o.r;
    if (d2 >= hi * hi) {
      return false;
    }
    const double lo = p.r_lo + o.r;
    if (lo > 0 && d2 < lo * lo) {
      return true;
    }
    return overlaps_exact(p, o);
  }

  // Out of line, so that the scan loops keep the disks they test in registers (inlined, the
  // call's arguments made them copy every disk to the stack).
  [[gnu::noinline, gnu::cold]] bool overlaps_exact(const Probe& p, const Node& o) {
    ++stats_.exact_checks;
    return disks_closer_than_exact({p.x, p.y}, p.r, {o.x, o.y}, o.r, margin_);
  }

  // Whether a disk at (x, y, r) crosses wall w (open form). A disk within the band of a wall
  // counts as crossing it: walls only guide the generator; containment in the domain is decided
  // exactly by the certifier.
  [[nodiscard]] bool crosses_wall(std::int32_t w, double x, double y, double r) const noexcept {
    switch (w) {
      case kLeft: return x - r < box_.xmin + band_;
      case kRight: return x + r > box_.xmax - band_;
      default: return y - r < box_.ymin + band_;
    }
  }

  // Whether a disk at (x, y, r) overlaps front node v (a disk or a wall).
  bool overlaps_node(const Probe& p, std::int32_t v) {
    return is_wall(v) ? Open && crosses_wall(v, p.x, p.y, p.r) : overlaps(p, nodes_[static_cast<std::size_t>(v)]);
  }

  // Whether a disk at (x, y, r) overlaps any placed disk or any wall, other than walls c and n.
  // The grid scan covers only the cells that the box of possible overlaps spans: overlaps() can
  // say yes for a disk d only if |x - x_d| < r_hi + r_d <= r_hi + rmax (r_hi = r + 3/4 of the
  // clearance); the reach is padded so that rounding cannot lose a cell. Walls are obstacles
  // whether or not they are on the front. The candidate's parent disks need no skipping: it
  // touches them at the full clearance, outside the band where overlaps() can say yes.
  bool overlaps_anything(const Probe& p, std::int32_t c, std::int32_t n) {
    const double x = p.x;
    const double y = p.y;
    const double r = p.r;
    if constexpr (Open) {
      const bool clear_of_walls =
          x - r >= box_.xmin + band_ && x + r <= box_.xmax - band_ && y - r >= box_.ymin + band_;
      if (!clear_of_walls) {  // most candidates are: one test for the three walls
        for (const std::int32_t w : {kLeft, kBottom, kRight}) {
          if (w != c && w != n && crosses_wall(w, x, y, r)) {
            return true;
          }
        }
      }
    }
    const double reach = (p.r_hi + rmax_) * (1 + 1e-9);
    const std::int64_t c0 = col(x - reach);
    const std::int64_t c1 = col(x + reach);
    const std::int64_t r0 = row(y - reach);
    const std::int64_t r1 = row(y + reach);
    return visit_cells(head_.data(), grid_.nx, nodes_.data(), kNone, c0, c1, r0, r1,
                       [&](std::int32_t /*d*/, const Node& o) { return overlaps(p, o); });
  }

  // ------------------------------------------------------------------------------------------
  // Tangent positions. The new disk goes on the free side of the segment c -> n: the right in
  // the closed form (Sec. 2.1: "placed on the right-hand side"), the left in the open form (its
  // front runs left to right below the free region). Distances include the clearance.

  [[nodiscard]] static bool is_wall(std::int32_t id) noexcept { return id < kFirstDisk; }

  // Inward normal and offset of a wall line: points p inside satisfy dot(n, p) >= w.
  struct Wall {
    double nx, ny, w;
  };
  [[nodiscard]] Wall wall(std::int32_t id) const noexcept {
    switch (id) {
      case kLeft: return {1, 0, box_.xmin};
      case kRight: return {-1, 0, -box_.xmax};
      default: return {0, 1, box_.ymin};
    }
  }

  bool tangent(std::int32_t c, std::int32_t n, double r, double& px, double& py, bool left = Open) const {
    const double gap = r + clearance_;
    if (!is_wall(c) && !is_wall(n)) {
      const Node& cn = nodes_[static_cast<std::size_t>(c)];
      const Node& nn = nodes_[static_cast<std::size_t>(n)];
      // Left (open form) or right (closed form) of c -> n.
      return tangent_to_two(cn.x, cn.y, cn.r + gap, nn.x, nn.y, nn.r + gap, left, scale_, px, py);
    }
    if (is_wall(c) && is_wall(n)) {
      // A corner of two walls (Sec. 3: D1 in the corner of Bl and Bb).
      const bool right = c == kRight || n == kRight;
      px = right ? box_.xmax - gap : box_.xmin + gap;
      py = box_.ymin + gap;
      return true;
    }
    // A disk and a wall: the centre lies on the wall's line moved in by r, at distance
    // rd + r from the disk's centre; of the two such points, the one on the free side.
    const std::int32_t d = is_wall(c) ? n : c;
    const Wall wl = wall(is_wall(c) ? c : n);
    const Node& dn = nodes_[static_cast<std::size_t>(d)];
    const double a = dn.r + gap;
    const double off = wl.nx * dn.x + wl.ny * dn.y - (wl.w + gap);  // signed distance to the line
    const double s2 = a * a - off * off;
    if (!(s2 >= 0)) {
      return false;
    }
    // Along the wall (tx, ty) = rot90(inward normal); wall first: +, disk first: -.
    const double s = is_wall(c) ? std::sqrt(s2) : -std::sqrt(s2);
    px = dn.x - off * wl.nx + s * -wl.ny;
    py = dn.y - off * wl.ny + s * wl.nx;
    return true;
  }

  // ------------------------------------------------------------------------------------------
  // Segments: activity (Sec. 2.3) and the front list.

  [[nodiscard]] bool inside(std::int32_t id) const noexcept { return nodes_[static_cast<std::size_t>(id)].inside != 0; }

  // Sec. 2.3: a segment is inactive when both its disks' centres are outside the box (open
  // form: above the lid, Sec. 3). Inactive segments stay on the front for overlap checks.
  [[nodiscard]] bool segment_active(std::int32_t s) const noexcept {
    const auto i = static_cast<std::size_t>(s);
    if (nodes_[i].blocked != 0 || (Open && s == kRight)) {
      return false;
    }
    return inside(s) || inside(next_[i]);
  }

  // Activity bookkeeping. Active segments are counted; on a box more than kListAspect times
  // longer than wide the closed form also keeps them in a circular list in front order
  // (anext_/aprev_), so that its sweep goes from one active segment to the next without stepping
  // over the inactive ones: there most of the closed front runs outside the box, and stepping
  // over it on every lap made the sweep cost disks x aspect ratio. The visit order is the same
  // either way (the next active segment in front order), so the list changes no packing; it is
  // left out elsewhere because it costs about 8% on square boxes, where the steps it saves are
  // few.
  void unlink_segment(std::int32_t s) {
    if (!list_) {
      active_ -= segment_active(s) ? 1U : 0U;
    } else if (listed(s)) {
      list_remove(s);
    }
  }
  void link(std::int32_t s, std::int32_t t) {
    join(s, t);
    if (!list_) {
      active_ += segment_active(s) ? 1U : 0U;
    } else {
      relist(s);
    }
  }

  // The front pointers of link(), without the activity bookkeeping.
  void join(std::int32_t s, std::int32_t t) {
    next_[static_cast<std::size_t>(s)] = t;
    prev_[static_cast<std::size_t>(t)] = s;
    nodes_[static_cast<std::size_t>(s)].blocked = 0;
  }

  [[nodiscard]] bool listed(std::int32_t s) const noexcept { return anext_[static_cast<std::size_t>(s)] != kNone; }

  void list_remove(std::int32_t s) {
    const auto i = static_cast<std::size_t>(s);
    const std::int32_t a = aprev_[i];
    const std::int32_t b = anext_[i];
    anext_[static_cast<std::size_t>(a)] = b;
    aprev_[static_cast<std::size_t>(b)] = a;
    anext_[i] = aprev_[i] = kNone;
    --active_;
  }

  void list_insert_after(std::int32_t a, std::int32_t s) {
    const std::int32_t b = anext_[static_cast<std::size_t>(a)];
    anext_[static_cast<std::size_t>(a)] = s;
    aprev_[static_cast<std::size_t>(s)] = a;
    anext_[static_cast<std::size_t>(s)] = b;
    aprev_[static_cast<std::size_t>(b)] = s;
    ++active_;
  }

  // Makes segment s's membership of the list agree with its activity. A listed segment keeps its
  // place (s's position in the front does not change); a new one goes next to the nearest listed
  // segment, before it if it lies ahead, after it if behind.
  //
  // Anchors. The walk to the nearest listed segment is short only if one is near. On a sliver's
  // box the front is two long inactive strands joined by short active ends, and an end often has
  // a single listed segment: when a cut or a placement unlisted it and a new segment was listed
  // there just after, the walk went along a whole strand to the other end (quadratic: 182 s for
  // a 1 x 1e-6 rectangle, 2 s now). So within one place_on() a segment that goes inactive but marks the
  // place of the action stays listed, as an anchor (stale_), and place_on() unlists the anchors
  // still inactive before it returns. The list is the same at every return: each segment enters
  // at its place in front order, and the list holds the active segments in front order.
  void relist(std::int32_t s) {
    const bool active = segment_active(s);
    if (active == listed(s)) {
      return;
    }
    if (!active) {
      list_remove(s);
      return;
    }
    const Listed near = nearest_listed(s);
    if (near.node != kNone) {
      list_insert_after(near.ahead ? aprev_[static_cast<std::size_t>(near.node)] : near.node, s);
      return;
    }
    anext_[static_cast<std::size_t>(s)] = aprev_[static_cast<std::size_t>(s)] = s;  // the only one
    ++active_;
  }

  // The listed segment nearest to x along the front (x excluded), looking both ways at once, and
  // whether it lies ahead of x; kNone if there is none. One or two steps in practice: a segment
  // becomes active, or the sweep lands, next to active segments. (A kNone link, as for a new disk
  // whose second link is not made yet, ends the walk that way.)
  struct Listed {
    std::int32_t node;
    bool ahead;
  };
  [[nodiscard]] Listed nearest_listed(std::int32_t x) const noexcept {
    std::int32_t back = prev_[static_cast<std::size_t>(x)];
    std::int32_t ahead = next_[static_cast<std::size_t>(x)];
    for (std::size_t steps = 0; steps <= front_size_; ++steps) {
      if (ahead != kNone && ahead != x) {
        if (listed(ahead)) {
          return {ahead, true};
        }
        ahead = next_[static_cast<std::size_t>(ahead)];
      }
      if (back != kNone && back != x) {
        if (listed(back)) {
          return {back, false};
        }
        back = prev_[static_cast<std::size_t>(back)];
      }
    }
    return {kNone, false};
  }

  // The first active segment at or after x in front order: the one the sweep visits next (with
  // the list; without it the main loop steps there).
  [[nodiscard]] std::int32_t first_active_from(std::int32_t x) const noexcept {
    if (!list_ || listed(x)) {
      return x;
    }
    const Listed near = nearest_listed(x);
    if (near.node == kNone) {
      return x;  // nothing is active: the main loop ends
    }
    return near.ahead ? near.node : anext_[static_cast<std::size_t>(near.node)];
  }

  [[nodiscard]] std::int32_t advance(std::int32_t s) const noexcept {
    const std::int32_t n = next_[static_cast<std::size_t>(s)];
    return Open && n == kRight ? kLeft : n;
  }

  // Removes the front nodes first..last (in list order) and joins their neighbours.
  void cut(std::int32_t first, std::int32_t last) {
    const std::int32_t before = prev_[static_cast<std::size_t>(first)];
    const std::int32_t after = next_[static_cast<std::size_t>(last)];
    if (!list_) {
      unlink_segment(before);  // the list keeps `before` in place: link() relists it
    }
    if (fill_voids_) {
      // The segments cut off enclose a void between the disks removed from the front and the
      // disk about to be placed; later, smaller disks may fit there (Sec. 2.4.4's hole filling,
      // but with other disks than the one that cut).
      keep_void(before, kVoidClasses - 1);
      for (std::int32_t v = first; v != last; v = next_[static_cast<std::size_t>(v)]) {
        keep_void(v, kVoidClasses - 1);
      }
      keep_void(last, kVoidClasses - 1);
    }
    if (list_ && !listed(before)) {
      // The first listed segment cut off leaves its place to `before`, an anchor at least.
      for (std::int32_t v = first;; v = next_[static_cast<std::size_t>(v)]) {
        if (listed(v)) {
          list_insert_after(aprev_[static_cast<std::size_t>(v)], before);
          break;
        }
        if (v == last) {
          break;
        }
      }
    }
    for (std::int32_t v = first;; v = next_[static_cast<std::size_t>(v)]) {
      unlink_segment(v);
      --front_size_;
      if (v == last) {
        break;
      }
    }
    if (list_ && listed(before)) {
      join(before, after);
      if (!segment_active(before)) {
        stale_.push_back(before);  // an anchor until place_on() returns
      }
      return;
    }
    link(before, after);
  }

  void block(std::int32_t s) {
    unlink_segment(s);
    nodes_[static_cast<std::size_t>(s)].blocked = 1;
    ++stats_.blocked_segments;
  }

  [[nodiscard]] bool needs_angles(std::int32_t c) const noexcept {
    if (window_ == std::numeric_limits<std::size_t>::max()) {
      return true;
    }
    const Node& o = nodes_[static_cast<std::size_t>(c)];
    const double dx = o.x - ox_;
    const double dy = o.y - oy_;
    const double far = 6.06 * static_cast<double>(window_ + 1) * rmax_;
    return dx * dx + dy * dy <= far * far;
  }

  // Sec. 2.4.2: the angle of segment s -> t seen from O, positive for anticlockwise progress.
  [[nodiscard]] double angle(std::int32_t s, std::int32_t t) const noexcept {
    const Node& sn = nodes_[static_cast<std::size_t>(s)];
    const Node& tn = nodes_[static_cast<std::size_t>(t)];
    const double ax = sn.x - ox_;
    const double ay = sn.y - oy_;
    const double bx = tn.x - ox_;
    const double by = tn.y - oy_;
    return std::atan2(ax * by - ay * bx, ax * bx + ay * by);
  }

  // Walks the front from `from`, forwards (next) or backwards (prev), and returns the first node
  // that a disk at (x, y, r) overlaps, or kNone. The walk visits at most M nodes, stops before
  // `stop` or `also_stop`, after the open front's end wall, and (closed form, with `angles`) once
  // it has turned by more than half a turn about O, `acc` being the angle already turned
  // (Sec. 2.4.2: what lies beyond is on the other side of the active segment).
  std::int32_t first_overlap(std::int32_t from, bool forward, std::int32_t stop, std::int32_t also_stop, double acc,
                             bool angles, const Probe& p) {
    const std::int32_t* const step = forward ? next_.data() : prev_.data();
    const std::int32_t end_wall = forward ? kRight : kLeft;
    const std::size_t window = window_;
    std::size_t steps = 0;
    for (std::int32_t v = from; v != stop && v != also_stop && steps < window; ++steps) {
      const auto vi = static_cast<std::size_t>(v);
      if (angles) {
        acc += forward ? angle(prev_[vi], v) : angle(v, next_[vi]);
        if (acc > std::numbers::pi) {
          break;
        }
      }
      if (overlaps_node(p, v)) {
        return v;
      }
      if (Open && v == end_wall) {
        break;
      }
      v = step[vi];
    }
    return kNone;
  }

  // ------------------------------------------------------------------------------------------
  // Sec. 2.2: placing a disk of radius r on segment c -> n, with cases (a)-(d).
  // Returns the new node, or kNone after setting retired_ to the segment it retired (after cuts,
  // not necessarily the one it started on): the sweep goes on after it. (Returned as a pair of
  // ids, the two were stored as 4-byte halves and reloaded as one 8-byte register, a
  // store-forwarding stall on every disk.)
  // Case (a): accept; the front becomes ... c -> i -> n ...
  std::int32_t accept(std::int32_t c, std::int32_t n, double px, double py, double r) {
    const std::int32_t i = add_node(px, py, r);
    ++front_size_;
    if (!list_) {
      unlink_segment(c);
      link(c, i);
      link(i, n);
      return i;
    }
    // i is listed next to c (listed, or an anchor) before c is relisted.
    join(c, i);
    join(i, n);
    relist(i);
    relist(c);
    return i;
  }

  // place_on_front(), then the anchors left inactive leave the list (see relist()).
  std::int32_t place_on(std::int32_t c, double r) {
    const std::int32_t placed_node = place_on_front(c, r);
    for (const std::int32_t s : stale_) {
      if (listed(s) && !segment_active(s)) {
        list_remove(s);
      }
    }
    stale_.clear();
    return placed_node;
  }

  std::int32_t place_on_front(std::int32_t c, double r) {
    std::int32_t n = next_[static_cast<std::size_t>(c)];
    for (;;) {
      ++stats_.attempts;
      double px = 0;
      double py = 0;
      if (!tangent(c, n, r, px, py)) {
        block(c);
        retired_ = c;
        return kNone;
      }
      const bool can_forward = !(Open && n == kRight);
      const bool can_backward = !(Open && c == kLeft);
      const Probe cand = probe(px, py, r);
      // Case (a) first. Most candidates overlap nothing, and only the grid scan can prove it, so
      // the scan comes before the window walks, which only choose what to cut. The disks next to
      // the segment, the most likely to be in the way, are tried before the scan. The packing is
      // the one of walks first, scan second (same decisions; 11-13% fewer instructions).
      const std::int32_t nn = can_forward ? next_[static_cast<std::size_t>(n)] : kNone;
      const std::int32_t pc = can_backward ? prev_[static_cast<std::size_t>(c)] : kNone;
      const bool nn_hit = nn != kNone && nn != c && overlaps_node(cand, nn);
      const bool near = nn_hit || (pc != kNone && pc != n && overlaps_node(cand, pc));
      if (!near && !overlaps_anything(cand, c, n)) {
        return accept(c, n, px, py, r);
      }
      // Which front disk overlapping the new one comes first after n (subsequent, j) and
      // before c (preceding, u), within the window M and (closed form) half a turn about O.
      // Sec. 2.4.2's half-turn limit. A walk spans at most M + 1 segments, each at most 4 rmax
      // long (two radii plus the new disk's diameter for a cut segment), so it stays farther than
      // rho = |c - O| - 4 (M + 1) rmax from O, and each step turns by at most pi * 4 rmax / (2 rho).
      // From |c - O| >= 6 (M + 1) rmax the total cannot reach pi: no angle needs computing.
      std::int32_t j = kNone;
      std::int32_t u = kNone;
      const bool angles = !Open && needs_angles(c);
      if (nn_hit && !angles) {
        j = nn;  // the forward walk's first step, taken above
      } else if (can_forward) {
        j = first_overlap(nn, true, c, kNone, angles ? angle(c, n) : 0, angles, cand);
      }
      if (can_backward) {
        u = first_overlap(prev_[static_cast<std::size_t>(c)], false, n, j, 0, angles, cand);
      }
      if (j == kNone && u == kNone) {
        // Every overlapped disk is off the window or enclosed by the front: the paper's window
        // check would have missed it. Retire the segment rather than emit an overlap.
        block(c);
        retired_ = c;
        return kNone;
      }
      ++stats_.cuts;
      // The paper's index typos are corrected here (shared/design.md, "The paper, read closely"):
      // k is the disk before j, v the disk after u; in case (d) j is the subsequent and u the
      // preceding disk. The walks never return c or n, so each cut removes at least one disk.
      if (j != kNone) {
        cut(n, prev_[static_cast<std::size_t>(j)]);  // case (b): delete n..k, join c -> j
        n = j;
      }
      if (u != kNone) {
        cut(next_[static_cast<std::size_t>(u)], c);  // case (c): delete v..c, join u -> n
        c = u;
      }
      // Case (d) is both of the above. Retry on the intermediate segment c -> n.
    }
  }

  // ------------------------------------------------------------------------------------------
  // Void filling. The segments that a cut removes from the front are kept as voids, in buckets by
  // the most they can take (log-spaced radius classes). Each new radius is tried first in the
  // tightest bucket whose radii all exceed it (the most recent void there): tangent to the void
  // segment's two disks on its free side, accepted if it overlaps nothing (the grid). A void
  // where something is in the way moves to the class of the radius that failed; one in the
  // lowest class, or one whose disks are too far apart for that radius (so for any smaller one),
  // is dropped.
  // Every drawn radius is placed (here or on the front), so the size distribution is unchanged.

  [[nodiscard]] int void_class(double r) const noexcept { return classes_.of(r); }

  // Keeps segment s -> next_[s] as a void of class k.
  void keep_void(std::int32_t s, int k) {
    const std::int32_t t = next_[static_cast<std::size_t>(s)];
    if (k <= 0 || t == kNone || (Open && s == kRight)) {
      return;
    }
    voids_[static_cast<std::size_t>(k)].push_back(VoidSeg{s, t});
    vmask_ |= 1U << static_cast<unsigned>(k);
  }

  // Tries r in the voids; true if it was placed.
  bool try_voids(double r) {
    const int cls = void_class(r);
    const std::uint32_t eligible = vmask_ & ~((2U << static_cast<unsigned>(cls)) - 1U);
    if (eligible == 0) {
      return false;
    }
    const auto k = static_cast<std::size_t>(std::countr_zero(eligible));
    const VoidSeg v = voids_[k].back();
    voids_[k].pop_back();
    if (voids_[k].empty()) {
      vmask_ &= ~(1U << static_cast<unsigned>(k));
    }
    ++stats_.attempts;
    double px = 0;
    double py = 0;
    if (!tangent(v.a, v.b, r, px, py)) {
      return false;  // too far apart for r, so for any smaller radius: the void is dropped
    }
    if (!overlaps_anything(probe(px, py, r), v.a, v.b)) {
      add_node(px, py, r);  // off the front: it only fills
      ++stats_.void_fills;
      return true;
    }
    if (cls > 0) {
      voids_[static_cast<std::size_t>(cls)].push_back(v);
      vmask_ |= 1U << static_cast<unsigned>(cls);
    }
    return false;
  }

  // ------------------------------------------------------------------------------------------
  // Initial fronts.

  // Sec. 2.1: three mutually tangent disks D1, D2, D3, anticlockwise, at the start point; the
  // front D1 -> D2 -> D3 -> D1.
  std::int32_t start_closed() {
    const Point s =
        req_.start ? Point{(req_.start->x - origin_.x) * unit_.k, (req_.start->y - origin_.y) * unit_.k}
                   : Point{box_.xmax / 2, box_.ymax / 2};
    const double r1 = draw();
    const double r2 = draw();
    const double r3 = draw();
    const std::int32_t d1 = add_node(s.x, s.y, r1);
    const std::int32_t d2 = add_node(s.x + r1 + r2 + clearance_, s.y, r2);
    // D3 on the left of D1 -> D2 makes the triangle anticlockwise: compute it with the open
    // form's side convention, then restore the closed form's.
    double px = 0;
    double py = 0;
    const bool ok = tangent(d1, d2, r3, px, py, /*left=*/true);
    if (!ok) {
      return kNone;
    }
    const std::int32_t d3 = add_node(px, py, r3);
    front_size_ = 3;
    ox_ = (nodes_[3].x + nodes_[4].x + nodes_[5].x) / 3;
    oy_ = (nodes_[3].y + nodes_[4].y + nodes_[5].y) / 3;
    link(d1, d2);
    link(d2, d3);
    link(d3, d1);
    return d1;
  }

  // Sec. 3: the open front Bl -> Bb -> Br; the first active segment Bl -> Bb.
  std::int32_t start_open() {
    front_size_ = 3;
    next_[kRight] = kLeft;  // closes the list; Br -> Bl is never a segment
    prev_[kLeft] = kRight;
    link(kLeft, kBottom);
    link(kBottom, kRight);
    return kLeft;
  }

  double draw() { return req_.radii->quantile(rng_.uniform()) * unit_.k; }

  const FrontRequest& req_;
  Rng& rng_;
  std::vector<Disk>& out_;
  FillStats& stats_;
  WorkScale unit_;
  Point origin_;
  Box box_;
  double rmax_ = 0;
  LengthScale scale_;  // for tangent_to_two
  double clearance_ = 0;
  double margin_ = 0;
  double band_ = 0;
  std::size_t window_ = 5;
  RunControl control_;
  std::size_t fixed_bytes_ = 0;  // the grid's, for the memory limit's message
  double area_ = 0;  // sum of r^2 over the disks placed, for progress reports
  double ox_ = 0;
  double oy_ = 0;

  // Not HugeVector (common/huge_pages.hpp): these fronts read near the front only.
  std::vector<Node> nodes_;
  std::vector<std::int32_t> next_, prev_;
  bool list_ = false;                        // keep the list below (closed form, elongated box)
  std::vector<std::int32_t> anext_, aprev_;  // the active segments, in front order
  std::vector<std::int32_t> stale_;          // inactive segments listed as anchors (relist())
  std::size_t active_ = 0;
  std::size_t front_size_ = 0;
  std::int32_t retired_ = kNone;  // place_on()'s retired segment

  CellGrid grid_;
  std::vector<std::int32_t> head_;

  struct VoidSeg {
    std::int32_t a, b;
  };
  bool fill_voids_ = true;
  RadiusClasses<kVoidClasses> classes_;
  std::array<std::vector<VoidSeg>, kVoidClasses> voids_;
  std::uint32_t vmask_ = 0;  // bit k: voids_[k] is not empty
};

}  // namespace

FrontResult advance_front(const FrontRequest& req, Rng& rng, std::vector<Disk>& out, FillStats& stats) {
  if (req.method == Method::open) {
    Front<true> front(req, rng, out, stats);
    return front.run();
  }
  Front<false> front(req, rng, out, stats);
  return front.run();
}

}  // namespace frontpack::detail
