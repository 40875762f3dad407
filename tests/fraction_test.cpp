// Fills with a target (FillOptions::fraction, count, height): the fraction reached within 0.002,
// the requested radii kept (KS by area), the density even (cell coverage), the certificate clean,
// determinism; a count of disks exactly, in a compact region; a level, decided exactly against
// the unclipped domain.
#include <gtest/gtest.h>

#include <CGAL/Gmpq.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <numbers>
#include <string>
#include <vector>

#include "frontpack/frontpack.hpp"
#include "test_support.hpp"

namespace fp = frontpack;

namespace {

fp::Domain plate() {
  return fp::Domain::from_wkt_file(fp::test::shapes_dir() / "plate_with_holes.wkt");
}

using fp::test::fraction_of;

void expect_certified(const fp::Domain& domain, const std::vector<fp::Disk>& disks) {
  const fp::CertifyReport r = fp::certify(domain, disks);
  EXPECT_TRUE(r.outside.empty()) << r.outside.size() << " disks outside";
  EXPECT_TRUE(r.overlapping.empty()) << r.overlapping.size() << " overlapping pairs";
}

struct FractionCase {
  const char* radius;
  double fraction;
};

class TargetFraction : public ::testing::TestWithParam<FractionCase> {};

// Uniform radii ratio 10 (about 12k disks dense) and bidisperse 1:1.4 (about 17k dense).
TEST_P(TargetFraction, ReachedWithTheRequestedRadiiAndEvenDensity) {
  const FractionCase c = GetParam();
  const fp::Domain domain = plate();
  fp::FillOptions o;
  o.radii = fp::parse_radii(c.radius);
  o.seed = 5;
  o.fraction = c.fraction;
  const fp::Packing p = fp::fill(domain, o);
  ASSERT_TRUE(p.target.has_value());
  const double phi = fraction_of(domain, p.disks);
  EXPECT_NEAR(phi, c.fraction, 0.002);
  EXPECT_EQ(p.target->fraction_achieved, phi);
  EXPECT_GE(p.target->scale, 1.0);
  expect_certified(domain, p.disks);

  // The radii are the drawn ones; the interior (sampled) is at F, not denser or looser than the
  // band.
  fp::StatsOptions so;
  so.requested = o.radii;
  so.samples = 250'000;
  so.contacts = false;
  so.empty_circle = false;
  so.holes = false;
  so.coverage_profile = false;
  const fp::PackingStats s = fp::measure(domain, p.disks, so);
  EXPECT_EQ(s.packing_fraction, phi);
  EXPECT_LE(s.sizes.ks_area, 0.02) << s.sizes.requested;
  EXPECT_NEAR(s.interior_fraction, c.fraction, 4 * s.interior_error + 0.005);
  ASSERT_GT(s.cell_coverage.cells, 50U);

  // The density is as even as the dense fill's: its sparsest cells (1st percentile of the cells)
  // as far below the median, relatively, on the same cells (8 times the target packing's rmax: its
  // disks are the larger). The 1st percentile of the plate's 100 cells is their minimum, which
  // scatters by 0.03 from seed to seed in both fills, so the means over four seeds are compared
  // (seed 5's target fill is the one measured above; the cells do not depend on the sample
  // points).
  so.samples = 0;
  so.requested.reset();
  so.cell_side = s.cell_coverage.cell_side;
  const auto evenness = [](const fp::PackingStats& m) { return m.cell_coverage.p1 / m.cell_coverage.p50; };
  double even = evenness(s);
  double even_dense = 0;
  for (std::uint64_t seed = 5; seed < 9; ++seed) {
    o.seed = seed;
    if (seed > 5) {
      o.fraction = c.fraction;
      even += evenness(fp::measure(domain, fp::fill(domain, o).disks, so));
    }
    o.fraction.reset();
    even_dense += evenness(fp::measure(domain, fp::fill(domain, o).disks, so));
  }
  even /= 4;
  even_dense /= 4;
  EXPECT_GE(even, even_dense - 0.04) << "means of p1 / median over seeds 5-8: " << even << ", dense " << even_dense;
}

INSTANTIATE_TEST_SUITE_P(PlateWithHoles, TargetFraction,
                         ::testing::Values(FractionCase{"uniform:0.002,0.02", 0.60},
                                           FractionCase{"uniform:0.002,0.02", 0.70},
                                           FractionCase{"uniform:0.002,0.02", 0.80},
                                           FractionCase{"discrete:0.008:0.5,0.0112:0.5", 0.60},
                                           FractionCase{"discrete:0.008:0.5,0.0112:0.5", 0.70},
                                           FractionCase{"discrete:0.008:0.5,0.0112:0.5", 0.78}));

TEST(TargetFractionErrors, AboveTheDenseFractionNamesWhatIsReached) {
  fp::FillOptions o;
  o.radii = fp::parse_radii("discrete:0.008:0.5,0.0112:0.5");
  o.fraction = 0.86;
  try {
    (void)fp::fill(plate(), o);
    FAIL() << "expected OptionError";
  } catch (const fp::OptionError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("fraction 0.86: the boundary method reaches 0.80"), std::string::npos) << m;
    EXPECT_NE(m.find(o.radii.describe()), std::string::npos) << m;
  }
  for (const double bad : {0.0, 1.0, -0.5, std::nan("")}) {
    o.fraction = bad;
    EXPECT_THROW((void)fp::fill(plate(), o), fp::OptionError) << bad;
  }
}

TEST(TargetFractionDeterminism, SameSeedSameBits) {
  fp::FillOptions o;
  o.radii = fp::parse_radii("uniform:0.004,0.04");
  o.seed = 11;
  o.fraction = 0.65;
  const fp::Packing a = fp::fill(plate(), o);
  const fp::Packing b = fp::fill(plate(), o);
  ASSERT_EQ(a.disks.size(), b.disks.size());
  EXPECT_EQ(0, std::memcmp(a.disks.data(), b.disks.data(), a.disks.size() * sizeof(fp::Disk)));
  o.seed = 12;
  const fp::Packing c = fp::fill(plate(), o);
  EXPECT_FALSE(c.disks.size() == a.disks.size() &&
               std::memcmp(a.disks.data(), c.disks.data(), a.disks.size() * sizeof(fp::Disk)) == 0);
}

// The open form fills from the bottom: the first N disks are the bottom layers, so their top is
// about what N disks at the dense fraction cover of the width.
TEST(FillToCount, OpenFormGivesExactlyNFromTheBottom) {
  const fp::Domain domain = fp::Domain::from_wkt("POLYGON((0 0,2 0,2 3,0 3,0 0))");
  fp::FillOptions o;
  o.method = fp::Method::open;
  o.radii = fp::parse_radii("uniform:0.01,0.02");
  o.count = 3000;
  const fp::Packing p = fp::fill(domain, o);
  ASSERT_EQ(p.disks.size(), 3000U);
  EXPECT_FALSE(p.truncated);
  expect_certified(domain, p.disks);
  double top = 0;
  double area = 0;
  for (const fp::Disk& d : p.disks) {
    top = std::max(top, d.centre.y + d.radius);
    area += std::numbers::pi * d.radius * d.radius;
  }
  // The disks' area at the dense fill's fraction over the width 2, plus a layer of rmax: the
  // lowest level that holds them.
  o.count = 0;
  const fp::Packing whole = fp::fill(domain, o);
  double whole_area = 0;
  for (const fp::Disk& d : whole.disks) {
    whole_area += std::numbers::pi * d.radius * d.radius;
  }
  const double dense = whole_area / domain.area();
  EXPECT_LE(top, area / dense / 2 + 2 * 0.02) << "area " << area << ", dense " << dense;
  EXPECT_GT(whole.disks.size(), 3000U * 2);
}

TEST(FillToCount, ClosedFormGrowsABlobFromTheStart) {
  const fp::Domain domain = fp::Domain::from_wkt("POLYGON((0 0,4 0,4 4,0 4,0 0))");
  fp::FillOptions o;
  o.method = fp::Method::closed;
  o.radii = fp::parse_radii("uniform:0.01,0.02");
  o.start = fp::Point{1.5, 2.5};
  o.count = 2000;
  const fp::Packing p = fp::fill(domain, o);
  ASSERT_EQ(p.disks.size(), 2000U);
  expect_certified(domain, p.disks);
  double area = 0;
  double reach = 0;
  for (const fp::Disk& d : p.disks) {
    area += std::numbers::pi * d.radius * d.radius;
    reach = std::max(reach, std::hypot(d.centre.x - 1.5, d.centre.y - 2.5) + d.radius);
  }
  // A round blob at a fraction of at least 0.7 has a radius of sqrt(area / 0.7 / pi); allow a layer.
  EXPECT_LE(reach, std::sqrt(area / 0.7 / std::numbers::pi) + 2 * 0.02);
}

// A count the domain cannot hold is reported (TargetReport::count_achieved), and a count run is
// estimated by its count, not by the domain: a count of 1 within max_disks = 1 runs.
TEST(FillToCount, AShortfallIsReportedAndTheEstimateIsTheCount) {
  const fp::Domain domain = fp::Domain::from_wkt("POLYGON((0 0,1 0,1 1,0 1,0 0))");
  for (const fp::Method method : {fp::Method::open, fp::Method::closed}) {
    fp::FillOptions o;
    o.method = method;
    o.radii = fp::parse_radii("uniform:0.01,0.05");
    o.count = 5000;
    const fp::Packing p = fp::fill(domain, o);
    ASSERT_TRUE(p.target.has_value());
    EXPECT_LT(p.disks.size(), 5000U) << fp::to_string(method);
    EXPECT_EQ(p.target->count_requested, 5000U);
    EXPECT_EQ(p.target->count_achieved, p.disks.size()) << fp::to_string(method);
    o.count = 1;
    o.max_disks = 1;
    const fp::Packing one = fp::fill(domain, o);
    EXPECT_EQ(one.disks.size(), 1U) << fp::to_string(method);
    EXPECT_EQ(one.target->count_achieved, 1U);
    expect_certified(domain, one.disks);
  }
}

TEST(FillToCount, BoundaryMethodRefusesWithTheFormsThatTakeOne) {
  fp::FillOptions o;
  o.count = 100;
  try {
    (void)fp::fill(plate(), o);
    FAIL() << "expected OptionError";
  } catch (const fp::OptionError& e) {
    EXPECT_NE(std::string(e.what()).find("use --method open"), std::string::npos) << e.what();
  }
}

// An arch (a U upside down) cut below its crossbar splits into its two legs; every disk lies in
// the unclipped domain and below the level, decided exactly; the part below is filled as densely
// as a fill of the whole.
TEST(FillToLevel, ArchSplitsAndEveryDiskIsBelowTheLevelExactly) {
  const fp::Domain domain = fp::Domain::from_wkt("POLYGON((0 0,1 0,1 1.5,2 1.5,2 0,3 0,3.1 2,0 2,0 0))");
  const double level = 1.2345678901;
  fp::FillOptions o;
  o.radii = fp::parse_radii("uniform:0.005,0.02");
  o.height = level;
  const fp::Packing p = fp::fill(domain, o);
  ASSERT_TRUE(p.target.has_value());
  EXPECT_EQ(p.target->outside_original, 0U);
  ASSERT_GT(p.disks.size(), 1000U);
  expect_certified(domain, p.disks);
  for (const fp::Disk& d : p.disks) {
    ASSERT_LE(CGAL::Gmpq(d.centre.y) + CGAL::Gmpq(d.radius), CGAL::Gmpq(level)) << d.centre.y << " " << d.radius;
  }
  o.height.reset();
  const fp::Packing whole = fp::fill(domain, o);
  const double whole_fraction = fraction_of(domain, whole.disks);
  EXPECT_NEAR(p.target->fraction_achieved, whole_fraction, 0.02);
  // The legs: [0, 1] and [2, 3 + y / 20] below the level.
  EXPECT_NEAR(p.target->area_filled, 2 * level + 0.025 * level * level, 1e-9);
  EXPECT_TRUE(std::any_of(p.disks.begin(), p.disks.end(), [](const fp::Disk& d) { return d.centre.x < 1; }));
  EXPECT_TRUE(std::any_of(p.disks.begin(), p.disks.end(), [](const fp::Disk& d) { return d.centre.x > 2; }));
}

TEST(FillToLevel, WithAFractionAndTheEdges) {
  const fp::Domain domain = plate();
  fp::FillOptions o;
  o.radii = fp::parse_radii("uniform:0.004,0.04");
  o.height = 1.0;
  o.fraction = 0.7;
  const fp::Packing p = fp::fill(domain, o);
  ASSERT_TRUE(p.target.has_value());
  EXPECT_NEAR(p.target->fraction_achieved, 0.7, 0.002);
  expect_certified(domain, p.disks);
  for (const fp::Disk& d : p.disks) {
    ASSERT_LE(CGAL::Gmpq(d.centre.y) + CGAL::Gmpq(d.radius), CGAL::Gmpq(1.0));
  }
  o.fraction.reset();
  o.height = 0.0;
  EXPECT_THROW((void)fp::fill(domain, o), fp::OptionError);
  o.height = 5.0;  // above the top: the whole domain
  o.radii = fp::parse_radii("uniform:0.02,0.04");
  const fp::Packing all = fp::fill(domain, o);
  o.height.reset();
  EXPECT_EQ(all.disks, fp::fill(domain, o).disks);
}

}  // namespace
