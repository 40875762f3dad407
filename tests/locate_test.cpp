// Exact point and disk classification at the places where floating point goes wrong: on
// vertices, on edges, inside holes, and one ulp to either side of an edge.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "frontpack/frontpack.hpp"
#include "test_support.hpp"

namespace fp = frontpack;
using fp::Location;

namespace {

double up(double v) {
  return std::nextafter(v, std::numeric_limits<double>::infinity());
}
double down(double v) {
  return std::nextafter(v, -std::numeric_limits<double>::infinity());
}

// A square with a square hole and a diagonal edge: 0.1 is not representable, so points "on"
// the diagonal edge are decided by the exact orientation of the very doubles given.
const char* const kPlate = "POLYGON((0 0,4 0,4 3,3 4,0 4,0 0),(1 1,1 2,2 2,2 1,1 1))";

}  // namespace

TEST(Locate, VerticesAndEdgesAreBoundary) {
  const fp::Domain d = fp::Domain::from_wkt(kPlate);
  for (const fp::Point p : {fp::Point{0, 0},
                            {4, 0},
                            {4, 3},
                            {3, 4},
                            {0, 4},
                            {1, 1},
                            {2, 2},
                            {2, 0},
                            {4, 1.5},
                            {3.5, 3.5},
                            {1.5, 1},
                            {1, 1.75},
                            {0, 0.1}}) {
    EXPECT_EQ(d.locate(p), Location::boundary) << p.x << " " << p.y;
  }
}

TEST(Locate, InteriorHoleAndExterior) {
  const fp::Domain d = fp::Domain::from_wkt(kPlate);
  EXPECT_EQ(d.locate({0.5, 0.5}), Location::inside);
  EXPECT_EQ(d.locate({3, 3}), Location::inside);
  EXPECT_EQ(d.locate({1.5, 1.5}), Location::outside);  // in the hole
  EXPECT_EQ(d.locate({3.9, 3.9}), Location::outside);  // beyond the diagonal
  EXPECT_EQ(d.locate({-1, 2}), Location::outside);
  EXPECT_EQ(d.locate({5, 5}), Location::outside);
  EXPECT_EQ(d.locate({NAN, 1}), Location::outside);
  EXPECT_EQ(d.locate({INFINITY, 1}), Location::outside);
}

TEST(Locate, OneUlpOffAxisParallelEdges) {
  const fp::Domain d = fp::Domain::from_wkt(kPlate);
  // Outer left edge x = 0 and hole edge x = 1.
  EXPECT_EQ(d.locate({up(0.0), 2.5}), Location::inside);
  EXPECT_EQ(d.locate({down(0.0), 2.5}), Location::outside);
  EXPECT_EQ(d.locate({down(1.0), 1.5}), Location::inside);
  EXPECT_EQ(d.locate({up(1.0), 1.5}), Location::outside);
  EXPECT_EQ(d.locate({1.5, down(1.0)}), Location::inside);
  EXPECT_EQ(d.locate({1.5, up(1.0)}), Location::outside);
  EXPECT_EQ(d.locate({down(4.0), 1}), Location::inside);
  EXPECT_EQ(d.locate({up(4.0), 1}), Location::outside);
  // One ulp off a vertex, outward and inward.
  EXPECT_EQ(d.locate({up(0.0), up(0.0)}), Location::inside);
  EXPECT_EQ(d.locate({down(0.0), 0}), Location::outside);
}

TEST(Locate, OneUlpOffADiagonalEdge) {
  const fp::Domain d = fp::Domain::from_wkt(kPlate);
  // The edge (4 3)-(3 4) is the line x + y = 7. Points whose coordinates sum to exactly 7 are on
  // it; nudging y by one ulp moves the point off it, to one side or the other.
  for (const double x : {3.25, 3.5, 3.0625, 3.9990234375}) {
    const double y = 7.0 - x;  // exact for these x
    ASSERT_EQ(x + y, 7.0);
    EXPECT_EQ(d.locate({x, y}), Location::boundary) << x;
    EXPECT_EQ(d.locate({x, down(y)}), Location::inside) << x;
    EXPECT_EQ(d.locate({x, up(y)}), Location::outside) << x;
    EXPECT_EQ(d.locate({down(x), y}), Location::inside) << x;
    EXPECT_EQ(d.locate({up(x), y}), Location::outside) << x;
  }
  // 0.1 is not representable: the double nearest 3.1 plus the one nearest 3.9 need not be on
  // the line; the answer must follow the exact sum, not the rounded one.
  const fp::Point p{3.1, 3.9};
  const long double exact_sum =
      static_cast<long double>(p.x) + static_cast<long double>(p.y);  // 64-bit mantissa: exact
  const Location expected =
      exact_sum == 7.0L ? Location::boundary : (exact_sum < 7.0L ? Location::inside : Location::outside);
  EXPECT_EQ(d.locate(p), expected);
}

TEST(Contains, TouchingTheBoundaryCountsAsInside) {
  const fp::Domain d = fp::Domain::from_wkt(kPlate);
  // Disk in the corner region tangent to the bottom edge and to the hole's bottom edge.
  EXPECT_TRUE(d.contains({{2.5, 0.5}, 0.5}));
  EXPECT_FALSE(d.contains({{2.5, 0.5}, up(0.5)}));
  EXPECT_FALSE(d.contains({{2.5, down(0.5)}, 0.5}));
  // Tangent to the hole's left edge x = 1 from the left, and to the outer edge x = 0.
  EXPECT_TRUE(d.contains({{0.5, 1.5}, 0.5}));
  EXPECT_FALSE(d.contains({{up(0.5), 1.5}, 0.5}));
  // Around a hole corner: the nearest point is the vertex (2 2); distance sqrt(0.5) is not a
  // double, so a radius rounded down fits and its successor does not.
  const double r = std::sqrt(0.5);
  const fp::Point c{2.5, 2.5};
  const bool fits = std::fma(r, r, -0.5) <= 0.0;  // fma: the sign of r*r - 0.5 is exact
  EXPECT_EQ(d.contains({c, r}), fits);
  EXPECT_EQ(d.contains({c, fits ? up(r) : down(r)}), !fits);
}

TEST(Contains, DiagonalEdgeTangency) {
  const fp::Domain d = fp::Domain::from_wkt("POLYGON((0 0,8 0,0 8,0 0))");
  // Distance from (3 3) to x + y = 8 is sqrt(2) (3 to the other edges): not a double; decided
  // exactly, whichever way sqrt rounded.
  const double r = std::sqrt(2.0);
  const bool fits = std::fma(r, r, -2.0) <= 0.0;
  EXPECT_EQ(d.contains({{3, 3}, r}), fits);
  EXPECT_EQ(d.contains({{3, 3}, up(r)}), false);
  EXPECT_EQ(d.contains({{3, 3}, down(down(r))}), true);
}

TEST(Contains, DegenerateDisks) {
  const fp::Domain d = fp::Domain::from_wkt(kPlate);
  EXPECT_TRUE(d.contains({{0, 0}, 0.0}));  // a point on the boundary touches
  EXPECT_TRUE(d.contains({{0.5, 0.5}, 0.0}));
  EXPECT_FALSE(d.contains({{1.5, 1.5}, 0.0}));  // in the hole
  EXPECT_FALSE(d.contains({{0, 1}, 0.25}));     // centre on the boundary, positive radius
  EXPECT_FALSE(d.contains({{2, 2}, -1.0}));
  EXPECT_FALSE(d.contains({{2, 2}, NAN}));
  EXPECT_FALSE(d.contains({{2, 2}, INFINITY}));
  EXPECT_FALSE(d.contains({{0.5, 0.5}, 100.0}));
  EXPECT_FALSE(d.contains({{NAN, 0.5}, 0.1}));
}

TEST(Contains, BatchAgreesWithSingleQueries) {
  const fp::Domain d = fp::Domain::from_wkt_file(fp::test::shapes_dir() / "plate_with_holes.wkt");
  std::vector<fp::Disk> disks;
  for (int i = 0; i <= 200; ++i) {
    for (int j = 0; j <= 100; ++j) {
      disks.push_back({{i * 0.02, j * 0.02}, 0.015 + 0.01 * ((i * 7 + j * 3) % 5)});
    }
  }
  std::vector<std::uint8_t> out(disks.size());
  d.contains(disks, out);
  std::size_t inside = 0;
  for (std::size_t k = 0; k < disks.size(); ++k) {
    ASSERT_EQ(out[k] != 0, d.contains(disks[k])) << k;
    inside += out[k];
  }
  EXPECT_GT(inside, disks.size() / 2);
  EXPECT_LT(inside, disks.size());
  std::vector<std::uint8_t> wrong(disks.size() - 1);
  EXPECT_THROW(d.contains(disks, wrong), std::invalid_argument);
}

TEST(Contains, MultipolygonIslandInAHole) {
  const fp::Domain d =
      fp::Domain::from_wkt("MULTIPOLYGON(((0 0,9 0,9 9,0 9,0 0),(2 2,2 7,7 7,7 2,2 2)),((3 3,6 3,6 6,3 6,3 3)))");
  EXPECT_EQ(d.locate({1, 1}), Location::inside);
  EXPECT_EQ(d.locate({2.5, 2.5}), Location::outside);  // in the lake
  EXPECT_EQ(d.locate({4.5, 4.5}), Location::inside);   // on the island
  EXPECT_TRUE(d.contains({{4.5, 4.5}, 1.5}));
  EXPECT_FALSE(d.contains({{4.5, 4.5}, up(1.5)}));
  EXPECT_FALSE(d.contains({{2.5, 4.5}, 0.25}));
  EXPECT_TRUE(d.contains({{1, 4.5}, 1.0}));
}
