// certify()'s report on hand-made disk sets: the exact decisions (which disks are outside, which
// pairs overlap) and the floating-point "how bad" figures frontpack check prints.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "frontpack/frontpack.hpp"

namespace fp = frontpack;

namespace {

// The unit square with a square hole [0.4, 0.6]^2. Every number below is a short binary
// fraction or chosen so that the expected figures are exact in double.
fp::Domain square_with_hole() {
  return fp::Domain::from_wkt(
      "POLYGON((0 0,1 0,1 1,0 1,0 0),(0.375 0.375,0.375 0.625,0.625 0.625,0.625 0.375,0.375 0.375))");
}

TEST(CertifyReport, CertifiedSetHasNoWorst) {
  const std::vector<fp::Disk> disks = {{{0.125, 0.125}, 0.125}, {{0.375, 0.125}, 0.125}};  // touching, and the walls
  const fp::CertifyReport r = fp::certify(square_with_hole(), disks);
  EXPECT_TRUE(r.outside.empty());
  EXPECT_TRUE(r.overlapping.empty());
  EXPECT_FALSE(r.deepest_overlap.has_value());
  EXPECT_FALSE(r.farthest_outside.has_value());
}

TEST(CertifyReport, DeepestOverlapIsTheDeepestPair) {
  const std::vector<fp::Disk> disks = {
      {{0.125, 0.125}, 0.0625}, {{0.25, 0.125}, 0.0625},     // overlap by 0 (touch): not a pair
      {{0.125, 0.875}, 0.0625}, {{0.1875, 0.875}, 0.0625},   // overlap by 0.0625
      {{0.875, 0.875}, 0.0625}, {{0.875, 0.78125}, 0.0625},  // overlap by 0.03125
  };
  const fp::CertifyReport r = fp::certify(square_with_hole(), disks);
  ASSERT_EQ(r.overlapping.size(), 2u);
  ASSERT_TRUE(r.deepest_overlap.has_value());
  EXPECT_EQ(r.deepest_overlap->first, 2u);
  EXPECT_EQ(r.deepest_overlap->second, 3u);
  EXPECT_EQ(r.deepest_overlap_depth, 0.0625);
}

TEST(CertifyReport, FarthestOutsideMeasuresFromTheBoundary) {
  const std::vector<fp::Disk> disks = {
      {{0.0625, 0.25}, 0.125},  // centre inside, 0.0625 through the left wall
      {{1.125, 0.25}, 0.0625},  // centre outside, 0.125 beyond the right wall: reaches 0.1875 out
      {{0.5, 0.5}, 0.0625},     // centre in the hole, 0.125 from its edges: 0.1875 into the hole
      {{0.25, 0.75}, 0.125},    // inside
      {{0.75, 0.0}, 0.03125},   // centre on the boundary: 0.03125 out
  };
  const fp::CertifyReport r = fp::certify(square_with_hole(), disks);
  EXPECT_EQ(r.outside, (std::vector<std::size_t>{0, 1, 2, 4}));
  ASSERT_TRUE(r.farthest_outside.has_value());
  EXPECT_EQ(*r.farthest_outside, 1u);  // the first of the two at 0.1875
  EXPECT_DOUBLE_EQ(r.farthest_outside_by, 0.1875);
}

TEST(CertifyReport, NonFiniteDiskIsInfinitelyFarOut) {
  const std::vector<fp::Disk> disks = {{{2.0, 2.0}, 0.125}, {{std::numeric_limits<double>::quiet_NaN(), 0.5}, 0.125}};
  const fp::CertifyReport r = fp::certify(square_with_hole(), disks);
  ASSERT_TRUE(r.farthest_outside.has_value());
  EXPECT_EQ(*r.farthest_outside, 1u);
  EXPECT_TRUE(std::isinf(r.farthest_outside_by));
}

}  // namespace

// Far from the origin (8e9, where a float's step is 1024) the overlap pass must still search only
// neighbours: a 100 x 100 grid of touching disks, one pair overlapping by a few ulps of the
// coordinates. Before boxes were taken relative to the disks' corner, every pair was a candidate
// (about 50 million here).
TEST(CertifyReport, FarFromTheOriginTheOverlapPassStaysLocal) {
  const double o = 8e9;
  const fp::Domain domain =
      fp::Domain::from_wkt("POLYGON((8e9 8e9,8000000100 8e9,8000000100 8000000100,8e9 8000000100,8e9 8e9))");
  std::vector<fp::Disk> disks;
  for (int j = 0; j < 100; ++j) {
    for (int i = 0; i < 100; ++i) {
      disks.push_back({{o + 0.5 + i, o + 0.5 + j}, 0.5});  // neighbours touch: not overlapping
    }
  }
  disks[5050].centre.x -= 0x1p-20;  // 1e-6: about 1000 ulps at 8e9, so its left neighbour overlaps
  const fp::CertifyReport r = fp::certify(domain, disks);
  ASSERT_EQ(r.overlapping.size(), 1u);
  EXPECT_EQ(r.overlapping[0], (std::pair<std::size_t, std::size_t>{5049, 5050}));
  EXPECT_TRUE(r.outside.empty());
  EXPECT_LT(r.certificate.candidate_pairs, 10 * disks.size());
}

// The pair test is exact at every scale, down to subnormal coordinates: a 3-4-5 pair that touches
// is no overlap, and the same pair one ulp closer (the larger radius one ulp larger) is one, one
// ulp apart (one ulp smaller) is none. At the smallest scales the squares underflow (to zero, or
// to subnormals with the low bits lost), so only the exact fallback can tell the three apart; at
// 2^-509 they are normal but differ by a subnormal amount, the semi-static filter's floor.
TEST(CertifyReport, PairTestIsExactDownToSubnormals) {
  const fp::Domain domain = fp::Domain::from_wkt("POLYGON((-1 -1,1 -1,1 1,-1 1,-1 -1))");
  for (const double s : {1.0, 0x1p-500, 0x1p-509, 0x1p-530, 0x1p-1000, 0x1p-1060, 0x1p-1070}) {
    SCOPED_TRACE(s);
    const double r = 3 * s;
    const fp::Disk a{{0, 0}, 2 * s};
    const fp::Disk touching{{3 * s, 4 * s}, r};
    const fp::Disk closer{{3 * s, 4 * s}, std::nextafter(r, 2 * r)};
    const fp::Disk apart{{3 * s, 4 * s}, std::nextafter(r, 0.0)};
    EXPECT_TRUE(fp::certify(domain, std::vector<fp::Disk>{a, touching}).overlapping.empty());
    EXPECT_EQ(fp::certify(domain, std::vector<fp::Disk>{a, closer}).overlapping.size(), 1u);
    EXPECT_TRUE(fp::certify(domain, std::vector<fp::Disk>{a, apart}).overlapping.empty());
  }
}
