// A candidate on a finely divided boundary (a curve as many short edges): the wall it touches is
// moved along the ring to the wall nearest to it, so that a gently turning boundary supports the
// disk (docs/boundary-method.md). Header-only and CGAL-free: it runs at every move of a try.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "generate/boundary/elements.hpp"
#include "generate/boundary/obstacles.hpp"
#include "generate/boundary/walls.hpp"

namespace frontpack::detail {

/// The ring wall e belongs to, `ring_first` holding the first wall of each ring.
[[nodiscard]] inline std::size_t ring_of(const std::vector<std::size_t>& ring_first, std::int32_t e) noexcept {
  const std::size_t i = wall_index(e);
  return static_cast<std::size_t>(std::upper_bound(ring_first.begin(), ring_first.end(), i) - ring_first.begin()) - 1;
}

/// A candidate (px, py) of radius r touching a wall and a node, (x, y) in either order, whose foot
/// on the wall lies beyond the edge: along a gently turning boundary it touches the next wall
/// instead. It is recomputed against the wall nearest to it, if that wall is on the same ring and
/// turned by less than kSlideTurn from the first, a few times over; otherwise it is left as it is,
/// for Elements::supported_by() to refuse.
inline void slide(const Elements& elements, const Obstacles& obstacles, const std::vector<std::size_t>& ring_first,
                  std::int32_t& x, std::int32_t& y, double r, double& px, double& py) {
  for (int k = 0; k < 4; ++k) {
    if (Elements::is_wall(x) == Elements::is_wall(y)) {
      return;
    }
    const bool wall_first = Elements::is_wall(x);
    const std::int32_t w = wall_first ? x : y;
    if (elements.supported_by(w, px, py)) {
      return;
    }
    double d2 = distance2(elements.wall(w), px, py);
    const std::int32_t e = obstacles.nearest(px, py, d2, w);
    if (e == kNoElement || e == w || ring_of(ring_first, e) != ring_of(ring_first, w)) {
      return;
    }
    const Wall& a = elements.wall(w);
    const Wall& b = elements.wall(e);
    if (a.tx * b.tx + a.ty * b.ty < kCosSlideTurn) {
      return;
    }
    double qx = 0;
    double qy = 0;
    if (!(wall_first ? elements.tangent(e, y, r, qx, qy) : elements.tangent(x, e, r, qx, qy))) {
      return;
    }
    (wall_first ? x : y) = e;
    px = qx;
    py = qy;
  }
}

}  // namespace frontpack::detail
