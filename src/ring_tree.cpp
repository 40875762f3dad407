// The nesting tree of a set of non-crossing rings by one plane sweep (ring_tree.hpp).
//
// Points are swept in lexicographic order (x, then y): a vertical line tilted by an infinitesimal
// angle, so that no edge is parallel to it and every event is a vertex. The status holds the
// edges that the line crosses, ordered from bottom to top; since no two edges cross or overlap,
// that order never changes while both are in it, and an exact orientation test decides it.
//
// At the lexicographically smallest vertex m of a ring r, both edges of r start, and r lies
// between them. Take a point q on the lower of the two, just after m, on no other ring: q is
// inside exactly the rings that contain r. The edge f directly below q in the status belongs to
// a ring s, and nothing lies between q and f. If the interior of s is on the upper side of f, q
// is inside s and s is the innermost ring that contains it: r's parent is s. Otherwise q lies
// just outside s, in the same rings as s itself: r's parent is s's parent. With no edge below,
// r is outermost. Rings touching at m, or an edge through m, change nothing: only edges active
// after m are in the status, and the edge below q is the same for every q close enough to m.

#include "ring_tree.hpp"

#include <algorithm>
#include <iterator>
#include <set>
#include <stdexcept>

#include "exact.hpp"

namespace frontpack::detail {

namespace {

bool lex_less(Point a, Point b) noexcept {
  return a.x < b.x || (a.x == b.x && a.y < b.y);
}

// An edge with its endpoints in sweep order.
struct SweepEdge {
  Point lo;  // lexicographically smaller endpoint
  Point hi;
  std::uint32_t id;
};

// Whether a lies below b on the sweep line, for two edges that are both crossed by it (just after
// the current event). Exact; a strict order for edges that neither cross nor overlap.
struct Below {
  bool operator()(const SweepEdge& a, const SweepEdge& b) const {
    if (a.id == b.id) {
      return false;
    }
    if (a.lo == b.lo) {
      return orientation(a.lo, a.hi, b.hi) > 0;
    }
    if (lex_less(a.lo, b.lo)) {
      // b starts on the sweep line, over a's span; if it starts on a, its other end decides.
      int o = orientation(a.lo, a.hi, b.lo);
      if (o == 0) {
        o = orientation(a.lo, a.hi, b.hi);
      }
      return o > 0;
    }
    int o = orientation(b.lo, b.hi, a.lo);
    if (o == 0) {
      o = orientation(b.lo, b.hi, a.hi);
    }
    return o < 0;
  }
};

}  // namespace

std::vector<std::uint32_t> ring_parents(const RingSet& rs) {
  const std::size_t n = rs.v.size();
  const std::size_t rings = rs.rings.size();
  const auto edge = [&rs](std::uint32_t e) {
    const Point a = rs.v[e];
    const Point b = rs.v[rs.next[e]];
    return lex_less(a, b) ? SweepEdge{a, b, e} : SweepEdge{b, a, e};
  };

  // Each ring's smallest vertex and orientation (exact at that vertex: its neighbours lie on the
  // same side, and a fold there is a spike, which validation rejected before).
  std::vector<std::uint32_t> lowest(rings);
  std::vector<std::uint8_t> anticlockwise(rings);
  for (std::uint32_t r = 0; r < rings; ++r) {
    const RingInfo& info = rs.rings[r];
    std::uint32_t m = info.first;
    for (std::uint32_t k = info.first + 1; k < info.first + info.count; ++k) {
      if (lex_less(rs.v[k], rs.v[m])) {
        m = k;
      }
    }
    lowest[r] = m;
    anticlockwise[r] = orientation(rs.v[rs.prev[m]], rs.v[m], rs.v[rs.next[m]]) > 0 ? 1 : 0;
  }

  std::vector<std::uint32_t> order(n);
  for (std::uint32_t k = 0; k < n; ++k) {
    order[k] = k;
  }
  std::sort(order.begin(), order.end(), [&rs](std::uint32_t a, std::uint32_t b) { return lex_less(rs.v[a], rs.v[b]); });

  // link[r]: the ring whose edge lies below r's start; inside[r]: whether r starts inside it.
  std::vector<std::uint32_t> link(rings, no_ring);
  std::vector<std::uint8_t> inside(rings, 0);
  std::set<SweepEdge, Below> status;
  std::vector<std::set<SweepEdge, Below>::iterator> where(n, status.end());
  for (std::size_t i = 0; i < n;) {
    const Point p = rs.v[order[i]];
    std::size_t j = i;
    while (j < n && rs.v[order[j]] == p) {
      ++j;
    }
    // Edges ending at p leave before those starting at p enter: the two never meet in the status.
    for (std::size_t k = i; k < j; ++k) {
      const std::uint32_t vtx = order[k];
      for (const std::uint32_t e : {rs.prev[vtx], vtx}) {
        if (where[e] != status.end() && edge(e).hi == p) {
          status.erase(where[e]);
          where[e] = status.end();
        }
      }
    }
    for (std::size_t k = i; k < j; ++k) {
      const std::uint32_t vtx = order[k];
      for (const std::uint32_t e : {rs.prev[vtx], vtx}) {
        const SweepEdge se = edge(e);
        if (se.lo == p) {
          const auto [it, fresh] = status.insert(se);
          if (!fresh) {
            throw std::logic_error("ring_parents: two edges overlap (validation should have rejected them)");
          }
          where[e] = it;
        }
      }
    }
    for (std::size_t k = i; k < j; ++k) {
      const std::uint32_t m = order[k];
      const std::uint32_t r = rs.ring_of[m];
      if (lowest[r] != m) {
        continue;
      }
      // The lower of r's two edges at m: the edge to next[m] unless prev[m] lies below it.
      const std::uint32_t low = orientation(rs.v[m], rs.v[rs.next[m]], rs.v[rs.prev[m]]) > 0 ? m : rs.prev[m];
      const auto it = where[low];
      if (it == status.begin()) {
        continue;  // nothing below: outermost
      }
      const std::uint32_t f = std::prev(it)->id;
      const std::uint32_t s = rs.ring_of[f];
      // The interior of s lies left of its edges if s is anticlockwise; left of f taken from its
      // smaller end to its larger is the upper side.
      const bool upward = lex_less(rs.v[f], rs.v[rs.next[f]]);
      link[r] = s;
      inside[r] = (upward == (anticlockwise[s] != 0)) ? 1 : 0;
    }
    i = j;
  }

  // parent[r] = s when r starts inside s, else parent[s]. The links go to rings whose edge lies
  // below r's start, met earlier in the sweep (or at the same point, lower), so they end.
  std::vector<std::uint32_t> parent(rings, no_ring);
  std::vector<std::uint8_t> state(rings, 0);  // 0 new, 1 on the chain being resolved, 2 done
  std::vector<std::uint32_t> chain;
  for (std::uint32_t r = 0; r < rings; ++r) {
    std::uint32_t x = r;
    while (state[x] == 0 && link[x] != no_ring && inside[x] == 0) {
      state[x] = 1;
      chain.push_back(x);
      x = link[x];
    }
    if (state[x] == 1) {
      throw std::logic_error("ring_parents: a cycle of enclosing rings (the rings cross)");
    }
    std::uint32_t answer = no_ring;
    if (state[x] == 2) {
      answer = parent[x];
    } else {
      answer = link[x];  // inside link[x], or no_ring
      parent[x] = answer;
      state[x] = 2;
    }
    for (const std::uint32_t y : chain) {
      parent[y] = answer;
      state[y] = 2;
    }
    chain.clear();
  }
  return parent;
}

}  // namespace frontpack::detail
