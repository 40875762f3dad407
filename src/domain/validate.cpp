// Validation of polygonal domains by the OGC Simple Features rules, decided exactly.
//
// Why not CGAL::is_valid_polygon_with_holes: its hole test is quadratic in practice (measured
// 18-24 s for 30k edges, 459 s for 100k, see shared/design.md) and it prints. Here every pair of
// edges whose boxes meet is found by CGAL::box_self_intersection_d and classified with exact
// orientation tests; ring nesting is decided by exact ray parity through the edge grid, or where
// that would be quadratic by a plane sweep that finds each ring's innermost enclosing ring
// (domain/ring_tree.cpp, exact orientation tests); and the connectivity of each polygon's interior
// follows from the graph of touching rings. Where the edges' boxes meet in far more pairs than
// there are edges (long edges fanning around a common region, as in a star with thousands of
// spikes) and none of them has shown a problem or a touch, a sweep (domain/edge_sweep.cpp, O(n log n))
// decides whether any pair would. Points where the vertices of many rings meet (hubs) are
// classified by sorting their edges by angle, not pair by pair (find_hubs()).

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

#include "domain/edge_sweep.hpp"
#include "exact/predicates.hpp"
#include "common/format.hpp"
#include "domain/ring_set.hpp"
#include "domain/ring_tree.hpp"

namespace frontpack::detail {

namespace {

using Kind = InvalidDomainError::Kind;
using Site = InvalidDomainError::Site;

// A constructed (rounded) point: 10 significant digits are all that mean anything.
std::string format_point_approx(Point p) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "(%.10g %.10g)", p.x, p.y);
  return buf;
}

// ---------------------------------------------------------------------------------------------
// Pairwise edge classification

struct Touch {
  Point p;
  std::uint32_t ring_a;
  std::uint32_t ring_b;
  std::uint32_t edge_a;  // an edge of ring_a through p
  std::uint32_t edge_b;  // an edge of ring_b through p
};

bool point_less(Point a, Point b) noexcept {
  return std::tie(a.x, a.y) < std::tie(b.x, b.y);
}

class Validator {
 public:
  Validator(const RingSet& rs, const SourceLocator& where) : rs_(rs), where_(where) {}

  void run(EdgeGrid& grid) {
    check_collinear_rings();
    check_edge_pairs();
    check_touch_crossings();
    grid.build(rs_.v, rs_.next, rs_.bbox, std::max<std::size_t>(4 * rs_.v.size(), 4096));
    check_nesting(grid);
    check_connectivity();
    grid.classify_cells();
  }

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

  void check_collinear_rings() const {
    for (std::uint32_t r = 0; r < rs_.rings.size(); ++r) {
      const RingInfo& info = ring(r);
      const Point a = rs_.v[info.first];
      const Point b = rs_.v[info.first + 1];  // differs from a: repeats were removed
      bool flat = true;
      for (std::uint32_t k = 2; k < info.count && flat; ++k) {
        flat = orientation(a, b, rs_.v[info.first + k]) == 0;
      }
      if (flat) {
        throw InvalidDomainError(
            Kind::zero_area,
            name(r) + ": the ring has zero area: all its vertices are collinear, from " + vertex(info.first),
            site(info.first), {}, a);
      }
    }
  }

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
  void check_edge_pairs() {
    for (std::uint32_t e = 0; e < rs_.v.size(); ++e) {
      classify(e, rs_.next[e]);  // consecutive edges: a problem there is a spike (rank 0)
    }
    if (problem_) {
      throw_problem();
    }
    find_hubs();
    std::vector<EdgeBox> boxes;
    boxes.reserve(rs_.v.size());
    for (std::uint32_t e = 0; e < rs_.v.size(); ++e) {
      boxes.push_back(edge_box(e));
    }
    const std::size_t budget = pair_budget(boxes.size());
    // A valid ring's boxes meet in about two pairs per edge; far more, with nothing reported so
    // far, and the sweep decides (about 0.1 s for a 50,000-edge star: 1.2 x 10^8 box pairs).
    const std::size_t crowd = 16 * boxes.size() + (std::size_t{1} << 16);
    bool swept = false;
    for (;;) {
      std::size_t pairs = 0;
      try {
        CGAL::box_self_intersection_d(boxes.begin(), boxes.end(), [&](const EdgeBox& x, const EdgeBox& y) {
          classify_unless_hub(edge_of(x), edge_of(y));
          ++pairs;
          if (pairs > budget && problem_) {
            throw Budget{};
          }
          if (pairs > crowd && !swept && !problem_ && touches_.empty()) {
            throw Crowded{};
          }
        });
      } catch (const Budget&) {
        ordered_search();
      } catch (const Crowded&) {
        // Nothing found in the budget's pairs. If no two edges meet anywhere but at the vertex
        // they share, the pairs left have nothing to report either; otherwise classify them all,
        // from the start (those seen so far reported nothing, so seeing them again changes
        // nothing).
        if (edges_disjoint()) {
          return;
        }
        swept = true;
        continue;
      }
      break;
    }
    if (problem_) {
      throw_problem();
    }
  }

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
  void ordered_search() {
    const std::size_t n = rs_.v.size();
    std::size_t lo = 0;
    std::size_t size = 64;
    while (lo < n) {
      const std::size_t hi = std::min(n, lo + size);
      std::vector<EdgeBox> block;
      std::vector<EdgeBox> rest;
      block.reserve(hi - lo);
      rest.reserve(n - hi);
      for (std::size_t e = lo; e < n; ++e) {
        (e < hi ? block : rest).push_back(edge_box(static_cast<std::uint32_t>(e)));
      }
      const std::size_t budget = pair_budget(n - lo);
      std::size_t pairs = 0;
      const auto visit = [&](const EdgeBox& x, const EdgeBox& y) {
        classify_unless_hub(edge_of(x), edge_of(y));
        if (++pairs > budget) {
          throw Budget{};
        }
      };
      try {
        // Pairs within the block, then the block against the edges after it.
        CGAL::box_self_intersection_d(block.begin(), block.end(), visit);
        CGAL::box_intersection_d(block.begin(), block.end(), rest.begin(), rest.end(), visit);
      } catch (const Budget&) {
        size = std::max<std::size_t>(1, size / 16);
        continue;
      }
      if (std::get<1>(problem_->key) < hi) {
        return;
      }
      lo = hi;
      size *= 2;
    }
  }

  // An edge leaving a hub: edge `edge` joins the hub's vertex `vertex` to the point `to`.
  struct Spoke {
    Point to;
    std::uint32_t edge;
    std::uint32_t vertex;
  };

  // The spokes of the hub's vertices [first, last) of hub_vertices_, in anticlockwise order about
  // p from the direction +x (exact); spokes in the same direction are adjacent.
  [[nodiscard]] std::vector<Spoke> spokes(Point p, std::size_t first, std::size_t last) const {
    std::vector<Spoke> out;
    out.reserve(2 * (last - first));
    for (std::size_t i = first; i < last; ++i) {
      const std::uint32_t k = hub_vertices_[i];
      out.push_back({rs_.v[rs_.prev[k]], rs_.prev[k], k});
      out.push_back({rs_.v[rs_.next[k]], k, k});
    }
    const auto upper = [p](Point q) { return q.y > p.y || (q.y == p.y && q.x > p.x); };
    std::sort(out.begin(), out.end(), [&](const Spoke& a, const Spoke& b) {
      const bool ua = upper(a.to);
      const bool ub = upper(b.to);
      if (ua != ub) {
        return ua;
      }
      if (const int turn = orientation(p, a.to, b.to); turn != 0) {
        return turn > 0;
      }
      return a.edge < b.edge;  // the same direction: a fixed order
    });
    return out;
  }

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
  void find_hubs() {
    struct At {
      Point p;
      std::uint32_t vertex;
    };
    std::vector<At> order(rs_.v.size());
    for (std::uint32_t k = 0; k < order.size(); ++k) {
      order[k] = {rs_.v[k], k};
    }
    std::sort(order.begin(), order.end(), [](const At& a, const At& b) {
      return std::tie(a.p.x, a.p.y, a.vertex) < std::tie(b.p.x, b.p.y, b.vertex);
    });
    for (std::size_t i = 0; i < order.size();) {
      std::size_t j = i + 1;
      while (j < order.size() && order[j].p == order[i].p) {
        ++j;
      }
      if (j - i >= 2) {
        const Point p = order[i].p;
        const std::size_t first = hub_vertices_.size();
        for (std::size_t k = i; k < j; ++k) {
          hub_vertices_.push_back(order[k].vertex);
        }
        std::sort(hub_vertices_.begin() + static_cast<std::ptrdiff_t>(first), hub_vertices_.end(),
                  [this](std::uint32_t a, std::uint32_t b) {
                    return std::tie(rs_.ring_of[a], a) < std::tie(rs_.ring_of[b], b);
                  });
        hubs_.push_back({p, static_cast<std::uint32_t>(first)});
        // One ring with several vertices here.
        for (std::size_t a = first; a < hub_vertices_.size();) {
          std::size_t b = a + 1;
          while (b < hub_vertices_.size() && rs_.ring_of[hub_vertices_[b]] == rs_.ring_of[hub_vertices_[a]]) {
            ++b;
          }
          if (b - a >= 2) {
            const auto smallest_edge = [this](std::uint32_t k) { return std::min(rs_.prev[k], k); };
            std::size_t lowest = a;
            for (std::size_t c = a + 1; c < b; ++c) {
              if (smallest_edge(hub_vertices_[c]) < smallest_edge(hub_vertices_[lowest])) {
                lowest = c;
              }
            }
            std::uint32_t other = UINT32_MAX;
            for (std::size_t c = a; c < b; ++c) {
              if (c != lowest) {
                other = std::min(other, smallest_edge(hub_vertices_[c]));
              }
            }
            classify(smallest_edge(hub_vertices_[lowest]), other);
          }
          a = b;
        }
        // Edges leaving in the same direction.
        const std::vector<Spoke> around = spokes(p, first, hub_vertices_.size());
        for (std::size_t a = 0; a + 1 < around.size();) {
          std::size_t b = a + 1;
          while (b < around.size() && same_direction(p, around[a], around[b])) {
            ++b;
          }
          if (b - a >= 2) {
            std::uint32_t e1 = UINT32_MAX;
            std::uint32_t e2 = UINT32_MAX;
            for (std::size_t c = a; c < b; ++c) {
              const std::uint32_t e = around[c].edge;
              if (e < e1) {
                e2 = e1;
                e1 = e;
              } else if (e < e2) {
                e2 = e;
              }
            }
            classify(e1, e2);
          }
          a = b;
        }
      }
      i = j;
    }
    hubs_.push_back({Point{}, static_cast<std::uint32_t>(hub_vertices_.size())});  // end marker
  }

  // The box pass's classification, leaving the pairs that meet at a hub to find_hubs(): two
  // edges with a common endpoint that are not consecutive in one ring.
  void classify_unless_hub(std::uint32_t e, std::uint32_t f) {
    const Point A = rs_.v[e];
    const Point B = rs_.v[rs_.next[e]];
    const Point C = rs_.v[f];
    const Point D = rs_.v[rs_.next[f]];
    if ((A == C || A == D || B == C || B == D) && rs_.next[e] != f && rs_.next[f] != e) {
      return;
    }
    classify(e, f);
  }

  void classify(std::uint32_t e, std::uint32_t f) {
    if (f < e) {
      std::swap(e, f);  // name the edges in input order
    }
    const Point A = rs_.v[e];
    const Point B = rs_.v[rs_.next[e]];
    const Point C = rs_.v[f];
    const Point D = rs_.v[rs_.next[f]];
    const std::uint32_t re = rs_.ring_of[e];
    const std::uint32_t rf = rs_.ring_of[f];
    const bool same_ring = re == rf;

    if (same_ring && (rs_.next[e] == f || rs_.next[f] == e)) {
      // Consecutive edges p -> s -> q meet at s; they overlap only if q folds back onto p's side.
      const bool e_first = rs_.next[e] == f;
      const Point p = e_first ? A : C;
      const Point s = e_first ? B : A;
      const Point q = e_first ? D : B;
      const std::uint32_t at = e_first ? f : e;
      if (orientation(p, s, q) == 0 && dot_sign(s, p, q) > 0 && improves(e, f, 0)) {
        report(e, f, Kind::self_intersection,
               name(re) + ": " + edge(e) + " and " + edge(f) + " fold back on each other at " + vertex(at) +
                   " (a zero-width spike)",
               s, 0);
      }
      return;
    }

    const int o1 = orientation(A, B, C);
    const int o2 = orientation(A, B, D);
    if (o1 == 0 && o2 == 0) {
      // Collinear: compare the two intervals on the line along a non-degenerate axis.
      const bool use_x = A.x != B.x;
      const auto lo_hi = [use_x](Point a, Point b) {
        const double s = use_x ? a.x : a.y;
        const double t = use_x ? b.x : b.y;
        return std::pair{std::min(s, t), std::max(s, t)};
      };
      const auto [l1, h1] = lo_hi(A, B);
      const auto [l2, h2] = lo_hi(C, D);
      const double lo = std::max(l1, l2);
      const double hi = std::min(h1, h2);
      if (lo > hi) {
        return;
      }
      if (lo < hi) {
        if (same_ring) {
          if (improves(e, f)) {
            report(e, f, Kind::self_intersection, name(re) + ": " + edge(e) + " and " + edge(f) + " overlap", {});
          }
        } else if (improves(e, f)) {
          report(e, f, Kind::rings_overlap,
                 name(re) + " and " + name(rf) + " share a segment: " + edge(e) + " of the first overlaps " + edge(f) +
                     " of the second",
                 {});
        }
        return;
      }
      // A single common point: an endpoint of both.
      const Point t = (A == C || A == D) ? A : B;
      touch(e, f, t);
      return;
    }
    const int o3 = orientation(C, D, A);
    const int o4 = orientation(C, D, B);
    if (o1 * o2 < 0 && o3 * o4 < 0) {
      if (!improves(e, f)) {
        return;
      }
      const auto x =
          CGAL::intersection(Kernel::Segment_2(to_cgal(A), to_cgal(B)), Kernel::Segment_2(to_cgal(C), to_cgal(D)));
      std::optional<Point> at;
      if (x) {
        if (const auto* pt = boost::get<KPoint>(&*x)) {
          at = Point{pt->x(), pt->y()};
        }
      }
      const std::string near = at ? " near " + format_point_approx(*at) : "";
      if (same_ring) {
        report(e, f, Kind::self_intersection, name(re) + ": " + edge(e) + " and " + edge(f) + " cross" + near, at);
      } else {
        report(e, f, Kind::rings_cross,
               name(re) + " and " + name(rf) + " cross: " + edge(e) + " of the first crosses " + edge(f) +
                   " of the second" + near,
               at);
      }
      return;
    }
    std::optional<Point> t;
    if (o1 == 0 && on_segment(C, A, B)) {
      t = C;
    } else if (o2 == 0 && on_segment(D, A, B)) {
      t = D;
    } else if (o3 == 0 && on_segment(A, C, D)) {
      t = A;
    } else if (o4 == 0 && on_segment(B, C, D)) {
      t = B;
    }
    if (t) {
      touch(e, f, *t);
    }
  }

  void touch(std::uint32_t e, std::uint32_t f, Point t) {
    const std::uint32_t re = rs_.ring_of[e];
    const std::uint32_t rf = rs_.ring_of[f];
    if (re == rf) {
      // OGC: a ring must be simple; touching itself (even at a vertex) is a self-intersection.
      if (!improves(e, f)) {
        return;
      }
      report(e, f, Kind::self_intersection,
             name(re) + ": " + edge(e) + " and " + edge(f) + " touch at " + format_point(t) +
                 " (a ring may not touch itself)",
             t);
      return;
    }
    touches_.push_back(re < rf ? Touch{t, re, rf, e, f} : Touch{t, rf, re, f, e});
  }

  // The two neighbours of point p along ring edge e (p is on e): the path prev -> p -> next.
  [[nodiscard]] std::pair<Point, Point> neighbours(std::uint32_t e, Point p) const {
    const std::uint32_t b = rs_.next[e];
    if (p == rs_.v[e]) {
      return {rs_.v[rs_.prev[e]], rs_.v[b]};
    }
    if (p == rs_.v[b]) {
      return {rs_.v[e], rs_.v[rs_.next[b]]};
    }
    return {rs_.v[e], rs_.v[b]};
  }

  // A vertex at the touch point: of ring a if it has one there, else of ring b.
  [[nodiscard]] std::uint32_t vertex_at(const Touch& t) const {
    for (const std::uint32_t e : {t.edge_a, t.edge_b}) {
      if (rs_.v[e] == t.p) {
        return e;
      }
      if (rs_.v[rs_.next[e]] == t.p) {
        return rs_.next[e];
      }
    }
    return t.edge_a;  // unreachable: a touch point is a vertex of one of the rings
  }

  // Whether q lies strictly inside the wedge swept anticlockwise about apex s from direction u
  // to direction w (u and w are points on the wedge's two rays).
  [[nodiscard]] static bool in_wedge(Point s, Point u, Point w, Point q) {
    const int turn = orientation(s, u, w);
    if (turn > 0) {
      return orientation(s, u, q) > 0 && orientation(s, q, w) > 0;
    }
    if (turn < 0) {
      return orientation(s, u, q) > 0 || orientation(s, q, w) > 0;
    }
    return orientation(s, u, q) > 0;  // a straight angle: the half-plane left of s -> u
  }

  // Rings that meet at a point must not cross there: the other ring's two edges at the point
  // must both lie on the same side of this ring's path through it.
  void check_touch_crossings() {
    // At a hub, rings cross iff their edges interleave about it: each ring has two edges there
    // (it passes the hub once, or it touches itself: reported before), and listed in order about
    // the hub, no two rings may alternate (a stack of the rings open). Where some do, every pair
    // of the hub's rings joins the pairwise test below, which names the first crossing.
    std::vector<std::uint8_t> seen(rs_.v.size(), 0);
    for (std::size_t h = 0; h + 1 < hubs_.size(); ++h) {
      const Point p = hubs_[h].p;
      const std::size_t first = hubs_[h].first;
      const std::size_t last = hubs_[h + 1].first;
      const std::vector<Spoke> around = spokes(p, first, last);
      std::vector<std::uint32_t> open;
      bool interleave = false;
      for (const Spoke& sp : around) {
        if (seen[sp.vertex] == 0) {
          seen[sp.vertex] = 1;
          open.push_back(sp.vertex);
        } else if (open.back() == sp.vertex) {
          open.pop_back();
        } else {
          interleave = true;
          break;
        }
      }
      for (const Spoke& sp : around) {
        seen[sp.vertex] = 0;
      }
      if (!interleave) {
        continue;
      }
      for (std::size_t a = first; a < last; ++a) {
        for (std::size_t b = a + 1; b < last; ++b) {
          const std::uint32_t ka = hub_vertices_[a];
          const std::uint32_t kb = hub_vertices_[b];
          const std::uint32_t ra = rs_.ring_of[ka];
          const std::uint32_t rb = rs_.ring_of[kb];
          touches_.push_back(ra < rb ? Touch{p, ra, rb, ka, kb} : Touch{p, rb, ra, kb, ka});
        }
      }
    }
    std::sort(touches_.begin(), touches_.end(), [](const Touch& a, const Touch& b) {
      return std::tie(a.ring_a, a.ring_b, a.p.x, a.p.y) < std::tie(b.ring_a, b.ring_b, b.p.x, b.p.y);
    });
    touches_.erase(std::unique(touches_.begin(), touches_.end(),
                               [](const Touch& a, const Touch& b) {
                                 return a.ring_a == b.ring_a && a.ring_b == b.ring_b && a.p == b.p;
                               }),
                   touches_.end());
    for (const Touch& t : touches_) {
      const auto [a_prev, a_next] = neighbours(t.edge_a, t.p);
      const auto [b_prev, b_next] = neighbours(t.edge_b, t.p);
      const bool in1 = in_wedge(t.p, a_next, a_prev, b_prev);
      const bool in2 = in_wedge(t.p, a_next, a_prev, b_next);
      if (in1 != in2) {
        throw InvalidDomainError(Kind::rings_cross,
                                 name(t.ring_a) + " and " + name(t.ring_b) + " cross at their common point, " +
                                     vertex(vertex_at(t)) + ", without a proper crossing of edges",
                                 site(t.edge_a), site(t.edge_b), t.p);
      }
    }
  }

  // A point of ring r that lies on no other ring: a vertex that is not a touch point, else a
  // point on an edge between touch points (computed exactly, tested without the grid).
  [[nodiscard]] std::optional<std::uint32_t> free_vertex(std::uint32_t r,
                                                         const std::vector<Point>& touch_points) const {
    const RingInfo& info = ring(r);
    for (std::uint32_t k = info.first; k < info.first + info.count; ++k) {
      if (!std::binary_search(touch_points.begin(), touch_points.end(), rs_.v[k], point_less)) {
        return k;
      }
    }
    return std::nullopt;
  }

  // Parity of the crossings of a horizontal ray from an exact point with each ring other than
  // `self` (brute force, exact constructions): the fallback when every vertex of a ring touches
  // another ring.
  [[nodiscard]] std::vector<std::uint32_t> odd_rings_exact(std::uint32_t self) const {
    using EK = CGAL::Exact_predicates_exact_constructions_kernel;
    const RingInfo& info = ring(self);
    const auto ek = [](Point p) { return EK::Point_2(p.x, p.y); };
    // Points at parameters 1/2, 1/3, 2/3, 1/4, ... of the first edge until one is on no ring.
    const EK::Point_2 a = ek(rs_.v[info.first]);
    const EK::Point_2 b = ek(rs_.v[rs_.next[info.first]]);
    for (int den = 2; den < 64; ++den) {
      for (int num = 1; num < den; ++num) {
        const EK::FT t = EK::FT(num) / EK::FT(den);
        const EK::Point_2 p = a + (b - a) * t;
        bool on_other = false;
        std::vector<std::uint8_t> parity(rs_.rings.size(), 0);
        for (std::uint32_t e = 0; e < rs_.v.size() && !on_other; ++e) {
          if (rs_.ring_of[e] == self) {
            continue;
          }
          EK::Point_2 lo = ek(rs_.v[e]);
          EK::Point_2 hi = ek(rs_.v[rs_.next[e]]);
          if (EK::Segment_2(lo, hi).has_on(p)) {
            on_other = true;
            break;
          }
          if ((lo.y() > p.y()) == (hi.y() > p.y())) {
            continue;
          }
          if (lo.y() > hi.y()) {
            std::swap(lo, hi);
          }
          if (CGAL::orientation(lo, hi, p) == CGAL::LEFT_TURN) {
            parity[rs_.ring_of[e]] ^= 1U;
          }
        }
        if (!on_other) {
          std::vector<std::uint32_t> odd;
          for (std::uint32_t r = 0; r < parity.size(); ++r) {
            if (parity[r] != 0) {
              odd.push_back(r);
            }
          }
          return odd;
        }
      }
    }
    // Unreachable for a valid set of rings: an edge meets other rings in finitely many points.
    throw InvalidDomainError(Kind::rings_overlap, name(self) + ": the ring lies on other rings", site(info.first));
  }

  // Nesting: holes inside their own outer ring and in no other hole of it; an outer ring
  // inside another polygon only within one of its holes. Ring by ring, misplaced() takes the
  // parity of a ray from a point of the ring on no other ring: through the edge grid, a row of
  // cells per ring, or by brute force where every vertex of the ring touches another ring. That
  // is quadratic where rays cross many rings (a row of parts) or many rings need brute force (a
  // checkerboard: 174 s for 8,192 squares). So when the rays would cost more than a few times the
  // number of edges, the nesting tree (domain/ring_tree.hpp, one sweep) decides for every ring at once,
  // and misplaced() only phrases the report of the first ring found wrong: the message is the one
  // the ring-by-ring search gives.
  void check_nesting(const EdgeGrid& grid) const {
    std::vector<std::vector<Point>> touch_points(rs_.rings.size());
    for (const Touch& t : touches_) {
      touch_points[t.ring_a].push_back(t.p);
      touch_points[t.ring_b].push_back(t.p);
    }
    for (std::size_t h = 0; h + 1 < hubs_.size(); ++h) {
      for (std::size_t i = hubs_[h].first; i < hubs_[h + 1].first; ++i) {
        touch_points[rs_.ring_of[hub_vertices_[i]]].push_back(hubs_[h].p);
      }
    }
    for (auto& pts : touch_points) {
      std::sort(pts.begin(), pts.end(), point_less);
    }
    const std::size_t n = rs_.v.size();
    const std::size_t budget = 8 * n + 4096;
    std::size_t cost = 0;
    for (std::uint32_t r = 0; r < rs_.rings.size() && cost <= budget; ++r) {
      const std::optional<std::uint32_t> k = free_vertex(r, touch_points[r]);
      cost += k ? grid.ray_cost(rs_.v[*k]) : 16 * n;
    }
    if (cost <= budget) {
      for (std::uint32_t r = 0; r < rs_.rings.size(); ++r) {
        misplaced(grid, r, touch_points[r]);
      }
      return;
    }
    const std::vector<std::uint8_t> wrong = misplaced_rings(ring_parents(rs_));
    for (std::uint32_t r = 0; r < wrong.size(); ++r) {
      if (wrong[r] != 0) {
        misplaced(grid, r, touch_points[r]);  // throws
        throw std::logic_error("validate: the nesting tree and ray parity disagree");
      }
    }
  }

  // The rings that break a nesting rule, from the tree (parent[r]: innermost ring containing r).
  // A depth-first walk keeps, for each polygon, whether its outer ring and how many of its holes
  // enclose the ring visited, and how many polygons enclose it through their outer ring alone.
  [[nodiscard]] std::vector<std::uint8_t> misplaced_rings(const std::vector<std::uint32_t>& parent) const {
    const std::size_t R = rs_.rings.size();
    std::vector<std::uint32_t> child_start(R + 2, 0);  // children of r: [child_start[r], child_start[r+1]); roots last
    for (std::uint32_t r = 0; r < R; ++r) {
      ++child_start[(parent[r] == no_ring ? R : parent[r]) + 1];
    }
    for (std::size_t k = 1; k < child_start.size(); ++k) {
      child_start[k] += child_start[k - 1];
    }
    std::vector<std::uint32_t> children(R);
    std::vector<std::uint32_t> fill(child_start.begin(), child_start.end() - 1);
    for (std::uint32_t r = 0; r < R; ++r) {
      children[fill[parent[r] == no_ring ? R : parent[r]]++] = r;
    }
    const std::size_t parts = rs_.part_first_ring.size() - 1;
    std::vector<std::uint8_t> shell_encloses(parts, 0);
    std::vector<std::uint32_t> holes_enclosing(parts, 0);
    std::size_t shells_alone = 0;                          // polygons enclosing through their outer ring and no hole
    const auto count = [&](std::uint32_t r, bool joins) {  // r joins or leaves the path from the root
      const RingInfo& info = ring(r);
      const bool alone_before = shell_encloses[info.part] != 0 && holes_enclosing[info.part] == 0;
      if (info.ring == 0) {
        shell_encloses[info.part] = joins ? 1 : 0;
      } else if (joins) {
        ++holes_enclosing[info.part];
      } else {
        --holes_enclosing[info.part];
      }
      const bool alone_after = shell_encloses[info.part] != 0 && holes_enclosing[info.part] == 0;
      shells_alone = shells_alone + (alone_after ? 1U : 0U) - (alone_before ? 1U : 0U);
    };
    std::vector<std::uint8_t> wrong(R, 0);
    // Stack of (ring, next child to visit); the roots hang below a virtual node R.
    std::vector<std::pair<std::uint32_t, std::uint32_t>> stack{{static_cast<std::uint32_t>(R), child_start[R]}};
    while (!stack.empty()) {
      auto& [node, next] = stack.back();
      if (next == child_start[node + 1]) {
        if (node != R) {
          count(node, false);
        }
        stack.pop_back();
        continue;
      }
      const std::uint32_t r = children[next++];
      const RingInfo& info = ring(r);
      if (info.ring > 0) {
        wrong[r] = (shell_encloses[info.part] == 0 || holes_enclosing[info.part] > 0) ? 1 : 0;
      } else {
        wrong[r] = shells_alone > 0 ? 1 : 0;
      }
      count(r, true);
      stack.emplace_back(r, child_start[r]);
    }
    return wrong;
  }

  // Reports ring r if it breaks a nesting rule, by the parity of a ray from a point of r on no
  // other ring (touch_points: the points where r touches other rings, sorted).
  void misplaced(const EdgeGrid& grid, std::uint32_t r, const std::vector<Point>& touch_points) const {
    const std::size_t parts = rs_.part_first_ring.size() - 1;
    std::vector<std::uint8_t> parity(rs_.rings.size(), 0);
    std::vector<std::uint32_t> crossed;
    std::vector<std::uint32_t> odd;
    std::vector<std::uint8_t> in_hole_of(parts, 0);
    const RingInfo& info = ring(r);
    const std::optional<std::uint32_t> k = free_vertex(r, touch_points);
    if (k) {
      grid.edges_crossing_ray(rs_.v[*k], crossed);
      for (const std::uint32_t e : crossed) {
        if (rs_.ring_of[e] != r) {
          parity[rs_.ring_of[e]] ^= 1U;
        }
      }
      for (const std::uint32_t e : crossed) {
        const std::uint32_t s = rs_.ring_of[e];
        if (parity[s] != 0) {
          odd.push_back(s);
          parity[s] = 0;
        }
      }
    } else {
      odd = odd_rings_exact(r);
    }
    const std::uint32_t at = k ? *k : info.first;
    // What the parity was taken at: a free vertex, or a point inside the first edge.
    const std::string witness =
        k ? vertex(*k) : "the inside of its " + edge(info.first) + " (each of its vertices touches another ring)";
    const std::optional<Point> witness_point = k ? std::optional<Point>(rs_.v[*k]) : std::nullopt;
    const std::uint32_t own_shell = rs_.part_first_ring[info.part];
    if (info.ring > 0) {
      if (std::find(odd.begin(), odd.end(), own_shell) == odd.end()) {
        throw InvalidDomainError(Kind::hole_outside_shell,
                                 name(r) + ": the hole is not inside its outer ring (" + witness + " lies outside it)",
                                 site(at), site(rs_.rings[own_shell].first), witness_point);
      }
      for (const std::uint32_t s : odd) {
        if (s != own_shell && ring(s).part == info.part) {
          throw InvalidDomainError(Kind::nested_holes,
                                   name(r) + " lies inside " + name(s) + " (" + witness + " is inside it)", site(at),
                                   site(ring(s).first), witness_point);
        }
      }
      return;
    }
    // An outer ring may lie inside another polygon only within one of its holes.
    for (const std::uint32_t s : odd) {
      if (ring(s).ring > 0) {
        in_hole_of[ring(s).part] = 1;
      }
    }
    for (const std::uint32_t s : odd) {
      if (ring(s).ring == 0 && in_hole_of[ring(s).part] == 0) {
        throw InvalidDomainError(Kind::overlapping_parts,
                                 "polygons " + std::to_string(ring(s).part) + " and " + std::to_string(info.part) +
                                     " overlap: " + name(r) + " lies inside polygon " + std::to_string(ring(s).part) +
                                     " (" + witness + " is inside it)",
                                 site(at), site(ring(s).first), witness_point);
      }
    }
  }

  // Within one polygon, rings that touch must not close a loop: a cycle in the graph of rings
  // and touch points cuts the interior in two (OGC: the interior must be connected).
  void check_connectivity() const {
    struct Link {
      std::uint32_t part;
      Point p;
      std::uint32_t ring;
    };
    std::vector<Link> links;
    for (const Touch& t : touches_) {
      if (ring(t.ring_a).part == ring(t.ring_b).part) {
        links.push_back({ring(t.ring_a).part, t.p, t.ring_a});
        links.push_back({ring(t.ring_a).part, t.p, t.ring_b});
      }
    }
    // At a hub, every two rings touch: those of a polygon with two or more rings there link.
    std::vector<Link> at_hub;
    for (std::size_t h = 0; h + 1 < hubs_.size(); ++h) {
      at_hub.clear();
      for (std::size_t i = hubs_[h].first; i < hubs_[h + 1].first; ++i) {
        const std::uint32_t r = rs_.ring_of[hub_vertices_[i]];
        at_hub.push_back({ring(r).part, hubs_[h].p, r});
      }
      std::sort(at_hub.begin(), at_hub.end(), [](const Link& a, const Link& b) { return a.part < b.part; });
      for (std::size_t a = 0; a < at_hub.size();) {
        std::size_t b = a + 1;
        while (b < at_hub.size() && at_hub[b].part == at_hub[a].part) {
          ++b;
        }
        if (b - a >= 2) {
          links.insert(links.end(), at_hub.begin() + static_cast<std::ptrdiff_t>(a),
                       at_hub.begin() + static_cast<std::ptrdiff_t>(b));
        }
        a = b;
      }
    }
    const auto less = [](const Link& a, const Link& b) {
      return std::tie(a.part, a.p.x, a.p.y, a.ring) < std::tie(b.part, b.p.x, b.p.y, b.ring);
    };
    std::sort(links.begin(), links.end(), less);
    links.erase(
        std::unique(links.begin(), links.end(),
                    [](const Link& a, const Link& b) { return a.part == b.part && a.p == b.p && a.ring == b.ring; }),
        links.end());
    // Union-find over rings [0, R) and touch points [R, R + points).
    const std::size_t R = rs_.rings.size();
    std::vector<std::uint32_t> parent(R + links.size());
    for (std::uint32_t i = 0; i < parent.size(); ++i) {
      parent[i] = i;
    }
    const auto find = [&parent](std::uint32_t x) {
      while (parent[x] != x) {
        parent[x] = parent[parent[x]];
        x = parent[x];
      }
      return x;
    };
    std::vector<Point> point_of;                                  // touch point of node R + i
    std::vector<std::pair<std::uint32_t, std::uint32_t>> joined;  // (ring, node) links so far
    auto node = static_cast<std::uint32_t>(R - 1);
    for (std::size_t i = 0; i < links.size(); ++i) {
      if (i == 0 || links[i].part != links[i - 1].part || links[i].p != links[i - 1].p) {
        ++node;
        point_of.push_back(links[i].p);
      }
      const std::uint32_t a = find(links[i].ring);
      const std::uint32_t b = find(node);
      if (a == b) {
        throw_loop(links[i].part, links[i].ring, node, joined, point_of);
      }
      parent[a] = b;
      joined.emplace_back(links[i].ring, node);
    }
  }

  // Reports the loop closed by linking `ring` to touch node `node`: the path between them
  // through the links made so far, found breadth first.
  [[noreturn]] void throw_loop(std::uint32_t part, std::uint32_t ring_id, std::uint32_t node,
                               const std::vector<std::pair<std::uint32_t, std::uint32_t>>& joined,
                               const std::vector<Point>& point_of) const {
    const std::size_t R = rs_.rings.size();
    std::vector<std::vector<std::uint32_t>> adj(R + point_of.size());
    for (const auto& [r, n] : joined) {
      adj[r].push_back(n);
      adj[n].push_back(r);
    }
    std::vector<std::uint32_t> from(adj.size(), UINT32_MAX);
    std::deque<std::uint32_t> queue{ring_id};
    from[ring_id] = ring_id;
    while (!queue.empty() && from[node] == UINT32_MAX) {
      const std::uint32_t x = queue.front();
      queue.pop_front();
      for (const std::uint32_t y : adj[x]) {
        if (from[y] == UINT32_MAX) {
          from[y] = x;
          queue.push_back(y);
        }
      }
    }
    // Walk back from the touch node to the ring: ring, point, ring, point, ...
    const auto ring_label = [this](std::uint32_t r) {
      return ring(r).ring == 0 ? std::string("the outer ring") : "hole " + std::to_string(ring(r).ring);
    };
    std::vector<std::string> rings{ring_label(ring_id)};
    std::vector<std::string> points{format_point(point_of[node - R])};
    for (std::uint32_t x = from[node]; x != ring_id && x != UINT32_MAX; x = from[x]) {
      if (x < R) {
        rings.push_back(ring_label(x));
      } else {
        points.push_back(format_point(point_of[x - R]));
      }
    }
    const auto join = [](const std::vector<std::string>& items) {
      std::string out;
      for (std::size_t i = 0; i < items.size(); ++i) {
        out += (i == 0 ? "" : (i + 1 == items.size() ? " and " : ", ")) + items[i];
      }
      return out;
    };
    const RingInfo& info = ring(ring_id);
    throw InvalidDomainError(Kind::disconnected_interior,
                             "polygon " + std::to_string(part) + ": the interior is disconnected: " + join(rings) +
                                 " touch at " + join(points) + ", closing a loop that cuts the polygon in two",
                             Site{info.part, info.ring, {}}, {}, point_of[node - R]);
  }

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

}  // namespace

void validate(const RingSet& rings, EdgeGrid& grid, const SourceLocator& where) {
  Validator(rings, where).run(grid);
}

}  // namespace frontpack::detail
