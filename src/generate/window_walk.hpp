// The paper's window check (Sec. 2.4.2-2.4.3): which front disk a candidate overlaps first, walking
// at most M disks along the front either way from the active segment, and no further than half a
// turn about the closed front's start O. It decides cases (b)-(d); the grid over all placed
// disks decides case (a) (paper_front.cpp). Header-only and CGAL-free: it runs on every
// candidate that something is in the way of.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <numbers>
#include <vector>

#include "periodic/wrap.hpp"

namespace frontpack::detail {

/// `Front` has next(), prev() and links(forward); `Node` has x and y. The walk reads the nodes and
/// the links in place, so it stays valid as they grow.
template <bool Open, class Node, class Front>
class WindowWalk {
 public:
  WindowWalk(const std::vector<Node>& nodes, const Front& front, const PeriodicWrap& wrap, std::size_t window,
             double rmax, std::int32_t none, std::int32_t left, std::int32_t right) noexcept
      : nodes_(nodes),
        front_(front),
        wrap_(wrap),
        window_(window == 0 ? std::numeric_limits<std::size_t>::max() : window),
        rmax_(rmax),
        none_(none),
        left_(left),
        right_(right) {}

  /// Where the closed front started (Sec. 2.4.2's O).
  void centre(double ox, double oy) noexcept {
    ox_ = ox;
    oy_ = oy;
  }
  /// The periodic front has met itself across the cell: it no longer turns about O.
  void stop_turning() noexcept { turning_ = false; }

  /// Whether the walks from segment c -> ... must count the angle turned about O. A walk spans at
  /// most M + 1 segments, each at most 4 rmax long (two radii plus the new disk's diameter for a
  /// cut segment), so it stays farther than rho = |c - O| - 4 (M + 1) rmax from O, and each step
  /// turns by at most pi * 4 rmax / (2 rho). From |c - O| >= 6 (M + 1) rmax the total cannot
  /// reach pi: no angle needs computing.
  [[nodiscard]] bool needs_angles(std::int32_t c) const noexcept {
    if (Open || !turning_) {
      return false;
    }
    if (window_ == std::numeric_limits<std::size_t>::max()) {
      return true;
    }
    const Node& o = nodes_[static_cast<std::size_t>(c)];
    const double dx = wrap_.dx(o.x - ox_);
    const double dy = wrap_.dy(o.y - oy_);
    const double far = 6.06 * static_cast<double>(window_ + 1) * rmax_;
    return dx * dx + dy * dy <= far * far;
  }

  /// Sec. 2.4.2: the angle of segment s -> t seen from O, positive for anticlockwise progress.
  [[nodiscard]] double angle(std::int32_t s, std::int32_t t) const noexcept {
    const Node& sn = nodes_[static_cast<std::size_t>(s)];
    const Node& tn = nodes_[static_cast<std::size_t>(t)];
    const double ax = wrap_.dx(sn.x - ox_);
    const double ay = wrap_.dy(sn.y - oy_);
    const double bx = wrap_.dx(tn.x - ox_);
    const double by = wrap_.dy(tn.y - oy_);
    return std::atan2(ax * by - ay * bx, ax * bx + ay * by);
  }

  /// Walks the front from `from`, forwards (next) or backwards (prev), and returns the first node v
  /// with overlaps(v), or `none`. The walk visits at most M nodes, stops before `stop` or
  /// `also_stop`, after the open front's end wall, and (closed form, with `angles`) once it has
  /// turned by more than half a turn about O, `acc` being the angle already turned (Sec. 2.4.2:
  /// what lies beyond is on the other side of the active segment).
  template <class Overlaps>
  std::int32_t first_overlap(std::int32_t from, bool forward, std::int32_t stop, std::int32_t also_stop, double acc,
                             bool angles, Overlaps&& overlaps) const {
    const std::int32_t* const step = front_.links(forward);
    const std::int32_t end_wall = forward ? right_ : left_;
    std::size_t steps = 0;
    for (std::int32_t v = from; v != stop && v != also_stop && steps < window_; ++steps) {
      const auto vi = static_cast<std::size_t>(v);
      if (angles) {
        acc += forward ? angle(front_.prev(v), v) : angle(v, front_.next(v));
        if (acc > std::numbers::pi) {
          break;
        }
      }
      if (overlaps(v)) {
        return v;
      }
      if (Open && v == end_wall) {
        break;
      }
      v = step[vi];
    }
    return none_;
  }

 private:
  const std::vector<Node>& nodes_;
  const Front& front_;
  const PeriodicWrap& wrap_;
  std::size_t window_;
  double rmax_;
  std::int32_t none_, left_, right_;
  double ox_ = 0, oy_ = 0;
  bool turning_ = true;
};

}  // namespace frontpack::detail
