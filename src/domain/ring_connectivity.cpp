// The interior of each polygon must be connected: rings that touch must not close a loop.
#include "domain/validator.hpp"

namespace frontpack::detail::validation {

// Within one polygon, rings that touch must not close a loop: a cycle in the graph of rings
// and touch points cuts the interior in two (OGC: the interior must be connected).
void Validator::check_connectivity() const {
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
[[noreturn]] void Validator::throw_loop(std::uint32_t part, std::uint32_t ring_id, std::uint32_t node,
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

}  // namespace frontpack::detail::validation
