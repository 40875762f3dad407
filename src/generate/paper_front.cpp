// The advancing front (Feng, Han & Owen 2003, "Filling domains with disks: an advancing front
// approach", IJNME 56:699-713). Section numbers refer to the paper; deviations say why.
//
// Data layout. Every placed disk is a node (nodes_, one record each, in the grid's cells); the
// front is a doubly linked list of nodes, in the open form with the walls as nodes 0, 1, 2
// (generate/front_list.hpp, which also keeps which segments are active).
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
#include <span>

#include "common/huge_pages.hpp"
#include "generate/acceptance.hpp"
#include "generate/disk_grid.hpp"
#include "generate/front_list.hpp"
#include "generate/run_control.hpp"
#include "generate/scale.hpp"
#include "generate/tangency.hpp"
#include "generate/void_buckets.hpp"
#include "generate/window_walk.hpp"
#include "periodic/front_images.hpp"

namespace frontpack::detail {

namespace {

using paper::kBottom;
using paper::kFirstDisk;
using paper::kLeft;
using paper::kNone;
using paper::kRight;
constexpr double kListAspect = 4;  // the list of active segments, see FrontList
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
    std::uint8_t on_front;   // on the front (FrontList)
    std::uint8_t image;      // an image of a disk across a periodic side (periodic/wrap.hpp): in the grid only
  };
  static_assert(sizeof(Node) == 32);

 public:
  Front(const FrontSettings& req, const Box& region, Rng& rng, std::vector<Disk>& out)
      : req_(req),
        rng_(rng),
        out_(out),
        frame_(*req.radii, req.clearance, region),
        overlap_(frame_.clearance, report_.exact_checks),
        control_(req.max_disks, req.tick),
        region_(region) {
    box_ = Box{0, 0, frame_.width, frame_.height};
    const double long_side = std::max(box_.width(), box_.height());
    const double short_side = std::min(box_.width(), box_.height());
    periodic_.wrap = PeriodicWrap{req.periodicity != Periodicity::none, req.periodicity == Periodicity::xy,
                                  frame_.width, frame_.height};
    // (A periodic front may be several cycles, which the list of active segments does not follow.)
    const bool list = !Open && !wrap_.any() && !(long_side <= kListAspect * short_side);  // NaN-safe
    fill_voids_ = req.fill_voids;
    classes_ = RadiusClasses<kVoidClasses>(frame_.rmin, frame_.rmax);

    // The memory limit: the grid's cell heads, then bytes_per_disk per disk generated.
    grid_ = CellGrid(box_.xmin, box_.ymin, box_.width(), box_.height(), frame_.rmax);
    const std::size_t grid_bytes = grid_.cells() * sizeof(std::int32_t);
    if (req.memory_limit != 0) {
      if (grid_bytes >= req.memory_limit) {
        throw_memory_limit(req.memory_limit,
                           "the grid over a polygon's box (" + std::to_string(grid_.cells()) + " cells) takes " +
                               std::to_string(grid_bytes) + " bytes",
                           count_of(estimate_disks(region, *req.radii), 1e18));
      }
      control_.limit_memory(req.memory_limit - grid_bytes, req.bytes_per_disk);
    }
    fixed_bytes_ = grid_bytes;

    const double estimate = estimate_disks(region, *req.radii);
    // Room for every disk the front can make: each lies within 5 rmax and two clearances of the
    // box (a disk on the front within 2 rmax and a clearance of a centre in the box, one in a void
    // within as much again of the front's), bound_disks(). A vector that outgrew its reservation
    // held its old and its new array at once, 96 bytes per node (an open form on a 1e-7 high
    // sliver generated 1.7 times the estimate and took 1.3 GB). Reserved pages cost nothing until
    // written; the disk budget (max_disks, the memory limit) caps it.
    const double bound = bound_disks(region, 5 * req.radii->max() + 2 * req.clearance, *req.radii);
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
    front_.reserve(reserve + kFirstDisk, list);
    setup_grid();
  }

  FrontReport run() {
    // Walls (open form) or placeholders (closed form) occupy nodes 0..2.
    for (std::int32_t w = 0; w < kFirstDisk; ++w) {
      add_node(0, 0, std::numeric_limits<double>::infinity());
    }
    std::int32_t cur = Open ? start_open() : start_closed();
    if (cur == kNone) {
      return report_;
    }
    double r = draw();
    std::size_t skips = 0;
    std::int32_t lap = kNone;  // a periodic front: where the current run of inactive segments began
    while (front_.active() > 0 && skips <= front_.size() + 1) {
      if (control_.stop(placed(), area_ * frame_.unit.inv_k * frame_.unit.inv_k, report_)) {
        break;
      }
      if (!front_.segment_active(cur)) {
        lap = skips == 0 ? cur : lap;
        cur = front_.advance(cur);
        ++skips;
        if (wrap_.any() && cur == lap) {
          // A whole cycle inactive: go on with another (FrontList::splice()).
          if (!periodic_.next_cycle(cur, [this](std::int32_t e) { return front_.on_front(e); })) {
            break;
          }
          skips = 0;
        }
        continue;
      }
      skips = 0;
      if (!voids_.empty() && try_voids(r)) {
        area_ += r * r;
        r = draw();
        continue;
      }
      const std::int32_t placed_node = place_on(cur, r);
      if (placed_node == kNone) {
        cur = front_.first_active_from(front_.advance(retired_));  // the radius stays for the next segment
        continue;
      }
      area_ += r * r;
      r = draw();
      // Visit order. Closed form (Fig. 4): after D4 on D1 -> D2, the next segment is D2 -> D3,
      // the one after the new disk's. Open form (Sec. 3): along the layer (D1 -> Bb after D1),
      // and back to Bl -> first disk once a layer reaches the right wall.
      const std::int32_t n = front_.next(placed_node);
      if constexpr (Open) {
        cur = n == kRight ? kLeft : placed_node;
      } else {
        cur = front_.first_active_from(n);
      }
    }
    // The front and the grid are done with: free them before the output grows (peak memory).
    front_.release();
    release(head_);
    voids_.release();
    const std::size_t first_out = out_.size();
    periodic_.drop(nodes_, kFirstDisk);
    move_out(nodes_, kFirstDisk, frame_.origin, frame_.unit.inv_k, out_);
    keep_in_cell(wrap_, std::span<Disk>(out_).subspan(first_out), region_);
    report_.fixed_bytes = fixed_bytes_;
    return report_;
  }

 private:
  // ------------------------------------------------------------------------------------------
  // Nodes, the grid over placed disks.

  [[nodiscard]] std::size_t placed() const noexcept {
    return nodes_.size() - kFirstDisk - periodic_.count() + out_.size();
  }

  [[gnu::always_inline]] std::int32_t add_node(double x, double y, double r) {
    const auto id = static_cast<std::int32_t>(nodes_.size());
    if (wrap_.any()) {
      x = wrap_.wrap_x(x);
      y = wrap_.wrap_y(y);
    }
    std::int32_t link_to = kNone;
    if (id >= kFirstDisk) {
      const std::size_t c = cell_of(x, y);
      link_to = head_[c];
      head_[c] = id;
    }
    // In a periodic cell every centre is in the box on a periodic axis.
    const bool in_x = wrap_.x || (x >= box_.xmin && x <= box_.xmax);
    const bool in_y = wrap_.y || (y >= box_.ymin && y <= box_.ymax);
    const bool in = id >= kFirstDisk ? in_x && in_y : id == kBottom;
    nodes_.push_back(Node{x, y, r, link_to, static_cast<std::uint8_t>(in ? 1 : 0), 0, 0, 0});
    front_.add();
    if (wrap_.any() && id >= kFirstDisk) {
      // A search from a centre in the cell reaches r_hi + rmax: at most 2 rmax and a clearance.
      periodic_.add(nodes_, head_, grid_, id, 2.5 * frame_.rmax + 2 * frame_.clearance, [this] { front_.add(); });
    }
    return id;
  }

  // Node v as seen from (x, y): its minimum image in a periodic cell.
  [[nodiscard]] Node seen_from(std::int32_t v, double x, double y) const noexcept {
    return periodic_.seen_from(nodes_[static_cast<std::size_t>(v)], x, y);
  }

  void setup_grid() { head_.assign(grid_.cells(), kNone); }  // (grid_ is set up in the constructor)

  [[nodiscard]] std::int64_t col(double x) const noexcept { return grid_.col(x); }
  [[nodiscard]] std::int64_t row(double y) const noexcept { return grid_.row(y); }
  [[nodiscard]] std::size_t cell_of(double x, double y) const noexcept { return grid_.cell_of(x, y); }

  [[nodiscard]] Probe probe(double x, double y, double r) const noexcept { return overlap_.probe(x, y, r); }

  // Whether a disk at (x, y, r) crosses wall w (open form). A disk within the band of a wall
  // counts as crossing it: walls only guide the generator; containment in the domain is decided
  // exactly by the certifier.
  [[nodiscard]] bool crosses_wall(std::int32_t w, double x, double y, double r) const noexcept {
    switch (w) {
      case kLeft: return x - r < box_.xmin + overlap_.band();
      case kRight: return x + r > box_.xmax - overlap_.band();
      default: return y - r < box_.ymin + overlap_.band();
    }
  }

  // Whether a disk at (x, y, r) overlaps front node v (a disk or a wall).
  bool overlaps_node(const Probe& p, std::int32_t v) {
    if (is_wall(v)) {
      return Open && crosses_wall(v, p.x, p.y, p.r);
    }
    return wrap_.any() ? overlap_.overlaps(p, seen_from(v, p.x, p.y))
                       : overlap_.overlaps(p, nodes_[static_cast<std::size_t>(v)]);
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
      const bool clear_of_walls = x - r >= box_.xmin + overlap_.band() && x + r <= box_.xmax - overlap_.band() &&
                                  y - r >= box_.ymin + overlap_.band();
      if (!clear_of_walls) {  // most candidates are: one test for the three walls
        for (const std::int32_t w : {kLeft, kBottom, kRight}) {
          if (w != c && w != n && crosses_wall(w, x, y, r)) {
            return true;
          }
        }
      }
    }
    const double reach = (p.r_hi + frame_.rmax) * (1 + 1e-9);
    const std::int64_t c0 = col(x - reach);
    const std::int64_t c1 = col(x + reach);
    const std::int64_t r0 = row(y - reach);
    const std::int64_t r1 = row(y + reach);
    return visit_cells(head_.data(), grid_.nx, nodes_.data(), kNone, c0, c1, r0, r1,
                       [&](std::int32_t /*d*/, const Node& o) { return overlap_.overlaps(p, o); });
  }

  // A periodic cell: a disk on the front, other than c and n, that the candidate overlaps (the
  // first the grid scan finds, images taken for their disks), or kNone.
  std::int32_t far_front_disk(const Probe& p, std::int32_t c, std::int32_t n) {
    const double reach = (p.r_hi + frame_.rmax) * (1 + 1e-9);
    std::int32_t found = kNone;
    visit_cells(head_.data(), grid_.nx, nodes_.data(), kNone, col(p.x - reach), col(p.x + reach), row(p.y - reach),
                row(p.y + reach), [&](std::int32_t d, const Node& o) {
                  const std::int32_t real = periodic_.real(nodes_, d);
                  if (real == c || real == n || !front_.on_front(real) || !overlap_.overlaps(p, o)) {
                    return false;
                  }
                  found = real;
                  return true;
                });
    return found;
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
    const double gap = r + frame_.clearance;
    if (!is_wall(c) && !is_wall(n)) {
      const Node& cn = nodes_[static_cast<std::size_t>(c)];
      if (wrap_.any()) {  // n's image next to c; the new centre brought into the cell
        const Node nn = seen_from(n, cn.x, cn.y);
        const bool ok = tangent_to_two(cn.x, cn.y, cn.r + gap, nn.x, nn.y, nn.r + gap, left, frame_.scale, px, py);
        px = wrap_.wrap_x(px);
        py = wrap_.wrap_y(py);
        return ok;
      }
      const Node& nn = nodes_[static_cast<std::size_t>(n)];
      // Left (open form) or right (closed form) of c -> n.
      return tangent_to_two(cn.x, cn.y, cn.r + gap, nn.x, nn.y, nn.r + gap, left, frame_.scale, px, py);
    }
    if (is_wall(c) && is_wall(n)) {
      return tangent_to_two_walls(wall(c), wall(n), gap, px, py);  // Sec. 3: D1 in a corner
    }
    // A disk and a wall: along the wall (tx, ty) = rot90(inward normal); wall first: +, disk
    // first: -.
    const bool wall_first = is_wall(c);
    const Wall wl = wall(wall_first ? c : n);
    const Node& dn = nodes_[static_cast<std::size_t>(wall_first ? n : c)];
    return tangent_to_disk_and_wall(dn.x, dn.y, dn.r, wl, -wl.ny, wl.nx, gap, wall_first, false, px, py);
  }

  // Removes the front nodes first..last (in list order) and joins their neighbours.
  void cut(std::int32_t first, std::int32_t last) {
    if (fill_voids_) {
      // The segments cut off enclose a void between the disks removed from the front and the
      // disk about to be placed; later, smaller disks may fit there (Sec. 2.4.4's hole filling,
      // but with other disks than the one that cut).
      keep_void(front_.prev(first), kVoidClasses - 1);
      for (std::int32_t v = first; v != last; v = front_.next(v)) {
        keep_void(v, kVoidClasses - 1);
      }
      keep_void(last, kVoidClasses - 1);
    }
    front_.remove(first, last);
  }

  void block(std::int32_t s) {
    front_.retire(s);
    ++report_.blocked_segments;
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
    front_.insert(c, i, n);
    return i;
  }

  // place_on_front(), then the anchors left inactive leave the list (FrontList::relist()).
  std::int32_t place_on(std::int32_t c, double r) {
    const std::int32_t placed_node = place_on_front(c, r);
    front_.drop_anchors();
    return placed_node;
  }

  std::int32_t place_on_front(std::int32_t c, double r) {
    std::int32_t n = front_.next(c);
    int splices = 0;  // at most two per placement: each ends in a retry, and the loop must end
    for (;;) {
      ++report_.attempts;
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
      const std::int32_t nn = can_forward ? front_.next(n) : kNone;
      const std::int32_t pc = can_backward ? front_.prev(c) : kNone;
      const bool nn_hit = nn != kNone && nn != c && overlaps_node(cand, nn);
      const bool near = nn_hit || (pc != kNone && pc != n && overlaps_node(cand, pc));
      if (!near && !overlaps_anything(cand, c, n)) {
        return accept(c, n, px, py, r);
      }
      // Which front disk overlapping the new one comes first after n (subsequent, j) and
      // before c (preceding, u), within the window M and (closed form) half a turn about O.
      std::int32_t j = kNone;
      std::int32_t u = kNone;
      const bool angles = walk_.needs_angles(c);
      const auto hits = [&](std::int32_t v) { return overlaps_node(cand, v); };
      if (nn_hit && !angles) {
        j = nn;  // the forward walk's first step, taken above
      } else if (can_forward) {
        j = walk_.first_overlap(nn, true, c, kNone, angles ? walk_.angle(c, n) : 0, angles, hits);
      }
      if (can_backward) {
        u = walk_.first_overlap(front_.prev(c), false, n, j, 0, angles, hits);
      }
      if (j == kNone && u == kNone && wrap_.any() && splices < 2) {
        if (const std::int32_t d = splice_across(cand, c, n); d != kNone) {
          ++splices;
          n = d;
          continue;
        }
      }
      if (j == kNone && u == kNone) {
        // Every overlapped disk is off the window or enclosed by the front: the paper's window
        // check would have missed it. Retire the segment rather than emit an overlap.
        block(c);
        retired_ = c;
        return kNone;
      }
      ++report_.cuts;
      // The paper's index typos are corrected here (shared/design.md, "The paper, read closely"):
      // k is the disk before j, v the disk after u; in case (d) j is the subsequent and u the
      // preceding disk. The walks never return c or n, so each cut removes at least one disk.
      if (j != kNone) {
        cut(n, front_.prev(j));  // case (b): delete n..k, join c -> j
        n = j;
      }
      if (u != kNone) {
        cut(front_.next(u), c);  // case (c): delete v..c, join u -> n
        c = u;
      }
      // Case (d) is both of the above. Retry on the intermediate segment c -> n.
    }
  }

  // A periodic front meets itself, or another of its cycles, across free space, where nothing on
  // the window is in the way of the candidate on c -> n: the segments c -> n and k -> d (k before
  // d, the front disk in the way) become c -> d, to be retried, and k -> n, the entry of the cycle
  // that a split leaves apart (FrontList::splice()). Returns d, or kNone (nothing spliced).
  // (Not onto a retired segment k -> d: k -> n would be live again, and two segments could hand
  // each other back and forth for ever, each splice undoing the other's retirement; the fill
  // fuzzer found such a cell. So a splice never adds a live segment, and every placement that does
  // not place a disk retires one.)
  std::int32_t splice_across(const Probe& cand, std::int32_t c, std::int32_t n) {
    const std::int32_t d = far_front_disk(cand, c, n);
    if (d == kNone || !front_.segment_active(front_.prev(d))) {
      return kNone;
    }
    front_.splice(c, front_.prev(d));
    periodic_.keep_entry(n);
    walk_.stop_turning();
    return d;
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

  // Keeps segment s -> next(s) as a void of class k.
  void keep_void(std::int32_t s, int k) {
    const std::int32_t t = front_.next(s);
    if (k <= 0 || t == kNone || (Open && s == kRight)) {
      return;
    }
    voids_.push(k, VoidSeg{s, t});
  }

  // Tries r in the voids; true if it was placed.
  bool try_voids(double r) {
    const int cls = void_class(r);
    const int k = voids_.first_above(cls);
    if (k < 0) {
      return false;
    }
    const VoidSeg v = voids_.pop(k);
    ++report_.attempts;
    double px = 0;
    double py = 0;
    if (!tangent(v.a, v.b, r, px, py)) {
      return false;  // too far apart for r, so for any smaller radius: the void is dropped
    }
    if (!overlaps_anything(probe(px, py, r), v.a, v.b)) {
      add_node(px, py, r);  // off the front: it only fills
      ++report_.void_fills;
      return true;
    }
    if (cls > 0) {
      voids_.push(cls, v);
    }
    return false;
  }

  // ------------------------------------------------------------------------------------------
  // Initial fronts.

  // Sec. 2.1: three mutually tangent disks D1, D2, D3, anticlockwise, at the start point; the
  // front D1 -> D2 -> D3 -> D1.
  std::int32_t start_closed() {
    const Point s = req_.start ? frame_.local(*req_.start) : Point{box_.xmax / 2, box_.ymax / 2};
    const double r1 = draw();
    const double r2 = draw();
    const double r3 = draw();
    const std::int32_t d1 = add_node(s.x, s.y, r1);
    const std::int32_t d2 = add_node(s.x + r1 + r2 + frame_.clearance, s.y, r2);
    // D3 on the left of D1 -> D2 makes the triangle anticlockwise: compute it with the open
    // form's side convention, then restore the closed form's.
    double px = 0;
    double py = 0;
    const bool ok = tangent(d1, d2, r3, px, py, /*left=*/true);
    if (!ok) {
      return kNone;
    }
    const std::int32_t d3 = add_node(px, py, r3);
    walk_.centre((nodes_[3].x + nodes_[4].x + nodes_[5].x) / 3, (nodes_[3].y + nodes_[4].y + nodes_[5].y) / 3);
    front_.start_closed(d1, d2, d3);
    return d1;
  }

  // Sec. 3: the open front Bl -> Bb -> Br; the first active segment Bl -> Bb.
  std::int32_t start_open() {
    front_.start_open();
    return kLeft;
  }

  double draw() { return frame_.draw(rng_); }

  const FrontSettings& req_;
  Rng& rng_;
  std::vector<Disk>& out_;
  FrontReport report_;  // counters and why the run stopped: what run() returns
  RunFrame frame_;
  OverlapTest overlap_;
  Box box_;  // local: (0, 0) to (width, height)
  RunControl control_;
  std::size_t fixed_bytes_ = 0;  // the grid's, for the memory limit's message
  double area_ = 0;              // sum of r^2 over the disks placed, for progress reports

  // A periodic cell (periodic/wrap.hpp).
  Box region_;  // the cell, as given
  PeriodicImages<Node, kNone> periodic_;
  const PeriodicWrap& wrap_ = periodic_.wrap;  // local

  // Not HugeVector (common/huge_pages.hpp): these fronts read near the front only.
  std::vector<Node> nodes_;
  paper::FrontList<Open, Node> front_{nodes_};
  WindowWalk<Open, Node, paper::FrontList<Open, Node>> walk_{nodes_,      front_, periodic_.wrap, req_.window,
                                                             frame_.rmax, kNone,  kLeft,          kRight};
  std::int32_t retired_ = kNone;  // place_on()'s retired segment

  CellGrid grid_;
  std::vector<std::int32_t> head_;

  struct VoidSeg {
    std::int32_t a, b;
  };
  bool fill_voids_ = true;
  RadiusClasses<kVoidClasses> classes_;
  VoidBuckets<VoidSeg, kVoidClasses> voids_;
};

}  // namespace

FrontReport advance_front(const FrontSettings& settings, const Box& box, Rng& rng, std::vector<Disk>& out) {
  if (settings.method == Method::open) {
    Front<true> front(settings, box, rng, out);
    return front.run();
  }
  Front<false> front(settings, box, rng, out);
  return front.run();
}

}  // namespace frontpack::detail
