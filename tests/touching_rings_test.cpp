// Validation of domains whose rings touch in many places or nest deeply: checkerboards of parts
// or holes meeting at corners, holes and parts touching one long ring, rings nested a hundred
// deep. Validation finds which ring encloses which by one sweep (src/domain/ring_tree.cpp); these cases
// cost a ray through every ring, or brute force, per ring before it. Sizes stay small so that the
// sanitizer build runs them fast; the large ones are benchmarks (bench/domain_bench.cpp).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <numbers>
#include <string>
#include <vector>

#include "frontpack/frontpack.hpp"

namespace fp = frontpack;
using Kind = fp::InvalidDomainError::Kind;

namespace {

// The unit square with lower left corner (x, y), anticlockwise.
fp::Ring square(double x, double y, double side = 1.0) {
  return {{x, y}, {x + side, y}, {x + side, y + side}, {x, y + side}};
}

// The squares of one colour of an n x n board: (i + j) even. Neighbours touch at corners.
std::vector<fp::Polygon> checkerboard(int n) {
  std::vector<fp::Polygon> parts;
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      if ((i + j) % 2 == 0) {
        parts.push_back({square(i, j), {}});
      }
    }
  }
  return parts;
}

// A frame one unit larger than the n x n board all round, with the board's squares at the
// positions `keep` accepts as holes.
template <class Keep>
fp::Polygon board_with_holes(int n, Keep keep) {
  fp::Polygon p{square(-1, -1, n + 2.0), {}};
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      if (keep(i, j)) {
        p.holes.push_back(square(i, j));
      }
    }
  }
  return p;
}

// The error Domain::from_polygons throws, or fails the test.
fp::InvalidDomainError rejection(const std::vector<fp::Polygon>& parts) {
  try {
    (void)fp::Domain::from_polygons(parts);
  } catch (const fp::InvalidDomainError& e) {
    return e;
  }
  ADD_FAILURE() << "accepted an invalid domain";
  return fp::InvalidDomainError(Kind::empty, "not rejected", {});
}

}  // namespace

TEST(TouchingRings, CheckerboardOfPartsIsValid) {
  const std::vector<fp::Polygon> board = checkerboard(32);
  const fp::Domain d = fp::Domain::from_polygons(board);
  EXPECT_EQ(d.num_polygons(), 512U);
  EXPECT_EQ(d.num_vertices(), 2048U);
  EXPECT_EQ(d.area(), 512.0);
  EXPECT_EQ(d.locate({0.5, 0.5}), fp::Location::inside);
  EXPECT_EQ(d.locate({1.5, 0.5}), fp::Location::outside);  // a square of the other colour
  EXPECT_EQ(d.locate({1, 1}), fp::Location::boundary);     // where four squares meet
  // Order and orientation of the rings do not matter.
  std::vector<fp::Polygon> reversed(board.rbegin(), board.rend());
  for (fp::Polygon& p : reversed) {
    std::reverse(p.outer.begin(), p.outer.end());
  }
  EXPECT_EQ(fp::Domain::from_polygons(reversed).area(), 512.0);
}

TEST(TouchingRings, CheckerboardWithASquareOfTheOtherColourSharesEdges) {
  std::vector<fp::Polygon> board = checkerboard(32);
  board.push_back({square(5, 6), {}});  // (5 + 6) odd: its edges are its neighbours' edges
  const fp::InvalidDomainError e = rejection(board);
  EXPECT_EQ(e.kind(), Kind::rings_overlap) << e.what();
  ASSERT_TRUE(e.other_site().has_value());
  EXPECT_EQ(std::max(e.site().part, e.other_site()->part), 512U) << e.what();
}

TEST(TouchingRings, CheckerboardWithTwoOverlappingSquaresIsRejected) {
  std::vector<fp::Polygon> board = checkerboard(32);
  board.push_back({square(10.5, 10.5), {}});  // crosses squares (10, 10) and (11, 11)
  EXPECT_EQ(rejection(board).kind(), Kind::rings_cross);
}

// A square strictly inside a square of the board meets no edge: only nesting finds it, and the
// report names both parts.
TEST(TouchingRings, CheckerboardWithASquareInsideAnotherIsRejected) {
  std::vector<fp::Polygon> board = checkerboard(32);
  const std::size_t host = 32 * 7 / 2 + 3;  // row 7 holds squares (1, 7), (3, 7), ...: (7, 7) is its fourth
  board.push_back({square(7.25, 7.25, 0.5), {}});
  const fp::InvalidDomainError e = rejection(board);
  EXPECT_EQ(e.kind(), Kind::overlapping_parts) << e.what();
  EXPECT_EQ(e.site().part, 512U);
  ASSERT_TRUE(e.other_site().has_value());
  EXPECT_EQ(e.other_site()->part, host) << e.what();
  EXPECT_NE(std::string(e.what()).find("polygons " + std::to_string(host) + " and 512 overlap"), std::string::npos)
      << e.what();
}

// Holes of one colour of a board: the four holes around each square of the other colour touch in
// a loop that cuts that square off the rest of the interior.
TEST(TouchingRings, CheckerboardOfHolesDisconnectsTheInterior) {
  const fp::Polygon p = board_with_holes(32, [](int i, int j) { return (i + j) % 2 == 0; });
  ASSERT_EQ(p.holes.size(), 512U);
  const fp::InvalidDomainError e = rejection({p});
  EXPECT_EQ(e.kind(), Kind::disconnected_interior) << e.what();
  EXPECT_EQ(e.site().part, 0U);
}

// Holes along every third diagonal touch their diagonal neighbours at corners: chains, no loop.
TEST(TouchingRings, DiagonalChainsOfTouchingHolesAreValid) {
  const int n = 64;
  const auto on_chain = [](int i, int j) { return ((j - i) % 3 + 3) % 3 == 0; };
  const fp::Polygon p = board_with_holes(n, on_chain);
  const fp::Domain d = fp::Domain::from_polygons({p});
  EXPECT_EQ(d.num_holes(), p.holes.size());
  EXPECT_EQ(d.area(), (n + 2.0) * (n + 2.0) - static_cast<double>(p.holes.size()));
  EXPECT_EQ(d.locate({0.5, 0.5}), fp::Location::outside);  // in hole (0, 0)
  EXPECT_EQ(d.locate({1.5, 0.5}), fp::Location::inside);
  // Closing one chain against the frame at both ends cuts the polygon: a chain from corner to
  // corner of the board, made to touch the frame at (-1, -1) and (n + 1, n + 1).
  fp::Polygon closed = p;
  closed.holes.push_back({{-1, -1}, {0, -0.5}, {0, 0}, {-0.5, 0}});
  closed.holes.push_back({{n + 1.0, n + 1.0}, {n, n + 0.5}, {n, n}, {n + 0.5, n}});
  EXPECT_EQ(rejection({closed}).kind(), Kind::disconnected_interior);
}

// Holes touching the outer ring each at one point, inside one of its edges or at one of its
// vertices, are valid; one more touching it twice is not.
TEST(TouchingRings, ManyHolesTouchingTheOuterRing) {
  const int n = 400;
  fp::Ring outer{{0, 0}};
  for (int i = 0; i < n; ++i) {
    outer.push_back({4.0 * i + 3, 0});  // the holes at 4i + 3 touch a vertex of the outer ring
  }
  outer.insert(outer.end(), {{4.0 * n + 1, 0}, {4.0 * n + 1, 10}, {0, 10}});
  fp::Polygon p{outer, {}};
  for (int i = 0; i < n; ++i) {
    const double x = 4.0 * i;
    p.holes.push_back({{x + 1, 0}, {x + 1.5, 1}, {x + 1, 1}});  // touches inside the bottom edge
    p.holes.push_back({{x + 3, 0}, {x + 3.5, 1}, {x + 3, 1}});  // touches at a vertex
  }
  const fp::Domain d = fp::Domain::from_polygons({p});
  EXPECT_EQ(d.num_holes(), 2U * n);
  EXPECT_EQ(d.area(), (4.0 * n + 1) * 10 - n * 0.5);
  fp::Polygon twice = p;
  twice.holes.push_back({{2.25, 0}, {2.75, 1}, {2.25, 10}, {1.75, 1}});  // touches the bottom and the top
  const fp::InvalidDomainError e = rejection({twice});
  EXPECT_EQ(e.kind(), Kind::disconnected_interior) << e.what();
  EXPECT_NE(std::string(e.what()).find("hole " + std::to_string(2 * n + 1) + " and the outer ring touch"),
            std::string::npos)
      << e.what();
}

// Long thin parts standing on one base part, each touching it at one point (inside an edge of
// the base or at one of its vertices); one that dips into the base crosses it.
TEST(TouchingRings, ThinPartsTouchingOneBasePart) {
  const int n = 400;
  fp::Ring base{{0, 0}, {4.0 * n, 0}, {4.0 * n, 1}};
  for (int i = n; i-- > 0;) {
    base.push_back({4.0 * i + 3, 1});  // a vertex for the parts at 4i + 3
  }
  base.push_back({0, 1});
  std::vector<fp::Polygon> parts{{base, {}}};
  for (int i = 0; i < n; ++i) {
    const double x = 4.0 * i;
    parts.push_back({{{x + 1, 1}, {x + 1.5, 1000}, {x + 0.5, 1000}}, {}});
    parts.push_back({{{x + 3, 1}, {x + 3.5, 1000}, {x + 2.5, 1000}}, {}});
  }
  const fp::Domain d = fp::Domain::from_polygons(parts);
  EXPECT_EQ(d.num_polygons(), 2U * n + 1);
  EXPECT_EQ(d.area(), 4.0 * n + 2.0 * n * 999 * 0.5);
  parts.push_back({{{2, 0.5}, {2.25, 1000}, {1.75, 1000}}, {}});
  EXPECT_EQ(rejection(parts).kind(), Kind::rings_cross);
}

// Concentric square annuli, 100 deep: part k is the ring between squares 2k and 2k + 1 units in
// from the outside, so part k + 1 lies in part k's hole. Any ring placed in the wrong polygon is
// reported as the ray parity reports it.
TEST(TouchingRings, ConcentricPartsNestedAHundredDeep) {
  const int depth = 100;
  const double size = 4.0 * depth + 2;
  const auto nested = [size](int inset) { return square(inset, inset, size - 2.0 * inset); };
  std::vector<fp::Polygon> parts;
  for (int k = 0; k < depth; ++k) {
    parts.push_back({nested(2 * k), {nested(2 * k + 1)}});
  }
  const fp::Domain d = fp::Domain::from_polygons(parts);
  EXPECT_EQ(d.num_polygons(), 100U);
  EXPECT_EQ(d.locate({0.5, size / 2}), fp::Location::inside);
  EXPECT_EQ(d.locate({1.5, size / 2}), fp::Location::outside);
  EXPECT_EQ(d.locate({2.0 * depth - 0.5, size / 2}), fp::Location::outside);

  // The innermost part without its hole: still valid (it lies in part 98's hole).
  std::vector<fp::Polygon> solid_core = parts;
  solid_core.back().holes.clear();
  EXPECT_EQ(fp::Domain::from_polygons(solid_core).num_holes(), 99U);

  // Part 50 without its hole: part 51 lies inside it, through its outer ring alone.
  std::vector<fp::Polygon> filled = parts;
  filled[50].holes.clear();
  fp::InvalidDomainError e = rejection(filled);
  EXPECT_EQ(e.kind(), Kind::overlapping_parts) << e.what();
  EXPECT_NE(std::string(e.what()).find("polygons 50 and 51 overlap"), std::string::npos) << e.what();

  // Part 60's hole handed to part 30: it lies inside part 30's own hole.
  std::vector<fp::Polygon> moved = parts;
  moved[30].holes.push_back(moved[60].holes[0]);
  moved[60].holes.clear();
  e = rejection(moved);
  EXPECT_EQ(e.kind(), Kind::nested_holes) << e.what();
  EXPECT_NE(std::string(e.what()).find("polygon 30, hole 2 lies inside polygon 30, hole 1"), std::string::npos)
      << e.what();

  // A hole of part 80 placed in part 20's ring, far outside part 80's outer ring.
  std::vector<fp::Polygon> outside = parts;
  outside[80].holes.push_back(square(40.25, size / 2, 0.5));
  e = rejection(outside);
  EXPECT_EQ(e.kind(), Kind::hole_outside_shell) << e.what();
  EXPECT_NE(std::string(e.what()).find("polygon 80, hole 2: the hole is not inside its outer ring"), std::string::npos)
      << e.what();
}

namespace {

// n thin triangles with a common vertex at the origin, the k-th spanning the angles
// [2 pi k / n, 2 pi (k + 1/2) / n] out to radius 1 (rounded points: the spans stay apart).
std::vector<fp::Ring> fan(int n) {
  std::vector<fp::Ring> rings;
  for (int k = 0; k < n; ++k) {
    const double a = 2 * std::numbers::pi * k / n;
    const double b = 2 * std::numbers::pi * (k + 0.5) / n;
    rings.push_back({{0, 0}, {std::cos(a), std::sin(a)}, {std::cos(b), std::sin(b)}});
  }
  return rings;
}

}  // namespace

// Hundreds of parts meeting at one point: their edges there meet pairwise (src/domain/validate.cpp sorts
// them by angle about the point instead of classifying the pairs). Valid, as parts or as holes
// of one polygon; one more part leaving the point along an edge of another overlaps it; two
// holes meeting at the centre and again at the outer ends cut the polygon.
TEST(TouchingRings, FanOfRingsMeetingAtOnePoint) {
  const std::vector<fp::Ring> rings = fan(512);
  std::vector<fp::Polygon> parts;
  for (const fp::Ring& r : rings) {
    parts.push_back({r, {}});
  }
  const fp::Domain d = fp::Domain::from_polygons(parts);
  EXPECT_EQ(d.num_polygons(), 512U);
  EXPECT_EQ(d.locate({0, 0}), fp::Location::boundary);

  fp::Polygon holes{square(-2, -2, 4), rings};
  EXPECT_EQ(fp::Domain::from_polygons({holes}).num_holes(), 512U);

  std::vector<fp::Polygon> along = parts;
  along.push_back({{{0, 0}, {rings[7][1].x * 0.5, rings[7][1].y * 0.5}, {-0.001, 0.5}}, {}});
  EXPECT_EQ(rejection(along).kind(), Kind::rings_overlap);

  // Holes 1 and 2 meet at the origin and again at (1 0.2), a vertex of each: a loop.
  const fp::Polygon cut{square(-2, -2, 4), {{{0, 0}, {1, 0.2}, {1, 0.5}}, {{0, 0}, {0.5, -0.3}, {1, 0.2}, {0.6, 0}}}};
  const fp::InvalidDomainError e = rejection({cut});
  EXPECT_EQ(e.kind(), Kind::disconnected_interior) << e.what();
  EXPECT_NE(std::string(e.what()).find("touch at (1 0.2) and (0 0)"), std::string::npos) << e.what();
}
