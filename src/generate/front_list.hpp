// The paper's front as a list of nodes (Sec. 2.1), and which of its segments are active (Sec. 2.3):
// what generate/paper_front.cpp walks, cuts and sweeps.
//
// Every placed disk is a node; in the open form nodes 0, 1, 2 are the walls Bl, Bb, Br (disks of
// infinite radius, Sec. 3). The front is a doubly linked list of nodes (next/prev), closed in both
// forms: the open form's list Bl -> ... -> Br is closed by a link Br -> Bl that is never a
// segment. A segment is identified by its first node s (s -> next(s)).
//
// Header-only and CGAL-free: every placement links, cuts and relists here.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "generate/run_control.hpp"

namespace frontpack::detail::paper {

inline constexpr std::int32_t kNone = -1;
inline constexpr std::int32_t kLeft = 0;    // Bl
inline constexpr std::int32_t kBottom = 1;  // Bb
inline constexpr std::int32_t kRight = 2;   // Br
inline constexpr std::int32_t kFirstDisk = 3;

/// The front's links over `nodes` (a Node has the flags `inside`, its centre in the box,
/// `blocked`, the segment starting there retired, and `on_front`) and the bookkeeping of its
/// active segments.
///
/// In a periodic cell the front may be several cycles (splice()), each bounding free space on its
/// free side; the active count covers them all.
///
/// Active segments are counted; on a box more than kListAspect times longer than wide
/// (paper_front.cpp) the closed form also keeps them in a circular list in front order
/// (anext_/aprev_), so that its sweep goes from one active segment to the next without stepping
/// over the inactive ones: there most of the closed front runs outside the box, and stepping over
/// it on every lap made the sweep cost disks x aspect ratio. The visit order is the same either
/// way (the next active segment in front order), so the list changes no packing; it is left out
/// elsewhere because it costs about 8% on square boxes, where the steps it saves are few.
template <bool Open, class Node>
class FrontList {
 public:
  explicit FrontList(std::vector<Node>& nodes) noexcept : nodes_(nodes) {}

  /// Room for n nodes; `list`: keep the list of active segments.
  void reserve(std::size_t n, bool list) {
    list_ = list;
    next_.reserve(n);
    prev_.reserve(n);
    if (list_) {
      anext_.reserve(n);
      aprev_.reserve(n);
    }
  }

  /// The links of a new node, not on the front yet.
  [[gnu::always_inline]] void add() {
    next_.push_back(kNone);
    prev_.push_back(kNone);
    if (list_) {
      anext_.push_back(kNone);
      aprev_.push_back(kNone);
    }
  }

  /// Frees the links (the run is over).
  void release() {
    detail::release(next_);
    detail::release(prev_);
    detail::release(anext_);
    detail::release(aprev_);
  }

  [[nodiscard]] std::int32_t next(std::int32_t s) const noexcept { return next_[static_cast<std::size_t>(s)]; }
  [[nodiscard]] std::int32_t prev(std::int32_t s) const noexcept { return prev_[static_cast<std::size_t>(s)]; }
  /// The links to walk by: next() forwards, prev() backwards.
  [[nodiscard]] const std::int32_t* links(bool forward) const noexcept { return forward ? next_.data() : prev_.data(); }
  /// The nodes on the front.
  [[nodiscard]] std::size_t size() const noexcept { return front_size_; }
  /// The active segments.
  [[nodiscard]] std::size_t active() const noexcept { return active_; }

  // Sec. 2.3: a segment is inactive when both its disks' centres are outside the box (open
  // form: above the lid, Sec. 3). Inactive segments stay on the front for overlap checks.
  [[nodiscard]] bool segment_active(std::int32_t s) const noexcept {
    const auto i = static_cast<std::size_t>(s);
    if (nodes_[i].blocked != 0 || (Open && s == kRight)) {
      return false;
    }
    return inside(s) || inside(next_[i]);
  }

  /// Whether node id is on the front (a removed node keeps stale links).
  [[nodiscard]] bool on_front(std::int32_t id) const noexcept {
    return nodes_[static_cast<std::size_t>(id)].on_front != 0;
  }

  /// Sec. 2.1: the closed front D1 -> D2 -> D3 -> D1.
  void start_closed(std::int32_t d1, std::int32_t d2, std::int32_t d3) {
    front_size_ = 3;
    for (const std::int32_t d : {d1, d2, d3}) {
      nodes_[static_cast<std::size_t>(d)].on_front = 1;
    }
    link(d1, d2);
    link(d2, d3);
    link(d3, d1);
  }

  /// Sec. 3: the open front Bl -> Bb -> Br.
  void start_open() {
    front_size_ = 3;
    for (const std::int32_t d : {kLeft, kBottom, kRight}) {
      nodes_[static_cast<std::size_t>(d)].on_front = 1;
    }
    next_[kRight] = kLeft;  // closes the list; Br -> Bl is never a segment
    prev_[kLeft] = kRight;
    link(kLeft, kBottom);
    link(kBottom, kRight);
  }

  /// Sec. 2.2, case (a): new node i goes between c and n (c -> i -> n).
  void insert(std::int32_t c, std::int32_t i, std::int32_t n) {
    ++front_size_;
    nodes_[static_cast<std::size_t>(i)].on_front = 1;
    if (!list_) {
      unlink_segment(c);
      link(c, i);
      link(i, n);
      return;
    }
    // i is listed next to c (listed, or an anchor) before c is relisted.
    join(c, i);
    join(i, n);
    relist(i);
    relist(c);
  }

  /// Cases (b)-(d): removes the front nodes first..last (in list order) and joins their neighbours.
  void remove(std::int32_t first, std::int32_t last);

  /// Exchanges the successors of c and k: c -> n and k -> d become c -> d and k -> n. Both
  /// segments keep their free side on the same hand, so each cycle still bounds free space: with c
  /// and k on one cycle it splits in two, on two cycles they join. (A periodic front that meets
  /// itself across the cell, or another of its cycles.) Not with the list of active segments.
  void splice(std::int32_t c, std::int32_t k) {
    const std::int32_t n = next(c);
    const std::int32_t d = next(k);
    unlink_segment(c);
    unlink_segment(k);
    link(c, d);
    link(k, n);
  }

  /// Retires segment s: it stays on the front, inactive.
  void retire(std::int32_t s) {
    unlink_segment(s);
    nodes_[static_cast<std::size_t>(s)].blocked = 1;
  }

  /// After a placement: the anchors left inactive leave the list (see relist()).
  void drop_anchors() {
    for (const std::int32_t s : stale_) {
      if (listed(s) && !segment_active(s)) {
        list_remove(s);
      }
    }
    stale_.clear();
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

  /// The segment after s, the open front's end wall skipped (the sweep's next step).
  [[nodiscard]] std::int32_t advance(std::int32_t s) const noexcept {
    const std::int32_t n = next_[static_cast<std::size_t>(s)];
    return Open && n == kRight ? kLeft : n;
  }

 private:
  [[nodiscard]] bool inside(std::int32_t id) const noexcept { return nodes_[static_cast<std::size_t>(id)].inside != 0; }

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
  // a 1 x 1e-6 rectangle, 2 s now). So within one placement a segment that goes inactive but marks
  // the place of the action stays listed, as an anchor (stale_), and drop_anchors() unlists the
  // anchors still inactive after it. The list is the same after every placement: each segment
  // enters at its place in front order, and the list holds the active segments in front order.
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

  std::vector<Node>& nodes_;
  // Not HugeVector (common/huge_pages.hpp): these fronts read near the front only.
  std::vector<std::int32_t> next_, prev_;
  bool list_ = false;                        // keep the list below (closed form, elongated box)
  std::vector<std::int32_t> anext_, aprev_;  // the active segments, in front order
  std::vector<std::int32_t> stale_;          // inactive segments listed as anchors (relist())
  std::size_t active_ = 0;
  std::size_t front_size_ = 0;
};

template <bool Open, class Node>
void FrontList<Open, Node>::remove(std::int32_t first, std::int32_t last) {
  const std::int32_t before = prev_[static_cast<std::size_t>(first)];
  const std::int32_t after = next_[static_cast<std::size_t>(last)];
  if (!list_) {
    unlink_segment(before);  // the list keeps `before` in place: link() relists it
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
    nodes_[static_cast<std::size_t>(v)].on_front = 0;
    --front_size_;
    if (v == last) {
      break;
    }
  }
  if (list_ && listed(before)) {
    join(before, after);
    if (!segment_active(before)) {
      stale_.push_back(before);  // an anchor until drop_anchors()
    }
    return;
  }
  link(before, after);
}

}  // namespace frontpack::detail::paper
