// The nesting tree of a set of non-crossing rings by one plane sweep (domain/ring_tree.hpp).
//
// Points are swept in lexicographic order (x, then y): a vertical line tilted by an infinitesimal
// angle, so that no edge is parallel to it and every event is a vertex (exact/sweep_line.hpp). Each ring
// is cut at its lexicographic turning points into chains, monotone in that order; the status holds
// the chains that the line crosses, ordered from bottom to top. Since no two edges cross or
// overlap, that order never changes while both chains are in it, and an exact orientation test
// against the edge of a chain under the line decides it. The events are the chains' ends only: a
// ring of 100,000 vertices that winds a few times is a few chains.
//
// At the lexicographically smallest vertex m of a ring r, two chains of r start, and r lies
// between them. Take a point q on the lower of the two, just after m, on no other ring: q is
// inside exactly the rings that contain r. The chain f directly below q in the status belongs to
// a ring s, and nothing lies between q and f. If the interior of s is on the upper side of f, q
// is inside s and s is the innermost ring that contains it: r's parent is s. Otherwise q lies
// just outside s, in the same rings as s itself: r's parent is s's parent. With no chain below,
// r is outermost. Rings touching at m, or an edge through m, change nothing: only chains active
// after m are in the status, and the chain below q is the same for every q close enough to m.

#include "domain/ring_tree.hpp"

#include <algorithm>
#include <iterator>
#include <set>
#include <stdexcept>
#include <tuple>

#include "exact/predicates.hpp"
#include "exact/sweep_line.hpp"

namespace frontpack::detail {

namespace {

// A chain of ring `ring`: its points in sweep order are points[first], ..., points[first + edges];
// forward if it runs along the ring's direction.
struct Chain {
  std::uint32_t ring;
  std::uint32_t first;
  std::uint32_t edges;
  bool forward;
};

class Chains {
 public:
  explicit Chains(const RingSet& rs) : rs_(rs) {}

  // Appends the chain of ring r whose vertices are, along the ring's direction, those at
  // ring-relative positions [from, from + edges] (modulo the ring's size), in sweep order.
  void add(std::uint32_t r, std::uint32_t from, std::uint32_t edges, bool forward) {
    const RingInfo& info = rs_.rings[r];
    chains_.push_back({r, static_cast<std::uint32_t>(points_.size()), edges, forward});
    for (std::uint32_t i = 0; i <= edges; ++i) {
      const std::uint32_t at = forward ? from + i : from + edges - i;
      vertices_.push_back(info.first + at % info.count);
      points_.push_back(rs_.v[vertices_.back()]);
    }
  }

  [[nodiscard]] const std::vector<Chain>& all() const noexcept { return chains_; }
  [[nodiscard]] std::uint32_t vertex(const Chain& c, std::uint32_t i) const noexcept { return vertices_[c.first + i]; }
  [[nodiscard]] Point point(const Chain& c, std::uint32_t i) const noexcept { return points_[c.first + i]; }
  [[nodiscard]] Point lo(const Chain& c) const noexcept { return point(c, 0); }
  [[nodiscard]] Point hi(const Chain& c) const noexcept { return point(c, c.edges); }

  // The edge of chain c under the sweep line at p (lo(c) <= p < hi(c)): its points i, i + 1 with
  // point(i) <= p < point(i + 1), by bisection.
  [[nodiscard]] std::pair<Point, Point> edge_at(const Chain& c, Point p) const noexcept {
    std::uint32_t a = 0;        // point(a) <= p
    std::uint32_t b = c.edges;  // p < point(b)
    while (b - a > 1) {
      const std::uint32_t mid = a + (b - a) / 2;
      if (lex_less(p, point(c, mid))) {
        b = mid;
      } else {
        a = mid;
      }
    }
    return {point(c, a), point(c, a + 1)};
  }

  // Whether chain a lies below chain b just after the later of their starts. Exact.
  [[nodiscard]] bool below(const Chain& a, const Chain& b) const {
    const Point la = lo(a);
    const Point lb = lo(b);
    if (la == lb) {
      return orientation(la, point(a, 1), point(b, 1)) > 0;
    }
    if (lex_less(la, lb)) {
      const auto [u, w] = edge_at(a, lb);
      int o = orientation(u, w, lb);
      if (o == 0) {
        o = orientation(u, w, point(b, 1));  // b starts on a: its first edge decides
      }
      return o > 0;
    }
    const auto [u, w] = edge_at(b, la);
    int o = orientation(u, w, la);
    if (o == 0) {
      o = orientation(u, w, point(a, 1));
    }
    return o < 0;
  }

 private:
  const RingSet& rs_;
  std::vector<Chain> chains_;
  std::vector<std::uint32_t> vertices_;  // of the chains' points, chain after chain
  std::vector<Point> points_;
};

// Each ring's smallest vertex (where two of its chains start), the two chains that start there,
// and its orientation.
struct RingStarts {
  std::vector<std::uint32_t> lowest;
  std::vector<std::uint32_t> forward;   // r's chain from lowest[r] along the ring's direction
  std::vector<std::uint32_t> backward;  // and against it
  std::vector<std::uint8_t> anticlockwise;

  explicit RingStarts(std::size_t rings) : lowest(rings), forward(rings), backward(rings), anticlockwise(rings) {}
};

// Cuts ring r into its chains, and records its start and orientation (exact at its smallest
// vertex: its neighbours lie on the same side, and a fold there is a spike, which validation
// rejected before).
void cut_ring(const RingSet& rs, std::uint32_t r, Chains& geometry, RingStarts& starts) {
  const RingInfo& info = rs.rings[r];
  const auto up = [&rs](std::uint32_t e) { return lex_less(rs.v[e], rs.v[rs.next[e]]); };
  std::uint32_t m = info.first;
  std::uint32_t turn = info.first;  // a vertex where the edges turn from down to up
  for (std::uint32_t k = info.first; k < info.first + info.count; ++k) {
    if (lex_less(rs.v[k], rs.v[m])) {
      m = k;
    }
    if (up(k) && !up(rs.prev[k])) {
      turn = k;
    }
  }
  starts.lowest[r] = m;
  starts.anticlockwise[r] = orientation(rs.v[rs.prev[m]], rs.v[m], rs.v[rs.next[m]]) > 0 ? 1 : 0;
  // Runs of edges going the same way, from `turn` once round the ring.
  const std::uint32_t start = turn - info.first;
  std::uint32_t run = start;
  bool run_up = true;
  for (std::uint32_t i = 1; i <= info.count; ++i) {
    const std::uint32_t k = info.first + (start + i) % info.count;
    if (i < info.count && up(k) == run_up) {
      continue;
    }
    const std::uint32_t end = start + i;  // the run is edges [run, end)
    geometry.add(r, run, end - run, run_up);
    const auto c = static_cast<std::uint32_t>(geometry.all().size() - 1);
    if (geometry.vertex(geometry.all()[c], 0) == m) {
      (run_up ? starts.forward : starts.backward)[r] = c;
    }
    run = end;
    run_up = !run_up;
  }
}

struct Event {
  Point p;
  bool enters;
  std::uint32_t chain;
};

// Events: a chain leaves at its last point, enters at its first; at one point, leaving first.
std::vector<Event> sweep_events(const Chains& geometry) {
  const std::vector<Chain>& chains = geometry.all();
  std::vector<Event> events;
  events.reserve(2 * chains.size());
  for (std::uint32_t c = 0; c < chains.size(); ++c) {
    events.push_back({geometry.lo(chains[c]), true, c});
    events.push_back({geometry.hi(chains[c]), false, c});
  }
  std::sort(events.begin(), events.end(), [](const Event& a, const Event& b) {
    if (lex_less(a.p, b.p) || lex_less(b.p, a.p)) {
      return lex_less(a.p, b.p);
    }
    return std::tie(a.enters, a.chain) < std::tie(b.enters, b.chain);
  });
  return events;
}

// link[r]: the ring whose chain lies below r's start (no_ring: none); inside[r]: whether r starts
// inside it.
struct Links {
  std::vector<std::uint32_t> link;
  std::vector<std::uint8_t> inside;
};

// The sweep: at each event point the chains leave and enter the status, then each ring starting
// there finds the chain below its lower starting chain.
Links sweep(const RingSet& rs, const Chains& geometry, const RingStarts& starts) {
  const std::vector<Chain>& chains = geometry.all();
  const std::vector<Event> events = sweep_events(geometry);
  const auto less = [&](std::uint32_t a, std::uint32_t b) { return a != b && geometry.below(chains[a], chains[b]); };
  std::set<std::uint32_t, decltype(less)> status(less);
  std::vector<decltype(status)::iterator> where(chains.size(), status.end());
  Links links{std::vector<std::uint32_t>(rs.rings.size(), no_ring), std::vector<std::uint8_t>(rs.rings.size(), 0)};
  std::vector<std::uint32_t> starting;  // rings whose smallest vertex is the current point
  for (std::size_t i = 0; i < events.size();) {
    std::size_t j = i;
    starting.clear();
    for (; j < events.size() && events[j].p == events[i].p; ++j) {
      const std::uint32_t c = events[j].chain;
      if (!events[j].enters) {
        status.erase(where[c]);
        continue;
      }
      const auto [it, fresh] = status.insert(c);
      if (!fresh) {
        throw std::logic_error("ring_parents: two edges overlap (validation should have rejected them)");
      }
      where[c] = it;
      if (starts.forward[chains[c].ring] == c) {
        starting.push_back(chains[c].ring);
      }
    }
    for (const std::uint32_t r : starting) {
      // Both of r's chains at m are in; the lower is the one along the ring's direction if the
      // previous vertex lies above the edge to the next.
      const std::uint32_t m = starts.lowest[r];
      const bool forward_lower = orientation(rs.v[m], rs.v[rs.next[m]], rs.v[rs.prev[m]]) > 0;
      const auto it = where[forward_lower ? starts.forward[r] : starts.backward[r]];
      if (it == status.begin()) {
        continue;  // nothing below: outermost
      }
      const Chain& f = chains[*std::prev(it)];
      // The interior of ring s lies left of its edges if s is anticlockwise; left of an edge taken
      // in sweep order is its upper side, and f's edges run in sweep order along the ring's
      // direction if f is forward.
      links.link[r] = f.ring;
      links.inside[r] = (f.forward == (starts.anticlockwise[f.ring] != 0)) ? 1 : 0;
    }
    i = j;
  }
  return links;
}

// parent[r] = s when r starts inside s, else parent[s]. The links go to rings whose chain lies
// below r's start, met earlier in the sweep (or at the same point, lower), so they end.
void resolve_parents(const Links& links, std::vector<std::uint32_t>& parent) {
  const std::vector<std::uint32_t>& link = links.link;
  const std::vector<std::uint8_t>& inside = links.inside;
  const std::size_t rings = parent.size();
  std::vector<std::uint8_t> state(rings, 0);  // 0 new, 1 on the chain being resolved, 2 done
  std::vector<std::uint32_t> pending;
  for (std::uint32_t r = 0; r < rings; ++r) {
    std::uint32_t x = r;
    while (state[x] == 0 && link[x] != no_ring && inside[x] == 0) {
      state[x] = 1;
      pending.push_back(x);
      x = link[x];
    }
    if (state[x] == 1) {
      throw std::logic_error("ring_parents: a cycle of enclosing rings (the rings cross)");
    }
    if (state[x] == 0) {
      parent[x] = link[x];  // inside link[x], or no_ring
      state[x] = 2;
    }
    for (const std::uint32_t y : pending) {
      parent[y] = parent[x];
      state[y] = 2;
    }
    pending.clear();
  }
}

}  // namespace

std::vector<std::uint32_t> ring_parents(const RingSet& rs) {
  const std::size_t rings = rs.rings.size();
  std::vector<std::uint32_t> parent(rings, no_ring);
  if (rings < 2) {
    return parent;
  }
  Chains geometry(rs);
  RingStarts starts(rings);
  for (std::uint32_t r = 0; r < rings; ++r) {
    cut_ring(rs, r, geometry, starts);
  }
  resolve_parents(sweep(rs, geometry, starts), parent);
  return parent;
}

}  // namespace frontpack::detail
