// EdgeDistanceIndex (src/domain/edge_distance.hpp), the statistics' and the jam's distance to the
// walls: its answers are those of a scan of every edge, bit for bit, and its cost per query does
// not grow with the ratio of the query's reach to the edges' length (a 30,000-vertex circle of
// radius 1 asked as far as 3: each query once scanned the thousands of edges its grid cell of
// side 1 listed). The cost is counted in edges examined, never timed.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <numbers>
#include <random>
#include <vector>

#include "domain/edge_distance.hpp"
#include "frontpack/domain.hpp"

namespace {

namespace fp = frontpack;
using fp::detail::EdgeDistanceIndex;

fp::Ring circle(std::size_t n, double radius, fp::Point centre = {0, 0}) {
  fp::Ring ring;
  for (std::size_t k = 0; k < n; ++k) {
    const double t = 2 * std::numbers::pi * static_cast<double>(k) / static_cast<double>(n);
    ring.push_back({centre.x + radius * std::cos(t), centre.y + radius * std::sin(t)});
  }
  return ring;
}

// A star: n spikes between radii 0.3 and 1 (short and long edges, reflex vertices).
fp::Ring star(std::size_t n) {
  fp::Ring ring;
  for (std::size_t k = 0; k < 2 * n; ++k) {
    const double t = std::numbers::pi * static_cast<double>(k) / static_cast<double>(n);
    const double r = k % 2 == 0 ? 1.0 : 0.3 + 0.2 * static_cast<double>(k % 7) / 7;
    ring.push_back({r * std::cos(t), r * std::sin(t)});
  }
  return ring;
}

// min(cap, distance to every edge of the domain's rings), with the index's own formula for an
// edge's closest point.
double brute_distance(const fp::Domain& domain, fp::Point p, double cap) {
  std::vector<fp::Ring> rings;
  for (const fp::Polygon& polygon : domain.polygons()) {
    rings.push_back(polygon.outer);
    rings.insert(rings.end(), polygon.holes.begin(), polygon.holes.end());
  }
  double best = cap;
  for (const fp::Ring& ring : rings) {
    for (std::size_t k = 0; k < ring.size(); ++k) {
      const fp::Point a = ring[k];
      const fp::Point b = ring[(k + 1) % ring.size()];
      const double dx = b.x - a.x;
      const double dy = b.y - a.y;
      const double len2 = dx * dx + dy * dy;
      double t = len2 > 0 ? ((p.x - a.x) * dx + (p.y - a.y) * dy) / len2 : 0;
      t = std::clamp(t, 0.0, 1.0);
      const fp::Point q{a.x + t * dx, a.y + t * dy};
      best = std::min(best, std::hypot(q.x - p.x, q.y - p.y));
    }
  }
  return best;
}

TEST(EdgeDistance, CostPerQueryDoesNotGrowWithTheReachOverTheEdgeLength) {
  // The statistics of disks up to radius 0.5 in a circle of radius 1 drawn with 30,000 edges
  // (2.1e-4 long): the band is 1 wide, the coverage profile reaches 3. 10,000 queries at random
  // points of the circle's box, at either reach, and whether a disk's centre is near the wall.
  const fp::Domain domain = fp::Domain::from_polygons({fp::Polygon{circle(30'000, 1), {}}});
  const EdgeDistanceIndex edges(domain, 1.0);
  std::mt19937_64 rng(46);
  std::uniform_real_distribution<double> u(-1.2, 1.2);
  constexpr std::size_t kQueries = 10'000;
  for (std::size_t k = 0; k < kQueries; ++k) {
    const fp::Point p{u(rng), u(rng)};
    (void)edges.distance(p, k % 2 == 0 ? 1.0 : 3.0);
    (void)edges.closer_than(p, 0.75);
  }
  // A scan of one grid cell of side 1 examines about 7,500 edges; a search that narrows to the
  // edges near p examines a few dozen per query whatever the reach.
  EXPECT_LT(edges.examined(), 64 * 2 * kQueries) << edges.examined();
}

TEST(EdgeDistance, EqualsAScanOfEveryEdgeBitForBit) {
  // Rings with long and short edges, a hole, points inside, outside and far away, caps from below
  // the edges' length to beyond the domain: the index returns min(cap, every edge's distance)
  // exactly, as a scan of every edge computes it.
  fp::Ring hole = circle(3'000, 0.1);
  std::reverse(hole.begin(), hole.end());
  const fp::Domain domain = fp::Domain::from_polygons({fp::Polygon{star(50), {hole}}});
  for (const double h : {0.001, 0.05, 1.0}) {
    const EdgeDistanceIndex edges(domain, h);
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> u(-1.5, 1.5);
    for (std::size_t k = 0; k < 5'000; ++k) {
      const fp::Point p = k % 100 == 0 ? fp::Point{u(rng) * 1e6, u(rng)} : fp::Point{u(rng), u(rng)};
      const double cap = std::ldexp(1.0, static_cast<int>(k % 24) - 16);
      const double expected = brute_distance(domain, p, cap);
      ASSERT_EQ(edges.distance(p, cap), expected) << "p = (" << p.x << ", " << p.y << "), cap " << cap;
      ASSERT_EQ(edges.closer_than(p, cap), expected < cap);
    }
  }
}

TEST(EdgeDistance, WithinListsEachEdgeInReachOnceInOrder) {
  // The wall contacts' query: every edge whose distance is at most d, once each, in the order of
  // the edges (and near() on an index without a grid the same), against a scan of every edge.
  const fp::Domain domain = fp::Domain::from_polygons({fp::Polygon{star(40), {}}});
  const fp::Ring& ring = domain.polygons()[0].outer;
  const EdgeDistanceIndex edges(domain);
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(-1.2, 1.2);
  std::size_t listed = 0;
  for (std::size_t k = 0; k < 2'000; ++k) {
    const fp::Point p{u(rng), u(rng)};
    const double d = 0.01 * static_cast<double>(k % 40);
    std::vector<double> expected;
    for (std::size_t e = 0; e < ring.size(); ++e) {
      const fp::Point a = ring[e];
      const fp::Point b = ring[(e + 1) % ring.size()];
      const double dx = b.x - a.x;
      const double dy = b.y - a.y;
      const double t = std::clamp(((p.x - a.x) * dx + (p.y - a.y) * dy) / (dx * dx + dy * dy), 0.0, 1.0);
      const double dist = std::hypot(a.x + t * dx - p.x, a.y + t * dy - p.y);
      if (dist <= d) {
        expected.push_back(dist);
      }
    }
    std::vector<double> got;
    edges.within(p, d, [&got](fp::Point, double dist) { got.push_back(dist); });
    std::vector<double> via_near;
    edges.near(p, d, [&via_near](fp::Point, double dist) { via_near.push_back(dist); });
    ASSERT_EQ(got, expected) << "p = (" << p.x << ", " << p.y << "), d " << d;
    ASSERT_EQ(via_near, expected);
    listed += got.size();
  }
  EXPECT_GT(listed, 1'000U);  // the reaches do meet edges
}

}  // namespace
