// Frozen wall disks along every ring of a domain, outside it, certified exactly against the
// domain's complement, with no gap a free disk could pass.
//
// Placement. Rings are normalised (outer rings anticlockwise, holes clockwise), so the domain is on
// the left of every edge and the outside on its right. Along each edge, centres on the line offset
// by w (1 + 1e-6) to the right, at most w apart; at a convex vertex, an arc of centres about the
// vertex; at a reflex vertex, the point where the two offset lines meet (a disk there touches both
// edges' lines). Candidates are certified exactly (the closed wall disk in the closed complement,
// Domain::contains on a domain built from the complement); those that fail (near a reflex vertex,
// or where another part of the boundary is close) are dropped, and the chain that remains must
// leave no gap of 2 rmin or more between consecutive disks.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "common/format.hpp"
#include "frontpack/deck.hpp"

namespace frontpack {

namespace {

struct Vec {
  double x = 0;
  double y = 0;
};

Point along(Point p, Vec d, double t) {
  return {p.x + d.x * t, p.y + d.y * t};
}

// The complement of the domain inside a box with room for the walls: the box with every polygon's
// outer ring as a hole, and every hole of the domain as a polygon of its own, holding as holes the
// domain's polygons that lie in it (islands).
Domain complement(const Domain& domain, double margin) {
  const Box b = domain.bbox();
  const Ring box{{b.xmin - margin, b.ymin - margin},
                 {b.xmax + margin, b.ymin - margin},
                 {b.xmax + margin, b.ymax + margin},
                 {b.xmin - margin, b.ymax + margin}};
  std::vector<Polygon> parts;
  Polygon outside{box, {}};
  std::vector<const Ring*> islands;
  for (const Polygon& p : domain.polygons()) {
    islands.push_back(&p.outer);
  }
  std::vector<bool> taken(islands.size(), false);
  for (const Polygon& p : domain.polygons()) {
    for (const Ring& h : p.holes) {
      Polygon part{h, {}};
      const Domain hole = Domain::from_rings(h);
      for (std::size_t k = 0; k < islands.size(); ++k) {
        if (!taken[k] && hole.locate(islands[k]->front()) == Location::inside) {
          part.holes.push_back(*islands[k]);
          taken[k] = true;
        }
      }
      parts.push_back(std::move(part));
    }
  }
  for (std::size_t k = 0; k < islands.size(); ++k) {
    if (!taken[k]) {
      outside.holes.push_back(*islands[k]);
    }
  }
  parts.insert(parts.begin(), std::move(outside));
  return Domain::from_polygons(std::move(parts));
}

// A candidate wall disk; `chain` disks form the closed chain along the ring (in ring order), the
// others fill the tips of narrow outside corners.
struct Candidate {
  Disk disk;
  bool chain = true;
};

// How far tip disks shrink: the last one has radius w / 64, so a free disk pressed into the
// corner of a reflex vertex stops within about 0.03 w of the boundary.
constexpr int kTipHalvings = 6;

// The candidate wall disks of one ring, in ring order.
std::vector<Candidate> ring_candidates(const Ring& ring, double radius, double spacing) {
  const double offset = radius * (1 + 1e-6);
  std::vector<Candidate> out;
  const std::size_t n = ring.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Point a = ring[i];
    const Point b = ring[(i + 1) % n];
    const Point c = ring[(i + 2) % n];
    const double len = std::hypot(b.x - a.x, b.y - a.y);
    const Vec u{(b.x - a.x) / len, (b.y - a.y) / len};
    const Vec nr{u.y, -u.x};  // right of the edge: outside
    const auto k = static_cast<std::size_t>(std::ceil(len / spacing));
    for (std::size_t j = 0; j <= k; ++j) {
      out.push_back({{along(along(a, u, len * static_cast<double>(j) / static_cast<double>(k)), nr, offset), radius}});
    }
    const double len2 = std::hypot(c.x - b.x, c.y - b.y);
    const Vec u2{(c.x - b.x) / len2, (c.y - b.y) / len2};
    const Vec n2{u2.y, -u2.x};
    const double turn = u.x * u2.y - u.y * u2.x;  // > 0: a left turn, a convex vertex of the domain
    const double cosine = nr.x * n2.x + nr.y * n2.y;
    if (turn > 0) {
      const double angle = std::atan2(nr.x * n2.y - nr.y * n2.x, cosine);
      const auto m = static_cast<std::size_t>(std::ceil(std::abs(angle) * offset / spacing));
      for (std::size_t j = 1; j < m; ++j) {
        const double t = angle * static_cast<double>(j) / static_cast<double>(m);
        const Vec d{nr.x * std::cos(t) - nr.y * std::sin(t), nr.x * std::sin(t) + nr.y * std::cos(t)};
        out.push_back({{along(b, d, offset), radius}});
      }
    } else if (turn < 0 && cosine > -0.999) {
      // Where the offset lines meet: b + offset (n1 + n2) / (1 + n1.n2); then smaller disks, each
      // touching both edges' lines, into the corner's tip.
      const Vec s{(nr.x + n2.x) / (1 + cosine), (nr.y + n2.y) / (1 + cosine)};
      out.push_back({{along(b, s, offset), radius}});
      double r = radius;
      for (int h = 0; h < kTipHalvings; ++h) {
        r /= 2;
        out.push_back({{along(b, s, r * (1 + 1e-6)), r}, false});
      }
    }
  }
  return out;
}

}  // namespace

std::vector<Disk> wall_disks(const Domain& domain, double wall_radius, double rmin) {
  if (!(std::isfinite(wall_radius) && wall_radius > 0)) {
    throw OptionError("wall radius " + detail::format_double(wall_radius) + " must be a finite number > 0");
  }
  if (!(std::isfinite(rmin) && rmin > 0)) {
    throw OptionError("smallest free radius " + detail::format_double(rmin) + " must be a finite number > 0");
  }
  const double offset = wall_radius * (1 + 1e-6);
  // Half a radius apart: the chain's bumps let a free disk of radius r >= w sink at most
  // (r + w) - sqrt((r + w)^2 - (w / 4)^2) <= 0.016 w past the boundary line, touching two wall disks.
  const double spacing = wall_radius / 2;
  const double reach = 2 * (wall_radius + rmin);
  const Domain outside = complement(domain, 4 * offset + reach);

  std::vector<Disk> walls;
  std::size_t polygon = 0;
  for (const Polygon& p : domain.polygons()) {
    for (std::size_t r = 0; r <= p.holes.size(); ++r) {
      const Ring& ring = r == 0 ? p.outer : p.holes[r - 1];
      const std::vector<Candidate> found = ring_candidates(ring, wall_radius, spacing);
      std::vector<Disk> candidates;
      candidates.reserve(found.size());
      for (const Candidate& c : found) {
        candidates.push_back(c.disk);
      }
      std::vector<std::uint8_t> ok(candidates.size());
      outside.contains(candidates, ok);
      std::vector<Disk> kept;  // the chain
      for (std::size_t i = 0; i < candidates.size(); ++i) {
        const Point c = candidates[i].centre;
        if (ok[i] == 0) {
          continue;
        }
        if (!found[i].chain) {
          walls.push_back(candidates[i]);
          continue;
        }
        // Skip near-duplicates (the end of one edge and the start of the next where they are collinear).
        if (kept.empty() || std::hypot(c.x - kept.back().centre.x, c.y - kept.back().centre.y) > 0.25 * spacing) {
          kept.push_back(candidates[i]);
        }
      }
      const std::string where = (r == 0 ? std::string("the outer ring") : "hole " + std::to_string(r)) +
                                " of polygon " + std::to_string(polygon + 1);
      if (kept.size() < 3) {
        throw OptionError("walls: no closed chain of wall disks of radius " + detail::format_double(wall_radius) +
                          " fits outside " + where + "; use a smaller wall radius");
      }
      for (std::size_t i = 0; i < kept.size(); ++i) {
        const Point a = kept[i].centre;
        const Point b = kept[(i + 1) % kept.size()].centre;
        // The margin covers the rounding of hypot (a few ulps).
        if (!(std::hypot(b.x - a.x, b.y - a.y) < reach * (1 - 1e-12))) {
          throw OptionError("walls: wall disks of radius " + detail::format_double(wall_radius) + " along " + where +
                            " leave a gap between " + detail::format_point(a) + " and " + detail::format_point(b) +
                            " that a disk of radius " + detail::format_double(rmin) +
                            " could pass (no wall disk fits there outside the domain); use a smaller wall radius");
        }
      }
      walls.insert(walls.end(), kept.begin(), kept.end());
    }
    ++polygon;
  }
  return walls;
}

}  // namespace frontpack
