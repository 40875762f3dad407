// Frozen wall disks along every ring of a domain, outside it, certified exactly against the
// domain's complement, with no gap a free disk could pass.
//
// Placement. Rings are normalised (outer rings anticlockwise, holes clockwise), so the domain is on
// the left of every edge and the outside on its right. Along each edge, centres on the line offset
// by w (1 + 1e-6) to the right, at most w apart; at a convex vertex, an arc of centres about the
// vertex; at a reflex vertex, the point where the two offset lines meet (a disk there touches both
// edges' lines). Candidates are certified exactly (the closed wall disk in the closed complement,
// Domain::contains on a domain built from the complement); those that fail (near a reflex vertex,
// or where another part of the boundary is close) are dropped, and the chain that remains is
// verified (wall_chain.hpp): outside, no gap a free disk passes, the whole ring covered. Before any
// is placed, the radius is held to the coordinates' precision and the count to the Budget.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include "common/budget.hpp"
#include "common/format.hpp"
#include "decks/wall_chain.hpp"
#include "frontpack/deck.hpp"

namespace frontpack {

namespace detail {

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

// A candidate wall disk, placed from ring edge `edge`; `chain` disks form the closed chain along
// the ring (in ring order), the others fill the tips of narrow outside corners.
struct Candidate {
  Disk disk;
  std::size_t edge = 0;
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
      out.push_back(
          {{along(along(a, u, len * static_cast<double>(j) / static_cast<double>(k)), nr, offset), radius}, i});
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
        out.push_back({{along(b, d, offset), radius}, i});
      }
    } else if (turn < 0 && cosine > -0.999) {
      // Where the offset lines meet: b + offset (n1 + n2) / (1 + n1.n2); then smaller disks, each
      // touching both edges' lines, into the corner's tip.
      const Vec s{(nr.x + n2.x) / (1 + cosine), (nr.y + n2.y) / (1 + cosine)};
      out.push_back({{along(b, s, offset), radius}, i});
      double r = radius;
      for (int h = 0; h < kTipHalvings; ++h) {
        r /= 2;
        out.push_back({{along(b, s, r * (1 + 1e-6)), r}, i, false});
      }
    }
  }
  return out;
}

}  // namespace

Domain wall_complement(const Domain& domain, double wall_radius, double rmin) {
  return complement(domain, 4 * wall_radius * (1 + 1e-6) + 2 * (wall_radius + rmin));
}

double ring_wall_count(const Ring& ring, double wall_radius) {
  // ring_candidates' counts, in floating point: ceil(len / spacing) + 1 per edge, an arc of
  // ceil(angle offset / spacing) - 1 at a convex corner, 1 + kTipHalvings at a reflex one.
  const double spacing = wall_radius / 2;
  const double offset = wall_radius * (1 + 1e-6);
  const std::size_t n = ring.size();
  double count = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const Point a = ring[i];
    const Point b = ring[(i + 1) % n];
    const Point c = ring[(i + 2) % n];
    const double len = std::hypot(b.x - a.x, b.y - a.y);
    count += std::ceil(len / spacing) + 1;
    const double turn = (b.x - a.x) * (c.y - b.y) - (b.y - a.y) * (c.x - b.x);
    const double angle = std::atan2(std::abs(turn), (b.x - a.x) * (c.x - b.x) + (b.y - a.y) * (c.y - b.y));
    count += turn > 0 ? std::ceil(angle * offset / spacing) : (turn < 0 ? 1 + kTipHalvings : 0);
  }
  return count;
}

RingWalls ring_walls(const Domain& outside, const Ring& ring, double wall_radius) {
  const double spacing = wall_radius / 2;
  const std::vector<Candidate> found = ring_candidates(ring, wall_radius, spacing);
  std::vector<Disk> candidates;
  candidates.reserve(found.size());
  for (const Candidate& c : found) {
    candidates.push_back(c.disk);
  }
  std::vector<std::uint8_t> ok(candidates.size());
  outside.contains(candidates, ok);
  RingWalls out;
  for (std::size_t i = 0; i < candidates.size(); ++i) {
    const Point c = candidates[i].centre;
    if (ok[i] == 0) {
      continue;
    }
    if (!found[i].chain) {
      out.tips.push_back({candidates[i], found[i].edge});
      continue;
    }
    // Skip near-duplicates (the end of one edge and the start of the next where they are collinear).
    const Disk* last = out.chain.empty() ? nullptr : &out.chain.back().disk;
    if (last == nullptr || std::hypot(c.x - last->centre.x, c.y - last->centre.y) > 0.25 * spacing) {
      out.chain.push_back({candidates[i], found[i].edge});
    }
  }
  return out;
}

}  // namespace detail

namespace {

// "at least X": `value` rounded up to two significant digits.
std::string at_least(double value) {
  const double unit = std::pow(10.0, std::floor(std::log10(value)) - 1);
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.2g", std::ceil(value / unit * (1 - 1e-9)) * unit);
  return buf;
}

// The smallest wall radius whose count fits `budget`. The count at radius w is 2 perimeter / w
// (along the edges) plus a part that does not depend on w (corners, edge ends): `count` less
// 2 perimeter / w at the radius asked. 0 if no radius fits.
double smallest_radius_for(const Budget& budget, double count, double perimeter, double wall_radius,
                           double bytes_each) {
  double allowed = budget.max_count != 0 ? static_cast<double>(budget.max_count) : INFINITY;
  const double memory = detail::memory_allowed(budget);
  if (memory > 0) {
    allowed = std::min(allowed, memory / bytes_each);
  }
  const double fixed = std::max(0.0, count - 2 * perimeter / wall_radius);
  return allowed > fixed ? 2 * perimeter / (allowed - fixed) : 0.0;
}

}  // namespace

std::vector<Disk> wall_disks(const Domain& domain, double wall_radius, double rmin, const Budget& budget) {
  if (!(std::isfinite(wall_radius) && wall_radius > 0)) {
    throw OptionError("wall radius " + detail::format_double(wall_radius) + " must be a finite number > 0");
  }
  if (!(std::isfinite(rmin) && rmin > 0)) {
    throw OptionError("smallest free radius " + detail::format_double(rmin) + " must be a finite number > 0");
  }
  const Box bbox = domain.bbox();
  const double floor = detail::wall_radius_floor(bbox);
  if (!(wall_radius >= floor)) {
    const double m = std::max({std::abs(bbox.xmin), std::abs(bbox.xmax), std::abs(bbox.ymin), std::abs(bbox.ymax)});
    throw OptionError("walls: wall radius " + detail::format_double(wall_radius) +
                      " is below the precision floor of coordinates up to " + detail::format_double(m) +
                      ": the rounding of a wall disk's centre would exceed its gap of 1e-6 wall radii from the "
                      "boundary; use a wall radius of at least " +
                      at_least(floor));
  }
  // Measured: a wall disk costs about 218 bytes through a LAMMPS deck (16 million took 3.4 GB
  // peak): its candidate, certification and chain entries, its copy among the deck's atoms and its
  // 54 bytes of data-file text, held twice while the text is made.
  constexpr double kBytesPerWallDisk = 220;
  double count = 0;
  double perimeter = 0;
  for (const Polygon& p : domain.polygons()) {
    for (std::size_t r = 0; r <= p.holes.size(); ++r) {
      const Ring& ring = r == 0 ? p.outer : p.holes[r - 1];
      count += detail::ring_wall_count(ring, wall_radius);
      for (std::size_t i = 0; i < ring.size(); ++i) {
        const Point a = ring[i];
        const Point b = ring[(i + 1) % ring.size()];
        perimeter += std::hypot(b.x - a.x, b.y - a.y);
      }
    }
  }
  const double smallest = smallest_radius_for(budget, count, perimeter, wall_radius, kBytesPerWallDisk);
  detail::check_count(budget, count, kBytesPerWallDisk, "wall disks",
                      smallest > 0 ? "use a wall radius of at least " + at_least(smallest)
                                   : std::string("simplify the domain (each edge and corner takes wall disks, "
                                                 "whatever their radius)"));

  const Domain outside = detail::wall_complement(domain, wall_radius, rmin);
  std::vector<Disk> walls;
  std::size_t polygon = 0;
  for (const Polygon& p : domain.polygons()) {
    for (std::size_t r = 0; r <= p.holes.size(); ++r) {
      const Ring& ring = r == 0 ? p.outer : p.holes[r - 1];
      detail::RingWalls found = detail::ring_walls(outside, ring, wall_radius);
      const std::string where = (r == 0 ? std::string("the outer ring") : "hole " + std::to_string(r)) +
                                " of polygon " + std::to_string(polygon + 1);
      detail::verify_wall_chain(outside, ring, found.chain, wall_radius, rmin, where);
      for (const detail::ChainDisk& t : found.tips) {
        walls.push_back(t.disk);
      }
      for (const detail::ChainDisk& c : found.chain) {
        walls.push_back(c.disk);
      }
    }
    ++polygon;
  }
  return walls;
}

}  // namespace frontpack
