// Pairwise classification of the edges whose boxes meet (CGAL::box_self_intersection_d, exact
// predicates), the ordered search for the first problem, and the hubs where many vertices meet.
#include "domain/validator.hpp"

namespace frontpack::detail::validation {

namespace {

// The ends of edges e and f: A -> B and C -> D.
struct EdgeEnds {
  Point A, B, C, D;
};

EdgeEnds ends_of(const RingSet& rs, std::uint32_t e, std::uint32_t f) noexcept {
  return {rs.v[e], rs.v[rs.next[e]], rs.v[f], rs.v[rs.next[f]]};
}

}  // namespace

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
void Validator::check_edge_pairs() {
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

// With a problem in hand (problem_), the one with the smallest key: the pairs whose smaller edge
// lies in [lo, hi) are classified block after block, each block's edges against the edges from
// lo on. Once hi passes the smaller edge of the problem in hand, every pair that could have a
// smaller key has been seen. Each block costs a box intersection over the edges left plus its
// pairs, so a problem among the first edges is found after few pairs. The blocks double while
// their pairs stay within a budget; a block that exceeds it (a dense cluster among its edges)
// is given up and taken again at a sixteenth of the size (a half needed many more tries: 20,000
// clean edges before a 30,000-edge cluster, 14.6 s in blocks without a budget, 3.8 s halving,
// 1.5 s). A single edge has fewer pairs than the budget, so the search always moves on.
void Validator::ordered_search() {
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

// The spokes of the hub's vertices [first, last) of hub_vertices_, in anticlockwise order about
// p from the direction +x (exact); spokes in the same direction are adjacent.
std::vector<Validator::Spoke> Validator::spokes(Point p, std::size_t first, std::size_t last) const {
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

// Hubs: points where two or more vertices lie (of one ring: it touches itself; of several:
// they touch). Of the edges ending at a hub, two that are not consecutive in one ring meet
// there, and nowhere else unless they overlap; such a pair is a problem if the two edges
// belong to one ring or leave the hub in the same direction, a touch otherwise. The pairs
// with a problem that could have the smallest key are classified here: in each ring, its
// smallest edge at the hub with the smallest edge of its other vertices there, and in each
// direction, its two smallest edges. The touches are kept as the hub's list of vertices
// (check_touch_crossings, check_nesting and check_connectivity read it), not pair by pair.
void Validator::find_hubs() {
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
void Validator::classify_unless_hub(std::uint32_t e, std::uint32_t f) {
  const auto [A, B, C, D] = ends_of(rs_, e, f);
  if ((A == C || A == D || B == C || B == D) && rs_.next[e] != f && rs_.next[f] != e) {
    return;
  }
  classify(e, f);
}

// Edges e < f, classified by the exact orientations of each one's ends against the other.
void Validator::classify(std::uint32_t e, std::uint32_t f) {
  if (f < e) {
    std::swap(e, f);  // name the edges in input order
  }
  const auto [A, B, C, D] = ends_of(rs_, e, f);
  if (rs_.ring_of[e] == rs_.ring_of[f] && (rs_.next[e] == f || rs_.next[f] == e)) {
    classify_consecutive(e, f);
    return;
  }
  const int o1 = orientation(A, B, C);
  const int o2 = orientation(A, B, D);
  if (o1 == 0 && o2 == 0) {
    classify_collinear(e, f);
    return;
  }
  const int o3 = orientation(C, D, A);
  const int o4 = orientation(C, D, B);
  if (o1 * o2 < 0 && o3 * o4 < 0) {
    report_crossing(e, f);
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

void Validator::classify_consecutive(std::uint32_t e, std::uint32_t f) {
  const auto [A, B, C, D] = ends_of(rs_, e, f);
  // Consecutive edges p -> s -> q meet at s; they overlap only if q folds back onto p's side.
  const bool e_first = rs_.next[e] == f;
  const Point p = e_first ? A : C;
  const Point s = e_first ? B : A;
  const Point q = e_first ? D : B;
  const std::uint32_t at = e_first ? f : e;
  if (orientation(p, s, q) == 0 && dot_sign(s, p, q) > 0 && improves(e, f, 0)) {
    report(e, f, Kind::self_intersection,
           name(rs_.ring_of[e]) + ": " + edge(e) + " and " + edge(f) + " fold back on each other at " + vertex(at) +
               " (a zero-width spike)",
           s, 0);
  }
}

void Validator::classify_collinear(std::uint32_t e, std::uint32_t f) {
  const auto [A, B, C, D] = ends_of(rs_, e, f);
  const std::uint32_t re = rs_.ring_of[e];
  const std::uint32_t rf = rs_.ring_of[f];
  // Compare the two intervals on the line along a non-degenerate axis.
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
    if (re == rf) {
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
}

void Validator::report_crossing(std::uint32_t e, std::uint32_t f) {
  if (!improves(e, f)) {
    return;
  }
  const auto [A, B, C, D] = ends_of(rs_, e, f);
  const std::uint32_t re = rs_.ring_of[e];
  const std::uint32_t rf = rs_.ring_of[f];
  const auto x =
      CGAL::intersection(Kernel::Segment_2(to_cgal(A), to_cgal(B)), Kernel::Segment_2(to_cgal(C), to_cgal(D)));
  std::optional<Point> at;
  if (x) {
    if (const auto* pt = boost::get<KPoint>(&*x)) {
      at = Point{pt->x(), pt->y()};
    }
  }
  const std::string near = at ? " near " + format_point_approx(*at) : "";
  if (re == rf) {
    report(e, f, Kind::self_intersection, name(re) + ": " + edge(e) + " and " + edge(f) + " cross" + near, at);
  } else {
    report(e, f, Kind::rings_cross,
           name(re) + " and " + name(rf) + " cross: " + edge(e) + " of the first crosses " + edge(f) +
               " of the second" + near,
           at);
  }
}

void Validator::touch(std::uint32_t e, std::uint32_t f, Point t) {
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

}  // namespace frontpack::detail::validation
