// The boundary-conforming method (Method::boundary, issue #5): certified on every shape with
// nothing culled; deterministic; the density targets of the issue (interior >= 0.84, band within
// 0.02 of the interior, KS distance by area <= 0.02, at rmax/rmin = 10); denser next to the walls
// than the paper's closed and open forms; termination on hostile domains.
// docs/density.md has the measured table (tools/density_table.py).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <map>
#include <numbers>
#include <string>
#include <vector>

#include "frontpack/frontpack.hpp"
#include "test_support.hpp"

namespace fp = frontpack;

namespace {

using fp::test::fill;

// Certified as every generator's packing is, and with nothing culled: the boundary method places
// every disk inside by construction.
void expect_certified(const fp::Domain& d, const fp::Packing& p) {
  fp::test::expect_certified(d, p);
  EXPECT_EQ(p.certificate.culled, 0U) << "the boundary method generated disks outside the domain";
  EXPECT_EQ(p.certificate.generated, p.disks.size());
}

// rmin for uniform radii [rmin, 10 rmin] giving about n disks on the domain: E[r^2] = 37 rmin^2,
// about 0.8 of the area covered.
double rmin_for(const fp::Domain& d, double n) {
  return std::sqrt(0.8 * d.area() / (n * std::numbers::pi * 37.0));
}

fp::Domain shape(const std::string& name) {
  return fp::Domain::from_wkt_file(fp::test::shapes_dir() / name);
}

}  // namespace

// Every shape x 3 seeds, radii [r, 10r] sized for about 4,000 disks.
class BoundaryShapes : public ::testing::TestWithParam<std::string> {};

TEST_P(BoundaryShapes, CertifiedWithNothingCulledOnThreeSeeds) {
  const fp::Domain d = shape(GetParam());
  const double r = rmin_for(d, 4000);
  for (const std::uint64_t seed : {1ULL, 2ULL, 3ULL}) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    const fp::Packing p = fill(d, fp::Method::boundary, fp::Radii::uniform(r, 10 * r), seed);
    EXPECT_GE(p.disks.size(), 1000U);
    EXPECT_LE(p.disks.size(), 20000U);
    EXPECT_FALSE(p.truncated);
    expect_certified(d, p);
  }
}

INSTANTIATE_TEST_SUITE_P(Shapes, BoundaryShapes, ::testing::ValuesIn(fp::test::shape_names()),
                         fp::test::ShapeTestName());

// The per-shape tests take their shapes from shapes/ itself; this guards against an empty or
// moved directory (no instances would run).
TEST(BoundaryShapes, CorpusCoversEveryShape) {
  EXPECT_GE(fp::test::shape_files().size(), 14U) << "shapes/ lost a shape";
}

TEST(Boundary, SameSeedSamePackingOtherSeedOther) {
  const fp::Domain d = shape("gear.wkt");
  const double r = rmin_for(d, 5000);
  const fp::Packing a = fill(d, fp::Method::boundary, fp::Radii::uniform(r, 10 * r), 7);
  const fp::Packing b = fill(d, fp::Method::boundary, fp::Radii::uniform(r, 10 * r), 7);
  const fp::Packing c = fill(d, fp::Method::boundary, fp::Radii::uniform(r, 10 * r), 8);
  ASSERT_GT(a.disks.size(), 1000U);
  EXPECT_TRUE(a.disks == b.disks);
  EXPECT_FALSE(a.disks == c.disks);
}

// The targets, on concave shapes with holes at >= 30,000 disks, rmax/rmin = 10, seed 1.
// The fills and their statistics are computed once per shape and shared by the tests below.
namespace {

struct Measured {
  std::size_t disks = 0;
  fp::PackingStats stats;
};

const Measured& measured(const std::string& name) {
  static std::map<std::string, Measured> cache;
  const auto it = cache.find(name);
  if (it != cache.end()) {
    return it->second;
  }
  const fp::Domain d = shape(name);
  const double r = rmin_for(d, 40000);
  const fp::Radii radii = fp::Radii::uniform(r, 10 * r);
  const fp::Packing p = fill(d, fp::Method::boundary, radii, 1);
  Measured m;
  m.disks = p.disks.size();
  m.stats = fp::measure(d, p.disks, {.requested = radii});
  std::printf("%s: %zu disks, interior %.4f, band %.4f, KS by area %.4f\n", name.c_str(), m.disks,
              m.stats.interior_fraction, m.stats.band_fraction, m.stats.sizes.ks_area);
  return cache.emplace(name, std::move(m)).first->second;
}

void expect_interior_target(const std::string& name) {
  const Measured& m = measured(name);
  ASSERT_GE(m.disks, 30000U);
  EXPECT_GE(m.stats.interior_fraction, 0.84);
}

void expect_band_target(const std::string& name) {
  const Measured& m = measured(name);
  ASSERT_GE(m.disks, 30000U);
  EXPECT_NEAR(m.stats.band_fraction, m.stats.interior_fraction, 0.02)
      << "band " << m.stats.band_fraction << ", interior " << m.stats.interior_fraction;
}

void expect_ks_target(const std::string& name) {
  const Measured& m = measured(name);
  ASSERT_GE(m.disks, 30000U);
  ASSERT_TRUE(m.stats.sizes.compared);
  EXPECT_LE(m.stats.sizes.ks_area, 0.02);
}

}  // namespace

// Issue #29, narrow size ranges: bidisperse 1:1.4 (the standard 2D granular model) on the plate
// with holes, about 20,000 disks. Without closing the front over blockers whose pocket no radius
// fits, the interior packed 0.746 with 20% rattlers; with it 0.80-0.81 and about 2%.
TEST(BoundaryNarrow, BidisperseOneToOnePointFourIsDenseWithFewRattlers) {
  const fp::Domain d = shape("plate_with_holes.wkt");
  const double r = std::sqrt(0.8 * d.area() / (20000 * std::numbers::pi * (1 + 1.96) / 2));
  const fp::Radii radii = fp::Radii::discrete({{r, 0.5}, {1.4 * r, 0.5}});
  const fp::Packing p = fill(d, fp::Method::boundary, radii, 1);
  const fp::PackingStats s = fp::measure(d, p.disks, {.requested = radii});
  ASSERT_GE(p.disks.size(), 15000U);
  EXPECT_GE(s.interior_fraction, 0.795);
  EXPECT_LE(static_cast<double>(s.rattlers), 0.05 * static_cast<double>(p.disks.size()));
  EXPECT_LE(s.sizes.ks_area, 0.02);
}

// The end of a run skips the radii that fit none of the last voids, at most one in a hundred
// placed; the sizes still follow the request.
TEST(BoundaryNarrow, SkipsAtMostOneRadiusInAHundredAtTheEnd) {
  const fp::Domain d = shape("gear.wkt");
  const double r = rmin_for(d, 20000);
  const fp::Radii radii = fp::Radii::uniform(r, 10 * r);
  const fp::Packing p = fill(d, fp::Method::boundary, radii, 2);
  EXPECT_GT(p.stats.skipped_radii, 0U);
  EXPECT_LE(p.stats.skipped_radii, p.disks.size() / 100);
  EXPECT_LE(fp::measure(d, p.disks, {.requested = radii, .samples = 0}).sizes.ks_area, 0.02);
}

// Issue #29, holes: after the front, the cavity pass finds the regions the fronts closed around
// with no void facing them. Uniform radii 1:10 on the square and the gear, about 60,000 disks:
// no hole takes a disk of the largest size (without the pass, one to three per 200,000 disks
// did: largest empty circle 1.06-1.12 rmax), and few take a median one.
TEST(BoundaryHoles, NoHoleTakesTheLargestDiskAtRatioTen) {
  for (const char* name : {"unit_square.wkt", "gear.wkt"}) {
    const fp::Domain d = shape(name);
    const double r = rmin_for(d, 60000);
    const fp::Radii radii = fp::Radii::uniform(r, 10 * r);
    for (const std::uint64_t seed : {1ULL, 2ULL}) {
      const fp::Packing p = fill(d, fp::Method::boundary, radii, seed);
      const fp::PackingStats s = fp::measure(d, p.disks, {.requested = radii, .samples = 0});
      ASSERT_TRUE(s.largest_empty_circle.computed);
      EXPECT_LT(s.largest_empty_circle.radius_upper, 10 * r) << name << " seed " << seed;
      ASSERT_EQ(s.holes.size(), 2U);
      EXPECT_EQ(s.holes[1].count, 0U) << name << " seed " << seed << ": holes taking rmax";
      EXPECT_LE(static_cast<double>(s.holes[0].count), 0.002 * static_cast<double>(p.disks.size()))
          << name << " seed " << seed << ": holes taking a median disk";
      EXPECT_GT(p.stats.cavities, 0U);
    }
  }
}

TEST(BoundaryDensity, PlateWithHolesInteriorAtLeast084) {
  expect_interior_target("plate_with_holes.wkt");
}
TEST(BoundaryDensity, PlateWithHolesBandWithin002OfInterior) {
  expect_band_target("plate_with_holes.wkt");
}
TEST(BoundaryDensity, PlateWithHolesKsByAreaAtMost002) {
  expect_ks_target("plate_with_holes.wkt");
}
TEST(BoundaryDensity, GearInteriorAtLeast084) {
  expect_interior_target("gear.wkt");
}
TEST(BoundaryDensity, GearBandWithin002OfInterior) {
  expect_band_target("gear.wkt");
}
TEST(BoundaryDensity, GearKsByAreaAtMost002) {
  expect_ks_target("gear.wkt");
}
TEST(BoundaryDensity, AnnulusInteriorAtLeast084) {
  expect_interior_target("annulus.wkt");
}
TEST(BoundaryDensity, AnnulusBandWithin002OfInterior) {
  expect_band_target("annulus.wkt");
}
TEST(BoundaryDensity, AnnulusKsByAreaAtMost002) {
  expect_ks_target("annulus.wkt");
}
// The comb has no hole, but 16 reflex corners and teeth 0.1 wide (about 20 rmax).
TEST(BoundaryDensity, CombInteriorAtLeast084) {
  expect_interior_target("comb.wkt");
}
TEST(BoundaryDensity, CombBandWithin002OfInterior) {
  expect_band_target("comb.wkt");
}
TEST(BoundaryDensity, CombKsByAreaAtMost002) {
  expect_ks_target("comb.wkt");
}

// An outer ring of 12,000 vertices (12,078 with its four holes) rough at the scale of the disks:
// most of its vertices are corners, half of them reflex, and a band of crevices the size of the
// small disks.
TEST(BoundaryDensity, BigPolygonInteriorAtLeast084) {
  expect_interior_target("big_polygon.wkt");
}
TEST(BoundaryDensity, BigPolygonBandWithin002OfInterior) {
  expect_band_target("big_polygon.wkt");
}
TEST(BoundaryDensity, BigPolygonKsByAreaAtMost002) {
  expect_ks_target("big_polygon.wkt");
}

// Next to the walls the boundary method is denser than the paper's forms, which fill the
// bounding box and cull what is not inside (same shape, radii and seed; about 10,000 disks).
class BoundaryBand : public ::testing::TestWithParam<std::string> {};

TEST_P(BoundaryBand, DenserNearTheWallsThanClosedAndOpen) {
  const fp::Domain d = shape(GetParam());
  const double r = rmin_for(d, 10000);
  const fp::Radii radii = fp::Radii::uniform(r, 10 * r);
  const fp::StatsOptions so{.requested = radii, .samples = 400'000};
  const double boundary = fp::measure(d, fill(d, fp::Method::boundary, radii, 1).disks, so).band_fraction;
  const double closed = fp::measure(d, fill(d, fp::Method::closed, radii, 1).disks, so).band_fraction;
  const double open = fp::measure(d, fill(d, fp::Method::open, radii, 1).disks, so).band_fraction;
  EXPECT_GT(boundary, closed);
  EXPECT_GT(boundary, open);
}

INSTANTIATE_TEST_SUITE_P(Shapes, BoundaryBand,
                         ::testing::Values("plate_with_holes.wkt", "gear.wkt", "annulus.wkt", "comb.wkt"),
                         fp::test::ShapeTestName());

// A saw of 100 teeth along the bottom of a strip: the tip of every tooth is a reflex vertex where
// the boundary turns by 77 degrees, and the front starts there with a disk touching the tooth's
// edge at the tip. The tip lies on the edge's line only up to rounding; before the touching
// position was computed as the tip itself, a quarter to a third of the tips got no disk (25-34
// of 100 on seeds 1-3; 36 with radii constant at 0.005).
TEST(Boundary, EveryReflexCornerOfASawIsTouched) {
  std::vector<fp::Point> ring;
  std::vector<fp::Point> tips;
  const int teeth = 100;
  for (int i = 0; i < teeth; ++i) {
    ring.push_back({0.1 * i, 0});
    tips.push_back({0.1 * i + 0.05, 0.04});
    ring.push_back(tips.back());
  }
  ring.push_back({0.1 * teeth, 0});
  ring.push_back({0.1 * teeth, 0.5});
  ring.push_back({0, 0.5});
  const fp::Domain d = fp::Domain::from_rings(ring);
  for (const std::uint64_t seed : {1ULL, 2ULL, 3ULL}) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    const fp::Packing p = fill(d, fp::Method::boundary, fp::Radii::uniform(0.004, 0.006), seed);
    expect_certified(d, p);
    int untouched = 0;
    for (const fp::Point& v : tips) {
      double gap = INFINITY;  // of the disk nearest to touching v
      for (const fp::Disk& k : p.disks) {
        gap = std::min(gap, std::abs(std::hypot(k.centre.x - v.x, k.centre.y - v.y) - k.radius));
      }
      untouched += gap < 1e-9 ? 0 : 1;
    }
    EXPECT_EQ(untouched, 0) << "of " << teeth << " tooth tips";
  }
}

// Hostile domains (as tests/hostile_test.cpp does for the paper's forms): each ends, certified.

// A channel narrower than 2 rmin holds no disk: NothingFitsError, naming the widest disk it holds.
TEST(BoundaryHostile, ChannelNarrowerThanTwoRminFitsNothing) {
  const fp::Domain d = fp::Domain::from_wkt("POLYGON((0 0,10 0,10 0.019,0 0.019,0 0))");
  fp::test::expect_nothing_fits([&] { return fill(d, fp::Method::boundary, fp::Radii::uniform(0.01, 0.02), 1); },
                                "none of radius above 0.0095)");
}

TEST(BoundaryHostile, RmaxLargerThanTheDomain) {
  const fp::Domain d = fp::Domain::from_wkt("POLYGON((0 0,1 0,1 1,0 1,0 0))");
  fp::test::expect_nothing_fits([&] { return fill(d, fp::Method::boundary, fp::Radii::uniform(0.6, 10), 1); },
                                "no disk fits: the smallest radius, 0.6 ");
}

// A unit square with a spike 1000 long and 1e-6 wide.
TEST(BoundaryHostile, SpikeAThousandTimesLongerThanTheDomain) {
  const fp::Domain d = fp::Domain::from_wkt("POLYGON((0 0,1 0,1 0.5,1000 0.5000005,1 0.500001,1 1,0 1,0 0))");
  const fp::Packing p = fill(d, fp::Method::boundary, fp::Radii::uniform(0.02, 0.05), 1);
  expect_certified(d, p);
  EXPECT_GT(p.disks.size(), 100U);
}

// Found by the fill fuzzer: a hole 9e-16 from a reflex corner's wall, far thinner than the
// clearance. A disk touching one of the two walls could lie wholly beyond the other, and the front
// then grew outside the domain (616 of 2,418 disks culled); now nothing is, and the L (area 0.71)
// holds 1,803 disks of radius 0.01 (0.80 of its area).
TEST(BoundaryHostile, HoleCloserThanTheClearanceToAWall) {
  const fp::Domain d = fp::Domain::from_wkt(
      "POLYGON((0 0,1 0,1 0.5,0.5 0.5,0.5 1,0 1,0 0),"
      "(0.3 0.6,0.4999999999999991 0.6,0.4999999999999991 0.8,0.3 0.8,0.3 0.6))");
  const fp::Packing p = fill(d, fp::Method::boundary, fp::Radii::constant(0.01), 1);
  expect_certified(d, p);
  EXPECT_GT(p.disks.size(), 1700U);
}

// A smooth 100,000-vertex circle of radius 10: every cell along it holds hundreds of walls, so
// the overlap test asks the wall tree for the nearest one. Every vertex is a (nearly flat) corner
// where the front starts; the band must still pack.
TEST(BoundaryHostile, SmoothHundredThousandVertexCircle) {
  std::vector<fp::Point> ring;
  const int n = 100'000;
  for (int k = 0; k < n; ++k) {
    const double t = 2 * std::numbers::pi * k / n;
    ring.push_back({10 * std::cos(t), 10 * std::sin(t)});
  }
  const fp::Domain d = fp::Domain::from_rings(ring);
  const fp::Packing p = fill(d, fp::Method::boundary, fp::Radii::uniform(0.05, 0.15), 1);
  expect_certified(d, p);
  EXPECT_GT(p.disks.size(), 7000U);
  fp::StatsOptions so;
  so.samples = 200'000;
  const fp::PackingStats s = fp::measure(d, p.disks, so);
  std::cout << "smooth circle: " << p.disks.size() << " disks, interior " << s.interior_fraction << ", band "
            << s.band_fraction << "\n";
  EXPECT_GT(s.band_fraction, s.interior_fraction - 0.02)
      << "band " << s.band_fraction << ", interior " << s.interior_fraction;
}

// The ring's inside is a disk of radius about 9.7: the closed form puts 7,414 disks in it. The saw
// is rougher than the smallest disk, so the boundary method cannot start its front on the walls.
TEST(BoundaryHostile, HundredThousandVertexRingIsFilled) {
  const fp::Domain d = fp::test::hundred_thousand_vertex_ring();
  ASSERT_EQ(d.num_vertices(), 100'000U);
  const fp::Packing p = fill(d, fp::Method::boundary, fp::Radii::uniform(0.05, 0.15), 1);
  expect_certified(d, p);
  EXPECT_GT(p.disks.size(), 5000U);
}
