// The validator of a domain's rings (domain/validate.cpp), one class whose checks live in one
// file each: the pairwise classification of edges and the hubs (edge_pairs.cpp), touches and the
// nesting of rings (ring_nesting.cpp), the connectivity of each polygon's interior
// (ring_connectivity.cpp). Every decision exact.
#pragma once

#include <CGAL/Bbox_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/box_intersection_d.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <deque>
#include <optional>
#include <stdexcept>
#include <string>
#include <tuple>
#include <vector>

#include "common/format.hpp"
#include "domain/edge_sweep.hpp"
#include "domain/ring_set.hpp"
#include "domain/ring_tree.hpp"
#include "exact/predicates.hpp"

#include "domain/edge_grid.hpp"

namespace frontpack::detail::validation {

using Kind = InvalidDomainError::Kind;
using Site = InvalidDomainError::Site;

// A constructed (rounded) point: 10 significant digits are all that mean anything.
inline std::string format_point_approx(Point p) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "(%.10g %.10g)", p.x, p.y);
  return buf;
}

struct Touch {
  Point p;
  std::uint32_t ring_a;
  std::uint32_t ring_b;
  std::uint32_t edge_a;  // an edge of ring_a through p
  std::uint32_t edge_b;  // an edge of ring_b through p
};

inline bool point_less(Point a, Point b) noexcept {
  return std::tie(a.x, a.y) < std::tie(b.x, b.y);
}

class Validator {
 public:
  Validator(const RingSet& rs, const SourceLocator& where) : rs_(rs), where_(where) {}

  void run(EdgeGrid& grid);

 private:
  [[nodiscard]] const RingInfo& ring(std::uint32_t r) const { return rs_.rings[r]; }
  [[nodiscard]] std::string name(std::uint32_t r) const { return ring_name(ring(r).part, ring(r).ring); }
  [[nodiscard]] Site site(std::uint32_t vertex) const {
    const RingInfo& info = ring(rs_.ring_of[vertex]);
    return Site{info.part, info.ring, rs_.source[vertex]};
  }
  [[nodiscard]] std::string vertex(std::uint32_t k) const {
    const RingInfo& info = ring(rs_.ring_of[k]);
    return vertex_text(info.part, info.ring, rs_.source[k], rs_.v[k], where_);
  }
  [[nodiscard]] std::string edge(std::uint32_t e) const {
    return "edge " + std::to_string(rs_.source[e]) + " " + format_point(rs_.v[e]) + "-" +
           format_point(rs_.v[rs_.next[e]]);
  }

  void check_collinear_rings() const;

  // A problem found by the pairwise pass; the one with the smallest pair of edges is reported,
  // so the message does not depend on the order in which the boxes are visited.
  struct Problem {
    std::tuple<int, std::uint32_t, std::uint32_t> key;
    Kind kind;
    std::string detail;
    Site a;
    Site b;
    std::optional<Point> where;
  };

  // Whether a problem on edges e and f of this rank would be reported before the one kept: the
  // callers build the message only then (a degenerate ring can have millions of problem pairs).
  [[nodiscard]] bool improves(std::uint32_t e, std::uint32_t f, int rank = 1) const {
    return !problem_ ||
           std::tuple<int, std::uint32_t, std::uint32_t>{rank, std::min(e, f), std::max(e, f)} < problem_->key;
  }

  // rank 0 is reported before rank 1 (a spike names its cause better than the touches it makes).
  void report(std::uint32_t e, std::uint32_t f, Kind kind, std::string detail, std::optional<Point> where,
              int rank = 1) {
    const std::tuple<int, std::uint32_t, std::uint32_t> key{rank, std::min(e, f), std::max(e, f)};
    if (!problem_ || key < problem_->key) {
      problem_ = Problem{key, kind, std::move(detail), site(e), site(f), where};
    }
  }

  using EdgeBox =
      CGAL::Box_intersection_d::Box_with_handle_d<double, 2, const Point*, CGAL::Box_intersection_d::ID_FROM_HANDLE>;

  [[nodiscard]] EdgeBox edge_box(std::uint32_t e) const {
    const Point a = rs_.v[e];
    const Point b = rs_.v[rs_.next[e]];
    return {CGAL::Bbox_2(std::min(a.x, b.x), std::min(a.y, b.y), std::max(a.x, b.x), std::max(a.y, b.y)), &rs_.v[e]};
  }

  [[nodiscard]] std::uint32_t edge_of(const EdgeBox& b) const {
    return static_cast<std::uint32_t>(b.handle() - rs_.v.data());
  }

  void throw_problem() const {
    throw InvalidDomainError(problem_->kind, problem_->detail, problem_->a, problem_->b, problem_->where);
  }

  // The pairwise pass reports the problem with the smallest key, whatever the order the pairs come
  // in. Two things keep it from enumerating millions of pairs where a ring collapses into a few
  // ulps (every pair of its edges' boxes meets: 16,384 vertices took 6.6-8.7 s):
  // - Spikes (rank 0) come before every other problem, and only consecutive edges make one: they
  //   are looked for first, in one pass over the edges.
  // - The pass over all box pairs stops once it has classified a budget of pairs with a problem
  //   in hand. The smallest key is then found by ordered_search().
  // Pairs of edges that end at a common point where vertices of several rings meet (hubs) are
  // left to find_hubs(): k rings meeting at a point make k^2 such pairs (a fan of 8,192 parts
  // around one point, 130 million), and the box pass only counts them.
  void check_edge_pairs();

  // Thrown from a box intersection's callback to stop it (only std::vectors are unwound).
  struct Budget {};
  struct Crowded {};

  // Whether the edges meet only at their endpoints: no two edges with a common point in the
  // interior of either (a crossing, an overlap, a vertex on another edge), by a sweep over the
  // edges in exact arithmetic. Then the pairwise classification finds no problem and no touch
  // but at hubs, which find_hubs() has dealt with.
  [[nodiscard]] bool edges_disjoint() const { return edge_interiors_disjoint(rs_.v, rs_.next); }
  static std::size_t pair_budget(std::size_t edges) { return 64 * edges + (std::size_t{1} << 20); }

  // With a problem in hand (problem_), the one with the smallest key: the pairs whose smaller edge
  // lies in [lo, hi) are classified block after block, each block's edges against the edges from
  // lo on. Once hi passes the smaller edge of the problem in hand, every pair that could have a
  // smaller key has been seen. Each block costs a box intersection over the edges left plus its
  // pairs, so a problem among the first edges is found after few pairs. The blocks double while
  // their pairs stay within a budget; a block that exceeds it (a dense cluster among its edges)
  // is given up and taken again at a sixteenth of the size (a half needed many more tries: 20,000
  // clean edges before a 30,000-edge cluster, 14.6 s in blocks without a budget, 3.8 s halving,
  // 1.5 s). A single edge has fewer pairs than the budget, so the search always moves on.
  void ordered_search();

  // An edge leaving a hub: edge `edge` joins the hub's vertex `vertex` to the point `to`.
  struct Spoke {
    Point to;
    std::uint32_t edge;
    std::uint32_t vertex;
  };

  // The spokes of the hub's vertices [first, last) of hub_vertices_, in anticlockwise order about
  // p from the direction +x (exact); spokes in the same direction are adjacent.
  [[nodiscard]] std::vector<Spoke> spokes(Point p, std::size_t first, std::size_t last) const;

  [[nodiscard]] static bool same_direction(Point p, const Spoke& a, const Spoke& b) {
    return orientation(p, a.to, b.to) == 0 && dot_sign(p, a.to, b.to) > 0;
  }

  // Hubs: points where two or more vertices lie (of one ring: it touches itself; of several:
  // they touch). Of the edges ending at a hub, two that are not consecutive in one ring meet
  // there, and nowhere else unless they overlap; such a pair is a problem if the two edges
  // belong to one ring or leave the hub in the same direction, a touch otherwise. The pairs
  // with a problem that could have the smallest key are classified here: in each ring, its
  // smallest edge at the hub with the smallest edge of its other vertices there, and in each
  // direction, its two smallest edges. The touches are kept as the hub's list of vertices
  // (check_touch_crossings, check_nesting and check_connectivity read it), not pair by pair.
  void find_hubs();

  // The box pass's classification, leaving the pairs that meet at a hub to find_hubs(): two
  // edges with a common endpoint that are not consecutive in one ring.
  void classify_unless_hub(std::uint32_t e, std::uint32_t f);

  void classify(std::uint32_t e, std::uint32_t f);
  // classify()'s cases, for e < f: consecutive edges of one ring (a fold back is a spike),
  // collinear edges (an overlap, or a touch at a common endpoint), and edges that cross.
  void classify_consecutive(std::uint32_t e, std::uint32_t f);
  void classify_collinear(std::uint32_t e, std::uint32_t f);
  void report_crossing(std::uint32_t e, std::uint32_t f);

  void touch(std::uint32_t e, std::uint32_t f, Point t);

  // The two neighbours of point p along ring edge e (p is on e): the path prev -> p -> next.
  [[nodiscard]] std::pair<Point, Point> neighbours(std::uint32_t e, Point p) const;

  // A vertex at the touch point: of ring a if it has one there, else of ring b.
  [[nodiscard]] std::uint32_t vertex_at(const Touch& t) const;

  // Whether q lies strictly inside the wedge swept anticlockwise about apex s from direction u
  // to direction w (u and w are points on the wedge's two rays).
  [[nodiscard]] static bool in_wedge(Point s, Point u, Point w, Point q);

  // Rings that meet at a point must not cross there: the other ring's two edges at the point
  // must both lie on the same side of this ring's path through it.
  void check_touch_crossings();

  // A point of ring r that lies on no other ring: a vertex that is not a touch point, else a
  // point on an edge between touch points (computed exactly, tested without the grid).
  [[nodiscard]] std::optional<std::uint32_t> free_vertex(std::uint32_t r, const std::vector<Point>& touch_points) const;

  // Parity of the crossings of a horizontal ray from an exact point with each ring other than
  // `self` (brute force, exact constructions): the fallback when every vertex of a ring touches
  // another ring.
  [[nodiscard]] std::vector<std::uint32_t> odd_rings_exact(std::uint32_t self) const;

  // Nesting: holes inside their own outer ring and in no other hole of it; an outer ring
  // inside another polygon only within one of its holes. Ring by ring, misplaced() takes the
  // parity of a ray from a point of the ring on no other ring: through the edge grid, a row of
  // cells per ring, or by brute force where every vertex of the ring touches another ring. That
  // is quadratic where rays cross many rings (a row of parts) or many rings need brute force (a
  // checkerboard: 174 s for 8,192 squares). So when the rays would cost more than a few times the
  // number of edges, the nesting tree (domain/ring_tree.hpp, one sweep) decides for every ring at once,
  // and misplaced() only phrases the report of the first ring found wrong: the message is the one
  // the ring-by-ring search gives.
  void check_nesting(const EdgeGrid& grid) const;

  // The rings that break a nesting rule, from the tree (parent[r]: innermost ring containing r).
  // A depth-first walk keeps, for each polygon, whether its outer ring and how many of its holes
  // enclose the ring visited, and how many polygons enclose it through their outer ring alone.
  [[nodiscard]] std::vector<std::uint8_t> misplaced_rings(const std::vector<std::uint32_t>& parent) const;

  // Reports ring r if it breaks a nesting rule, by the parity of a ray from a point of r on no
  // other ring (touch_points: the points where r touches other rings, sorted).
  void misplaced(const EdgeGrid& grid, std::uint32_t r, const std::vector<Point>& touch_points) const;

  // Within one polygon, rings that touch must not close a loop: a cycle in the graph of rings
  // and touch points cuts the interior in two (OGC: the interior must be connected).
  void check_connectivity() const;

  // Reports the loop closed by linking `ring` to touch node `node`: the path between them
  // through the links made so far, found breadth first.
  [[noreturn]] void throw_loop(std::uint32_t part, std::uint32_t ring_id, std::uint32_t node,
                               const std::vector<std::pair<std::uint32_t, std::uint32_t>>& joined,
                               const std::vector<Point>& point_of) const;

  const RingSet& rs_;
  const SourceLocator& where_;
  std::optional<Problem> problem_;
  std::vector<Touch> touches_;  // touches found pair by pair (not at hubs)
  // Hub h: the point hubs_[h].p and its vertices hub_vertices_[hubs_[h].first, hubs_[h + 1].first),
  // sorted by ring; the last entry of hubs_ only ends the list.
  struct Hub {
    Point p;
    std::uint32_t first;
  };
  std::vector<Hub> hubs_;
  std::vector<std::uint32_t> hub_vertices_;
};

}  // namespace frontpack::detail::validation
