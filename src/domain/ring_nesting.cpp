// Rings that touch must not cross there; holes inside their own outer ring and in no other hole,
// outer rings inside another polygon only within its holes (exact ray parity or the ring tree).
#include "domain/validator.hpp"

namespace frontpack::detail::validation {

// The two neighbours of point p along ring edge e (p is on e): the path prev -> p -> next.
std::pair<Point, Point> Validator::neighbours(std::uint32_t e, Point p) const {
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
std::uint32_t Validator::vertex_at(const Touch& t) const {
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
bool Validator::in_wedge(Point s, Point u, Point w, Point q) {
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
void Validator::check_touch_crossings() {
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
std::optional<std::uint32_t> Validator::free_vertex(std::uint32_t r, const std::vector<Point>& touch_points) const {
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
std::vector<std::uint32_t> Validator::odd_rings_exact(std::uint32_t self) const {
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
void Validator::check_nesting(const EdgeGrid& grid) const {
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
std::vector<std::uint8_t> Validator::misplaced_rings(const std::vector<std::uint32_t>& parent) const {
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
void Validator::misplaced(const EdgeGrid& grid, std::uint32_t r, const std::vector<Point>& touch_points) const {
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

}  // namespace frontpack::detail::validation
