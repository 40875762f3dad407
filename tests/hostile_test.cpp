// Hostile domains and parameters (issue #7). Each case ends in an exactly certified packing
// (checked again here by an independent certify() call) or in a specific error; none may hang:
// every test runs under a CTest time limit (tests/CMakeLists.txt), which fails it on a hang.
// docs/robustness.md has the table of cases and outcomes.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

#include "frontpack/frontpack.hpp"
#include "test_support.hpp"

namespace fp = frontpack;

namespace {

using fp::test::expect_certified;
using fp::test::fill;

double fraction(const fp::Domain& d, const fp::Packing& p) {
  double a = 0;
  for (const fp::Disk& k : p.disks) {
    a += std::numbers::pi * k.radius * k.radius;
  }
  return a / d.area();
}

constexpr fp::Method kForms[] = {fp::Method::closed, fp::Method::open};

}  // namespace

// A unit square with a spike 1000 long and 1e-6 wide: the box to fill is 1000 times the
// domain's area; the spike's disks are all culled.
TEST(Hostile, SpikeAThousandTimesLongerThanTheDomain) {
  const fp::Domain d = fp::Domain::from_wkt("POLYGON((0 0,1 0,1 0.5,1000 0.5000005,1 0.500001,1 1,0 1,0 0))");
  for (const fp::Method m : kForms) {
    SCOPED_TRACE(fp::to_string(m));
    const fp::Packing p = fill(d, m, fp::Radii::uniform(0.02, 0.05));
    expect_certified(d, p);
    EXPECT_GT(p.disks.size(), 100U);
    EXPECT_GT(p.certificate.culled, p.disks.size());  // the box is mostly spike
  }
}

// Zero-width parts are not polygons: clear errors, not packings.
TEST(Hostile, ZeroWidthSliversAreErrors) {
  try {
    (void)fp::Domain::from_wkt("POLYGON((0 0,1 0,1 1,0.5 1,0.5 2,0.5 1,0 1,0 0))");
    ADD_FAILURE() << "a zero-width spike was accepted";
  } catch (const fp::InvalidDomainError& e) {
    EXPECT_NE(std::string(e.what()).find("spike"), std::string::npos) << e.what();
  }
  try {
    (void)fp::Domain::from_wkt("POLYGON((0 0,1 0,2 0,0 0))");
    ADD_FAILURE() << "a zero-area ring was accepted";
  } catch (const fp::InvalidDomainError& e) {
    EXPECT_NE(std::string(e.what()).find("collinear"), std::string::npos) << e.what();
  }
}

// A square whose sides are 1,000-vertex polylines with every other vertex one ulp off the line.
TEST(Hostile, RingWithOneUlpWiggles) {
  std::vector<fp::Point> ring;
  const int n = 1000;
  const auto wiggle = [](double v, int k) { return k % 2 == 0 ? v : std::nextafter(v, v + 1); };
  for (int k = 0; k < n; ++k) ring.push_back({static_cast<double>(k) / n, wiggle(0.0, k)});
  for (int k = 0; k < n; ++k) ring.push_back({wiggle(1.0, k), static_cast<double>(k) / n});
  for (int k = 0; k < n; ++k) ring.push_back({1 - static_cast<double>(k) / n, wiggle(1.0, k)});
  for (int k = 0; k < n; ++k) ring.push_back({wiggle(0.0, k), 1 - static_cast<double>(k) / n});
  const fp::Domain d = fp::Domain::from_rings(ring);
  for (const fp::Method m : kForms) {
    SCOPED_TRACE(fp::to_string(m));
    const fp::Packing p = fill(d, m, fp::Radii::uniform(0.005, 0.02));
    expect_certified(d, p);
    EXPECT_GT(fraction(d, p), 0.6);
  }
}

// A channel narrower than 2 rmin holds no disk: an empty packing, not an error.
TEST(Hostile, ChannelNarrowerThanTwoRminIsEmpty) {
  const fp::Domain d = fp::Domain::from_wkt("POLYGON((0 0,10 0,10 0.019,0 0.019,0 0))");
  for (const fp::Method m : kForms) {
    SCOPED_TRACE(fp::to_string(m));
    const fp::Packing p = fill(d, m, fp::Radii::uniform(0.01, 0.02));
    EXPECT_TRUE(p.disks.empty());
    EXPECT_GT(p.certificate.generated, 0U);
  }
}

TEST(Hostile, HoleTouchingTheOuterRingAtAPoint) {
  const fp::Domain d = fp::Domain::from_wkt_file(fp::test::shapes_dir() / "hole_touching.wkt");
  for (const fp::Method m : kForms) {
    SCOPED_TRACE(fp::to_string(m));
    const fp::Packing p = fill(d, m, fp::Radii::uniform(0.01, 0.05));
    expect_certified(d, p);
    EXPECT_GT(fraction(d, p), 0.7);
  }
}

// A 100,000-vertex star-shaped ring (radius 10 with radial noise).
TEST(Hostile, HundredThousandVertexRing) {
  const fp::Domain d = fp::test::hundred_thousand_vertex_ring();
  ASSERT_EQ(d.num_vertices(), 100'000U);
  const fp::Packing p = fill(d, fp::Method::closed, fp::Radii::uniform(0.05, 0.15));
  expect_certified(d, p);
  EXPECT_GT(fraction(d, p), 0.7);
}

// The same square at 1e-9 scale and at a 1e9 offset packs as densely as at unit scale: the
// clearance is relative to the coordinates.
TEST(Hostile, NanoScaleAndGigaOffsetPackLikeUnitScale) {
  const fp::Domain unit = fp::Domain::from_wkt("POLYGON((0 0,1 0,1 1,0 1,0 0))");
  const fp::Domain nano = fp::Domain::from_wkt("POLYGON((0 0,1e-9 0,1e-9 1e-9,0 1e-9,0 0))");
  const fp::Domain giga =
      fp::Domain::from_wkt("POLYGON((1e9 1e9,1000000001 1e9,1000000001 1000000001,1e9 1000000001,1e9 1e9))");
  for (const fp::Method m : kForms) {
    SCOPED_TRACE(fp::to_string(m));
    const double base = fraction(unit, fill(unit, m, fp::Radii::uniform(0.005, 0.02)));
    const fp::Packing pn = fill(nano, m, fp::Radii::uniform(0.005e-9, 0.02e-9));
    expect_certified(nano, pn);
    EXPECT_NEAR(fraction(nano, pn), base, 0.02);
    const fp::Packing pg = fill(giga, m, fp::Radii::uniform(0.005, 0.02));
    expect_certified(giga, pg);
    EXPECT_NEAR(fraction(giga, pg), base, 0.02);
  }
}

TEST(Hostile, RmaxLargerThanTheDomain) {
  const fp::Domain d = fp::Domain::from_wkt("POLYGON((0 0,1 0,1 1,0 1,0 0))");
  for (const fp::Method m : kForms) {
    SCOPED_TRACE(fp::to_string(m));
    const fp::Packing p = fill(d, m, fp::Radii::uniform(0.6, 10));
    expect_certified(d, p);
    EXPECT_LE(p.disks.size(), 1U);
  }
}

TEST(Hostile, RadiusRatioOfAThousand) {
  const fp::Domain d = fp::Domain::from_wkt("POLYGON((0 0,1 0,1 1,0 1,0 0))");
  for (const fp::Method m : kForms) {
    SCOPED_TRACE(fp::to_string(m));
    const fp::Packing p = fill(d, m, fp::Radii::uniform(1e-4, 0.1));
    expect_certified(d, p);
    EXPECT_GT(p.disks.size(), 30U);
  }
}

// A request for about 1e16 disks is refused before any work, with the estimate in the message.
TEST(Hostile, AstronomicalRequestIsRefusedWithTheEstimate) {
  const fp::Domain d = fp::Domain::from_wkt("POLYGON((0 0,1 0,1 1,0 1,0 0))");
  try {
    (void)fill(d, fp::Method::closed, fp::Radii::constant(1e-8));
    ADD_FAILURE() << "not refused";
  } catch (const fp::LimitError& e) {
    EXPECT_GT(e.estimate(), 1e15);
    EXPECT_NE(std::string(e.what()).find("would generate about"), std::string::npos) << e.what();
  }
  // An estimate beyond any integer (1e600 disks) saturates instead of overflowing.
  try {
    (void)fill(d, fp::Method::closed, fp::Radii::constant(1e-300));
    ADD_FAILURE() << "not refused";
  } catch (const fp::LimitError& e) {
    EXPECT_EQ(e.estimate(), std::numeric_limits<std::size_t>::max());
  }
}

// A request within max_disks but beyond the memory limit is refused up front too, naming both.
TEST(Hostile, RequestBeyondTheMemoryLimitIsRefused) {
  const fp::Domain d = fp::Domain::from_wkt("POLYGON((0 0,1 0,1 1,0 1,0 0))");
  fp::FillOptions o;
  o.radii = fp::Radii::constant(1e-3);  // about 270,000 disks
  o.memory_limit = 1'000'000;           // 1 MB
  try {
    (void)fp::fill(d, o);
    ADD_FAILURE() << "not refused";
  } catch (const fp::LimitError& e) {
    EXPECT_NE(std::string(e.what()).find("bytes of memory"), std::string::npos) << e.what();
  }
  o.memory_limit = 100'000'000;  // 100 MB: enough
  EXPECT_NO_THROW((void)fp::fill(d, o));
}
