// Where the boundary front starts (seeding.hpp): the rings' walls, reflex vertices and first gaps,
// and the seed pairs inside. Out of line: set-up, and seeds are rare.
#include "generate/boundary/seeding.hpp"

#include <algorithm>
#include <cmath>

namespace frontpack::detail {

namespace {

constexpr int kSeedTries = 256;

// Adds a ring's walls, reflex vertices and first gaps to `s`.
void add_ring(Seeding& s, const Ring& ring, const RunFrame& frame) {
  const std::size_t n = ring.size();
  const auto first = static_cast<std::int32_t>(s.walls.size());
  for (std::size_t i = 0; i < n; ++i) {
    const Point a = frame.local(ring[i]);
    const Point b = frame.local(ring[(i + 1) % n]);
    s.walls.push_back(make_wall(a.x, a.y, b.x, b.y));
  }
  // Corner at vertex i + 1, between wall i (in) and wall i + 1 (out). The front starts at
  // every corner sharper than kSlideTurn; along gentler ones the wall layer slides from one
  // wall to the next (slide()), so a finely divided curve is not started at each of its
  // vertices (the ring's sharpest vertex starts it if none is sharp).
  s.ring_first.push_back(static_cast<std::size_t>(first));
  s.rough.resize(s.walls.size(), 0);
  std::size_t sharpest = 0;
  double sharpest_turn = -1;
  bool started = false;
  auto start_at = [&](std::size_t i, bool convex, std::int32_t v) {
    const std::int32_t in = -(first + static_cast<std::int32_t>(i) + 1);
    const std::int32_t out = -(first + static_cast<std::int32_t>((i + 1) % n) + 1);
    if (convex) {
      s.gaps.push_back(Gap{in, out});
    } else {
      s.gaps.push_back(Gap{in, v});
      s.gaps.push_back(Gap{v, out});
    }
    started = true;
  };
  std::vector<std::int32_t> vertex(n, kNoElement);  // the reflex vertex's node, per vertex
  for (std::size_t i = 0; i < n; ++i) {
    const Wall& wi = s.walls[static_cast<std::size_t>(first) + i];
    const Wall& wo = s.walls[static_cast<std::size_t>(first) + (i + 1) % n];
    const double cross = wi.tx * wo.ty - wi.ty * wo.tx;  // > 0: left turn, a convex corner
    const double dot = wi.tx * wo.tx + wi.ty * wo.ty;    // the cosine of the turn
    // A key that grows with the turn over [0, pi] (its sine, then 2 minus it), from * and -
    // alone: with std::atan2, whose last bit differs between C libraries, the vertex that
    // starts a ring without a corner could too.
    const double turn = dot > 0 ? std::abs(cross) : 2 - std::abs(cross);
    const bool sharp = dot <= kCosSlideTurn;  // turns by kSlideTurn or more
    const bool convex = cross > 1e-12;
    if (!convex) {
      vertex[i] = static_cast<std::int32_t>(s.corners.size());
      s.corners.push_back(Corner{wi.tx, wi.ty, wo.tx, wo.ty});
      s.corner_at.push_back(Point{wi.bx, wi.by});
    }
    if (sharp && wi.len < 2 * frame.rmax) {
      s.rough[static_cast<std::size_t>(first) + i] = 1;
    }
    if (sharp && wo.len < 2 * frame.rmax) {
      s.rough[static_cast<std::size_t>(first) + (i + 1) % n] = 1;
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
    const Wall& wi = s.walls[static_cast<std::size_t>(first) + sharpest];
    const Wall& wo = s.walls[static_cast<std::size_t>(first) + (sharpest + 1) % n];
    start_at(sharpest, wi.tx * wo.ty - wi.ty * wo.tx > 1e-12, vertex[sharpest]);
  }
}

// Whether a disk at (x, y) of radius r crosses no wall and overlaps no disk (with its centre
// inside the polygon, it then lies inside).
bool fits(Obstacles& obstacles, const Elements& elements, const RunFrame& frame, double x, double y, double r) {
  if (!(x - r >= 0 && x + r <= frame.width && y - r >= 0 && y + r <= frame.height)) {
    return false;
  }
  return obstacles.deepest<true>(elements, obstacles.probe(x, y, r)) == kNoElement;
}

}  // namespace

Box outer_box(const Polygon& polygon) noexcept {
  Box box;
  for (const Point& p : polygon.outer) {
    box.extend(p);
  }
  return box;
}

Seeding seed_at_corners(const Polygon& polygon, const RunFrame& frame) {
  Seeding s;
  add_ring(s, polygon.outer, frame);
  for (const Ring& hole : polygon.holes) {
    add_ring(s, hole, frame);
  }
  s.any_rough = std::find(s.rough.begin(), s.rough.end(), 1) != s.rough.end();
  for (const Wall& w : s.walls) {
    s.area += (w.ax * w.by - w.bx * w.ay) / 2;  // holes (clockwise) subtract
  }
  return s;
}

Seeding seed_periodic_cell(const RunFrame& frame, Periodicity periodicity) {
  Seeding s;
  if (periodicity == Periodicity::x) {
    const double reach = 4 * frame.rmax;
    s.walls.push_back(make_wall(-reach, 0, frame.width + reach, 0));                        // bottom, inside above
    s.walls.push_back(make_wall(frame.width + reach, frame.height, -reach, frame.height));  // top, inside below
    s.ring_first = {0, 1};
    s.rough = {0, 0};
  }
  s.area = frame.width * frame.height;
  return s;
}

std::array<std::optional<Point>, 2> seed_on_walls(const RunFrame& frame, Rng& rng, double r, double r2) {
  std::array<std::optional<Point>, 2> at;
  const double bottom = r + frame.clearance;
  if (bottom + r + frame.clearance <= frame.height) {
    at[0] = Point{frame.width * rng.uniform(), bottom};
  }
  const double top = frame.height - r2 - frame.clearance;
  const double x2 = frame.width * rng.uniform();
  if (at[0] && top - bottom >= r + r2 + frame.clearance) {
    at[1] = Point{x2, top};
  }
  return at;
}

std::optional<Point> seed_pair_at(Obstacles& obstacles, const Elements& elements, const RunFrame& frame, Rng& rng,
                                  double r, double r2) {
  for (int t = 0; t < kSeedTries; ++t) {
    const double sx = frame.width * rng.uniform();
    const double sy = frame.height * rng.uniform();
    const double tx = sx + r + r2 + frame.clearance;
    if (!obstacles.inside(sx, sy) || !fits(obstacles, elements, frame, sx, sy, r) ||
        !fits(obstacles, elements, frame, tx, sy, r2)) {
      continue;
    }
    // The pair apart by the clearance, as tangent disks are (this cannot fail; checked before
    // the first disk is placed, so that nothing is left behind if it did).
    if (obstacles.depth(obstacles.probe(tx, sy, r2), BoundaryNode{sx, sy, r, kNoElement, 0}) > 0) {
      continue;
    }
    return Point{sx, sy};
  }
  return std::nullopt;
}

}  // namespace frontpack::detail
