// domain/edge_sweep.hpp: the Shamos-Hoey sweep, with common endpoints allowed.
//
// Segments enter the status at their first endpoint and leave it at their last (exact/sweep_line.hpp);
// at a point, those that end there leave before those that start there enter. Each segment is
// tested against its neighbours when it enters, and the two segments that become neighbours when
// one leaves are tested against each other. If two segments meet where they must not, the
// leftmost such point Q has them, or segments that meet the same way at Q, as neighbours at
// some event up to Q (anything between them just before Q passes through Q or ends there), and
// up to Q the status order is that of segments that do not cross, so the first such pair is
// found before the order could go wrong. A point where many segments end (thousands of rings
// meeting at one point) costs a few comparisons per segment: CGAL's surface sweep, used here
// before, inserted each of them into the point's list of curves by a linear search (11 s for a
// fan of 8,192 triangles meeting at one point).

#include "domain/edge_sweep.hpp"

#include <algorithm>
#include <iterator>
#include <set>
#include <tuple>

#include "exact/predicates.hpp"
#include "exact/sweep_line.hpp"

namespace frontpack::detail {

namespace {

// Whether the segments have a common point inside either: a proper crossing, an overlap, or an
// endpoint of one inside the other. Exact.
bool meet_inside(const SweepEdge& a, const SweepEdge& b) {
  const int o1 = orientation(a.lo, a.hi, b.lo);
  const int o2 = orientation(a.lo, a.hi, b.hi);
  if (o1 == 0 && o2 == 0) {
    // Collinear: along the line, lexicographic order is the order of the points.
    const Point from = lex_less(a.lo, b.lo) ? b.lo : a.lo;
    const Point to = lex_less(a.hi, b.hi) ? a.hi : b.hi;
    return lex_less(from, to);  // a common piece of positive length
  }
  const int o3 = orientation(b.lo, b.hi, a.lo);
  const int o4 = orientation(b.lo, b.hi, a.hi);
  if (o1 * o2 < 0 && o3 * o4 < 0) {
    return true;
  }
  const auto inside = [](Point p, const SweepEdge& s) { return p != s.lo && p != s.hi && on_segment(p, s.lo, s.hi); };
  return (o1 == 0 && inside(b.lo, a)) || (o2 == 0 && inside(b.hi, a)) || (o3 == 0 && inside(a.lo, b)) ||
         (o4 == 0 && inside(a.hi, b));
}

}  // namespace

bool edge_interiors_disjoint(const std::vector<Point>& v, const std::vector<std::uint32_t>& next) {
  const std::size_t n = v.size();
  std::vector<SweepEdge> edges;
  edges.reserve(n);
  for (std::uint32_t e = 0; e < n; ++e) {
    edges.push_back(sweep_edge(v[e], v[next[e]], e));
  }
  // Events: (point, leaves before enters, edge).
  struct Event {
    Point p;
    bool enters;
    std::uint32_t edge;
  };
  std::vector<Event> events;
  events.reserve(2 * n);
  for (const SweepEdge& e : edges) {
    events.push_back({e.lo, true, e.id});
    events.push_back({e.hi, false, e.id});
  }
  std::sort(events.begin(), events.end(), [](const Event& a, const Event& b) {
    if (lex_less(a.p, b.p) || lex_less(b.p, a.p)) {
      return lex_less(a.p, b.p);
    }
    return std::tie(a.enters, a.edge) < std::tie(b.enters, b.edge);
  });

  std::set<SweepEdge, Below> status;
  std::vector<std::set<SweepEdge, Below>::iterator> where(n, status.end());
  for (const Event& ev : events) {
    const SweepEdge& e = edges[ev.edge];
    if (ev.enters) {
      const auto [it, fresh] = status.insert(e);
      if (!fresh) {
        return false;  // collinear with a segment already there, overlapping it
      }
      where[ev.edge] = it;
      if (it != status.begin() && meet_inside(*std::prev(it), e)) {
        return false;
      }
      if (const auto above = std::next(it); above != status.end() && meet_inside(e, *above)) {
        return false;
      }
      continue;
    }
    const auto it = where[ev.edge];
    const auto above = status.erase(it);
    if (above != status.begin() && above != status.end() && meet_inside(*std::prev(above), *above)) {
      return false;
    }
  }
  return true;
}

}  // namespace frontpack::detail
