// The jam stage (FillOptions::jam): denser than the front alone where the front is below jamming,
// every disk still inside and apart (certified exactly by certify(), independently of the fill's
// own certification), only the requested radii, never sparser at a wide size range,
// periodic cells and domains with holes, the same bits for a seed, and the options it refuses.
#include <gtest/gtest.h>

#include <algorithm>
#include <numbers>
#include <string>
#include <vector>

#include "frontpack/frontpack.hpp"
#include "test_support.hpp"

namespace fp = frontpack;

namespace {

constexpr double kSmall = 0.014;
constexpr double kLarge = 0.0196;

fp::FillOptions bidisperse(std::uint64_t seed, bool jam) {
  fp::FillOptions o;
  o.radii = fp::Radii::discrete({{kSmall, 0.5}, {kLarge, 0.5}});
  o.seed = seed;
  o.jam = jam;
  return o;
}

fp::Domain unit_square() {
  return fp::Domain::from_wkt("POLYGON((0 0,1 0,1 1,0 1,0 0))");
}

using fp::test::expect_certified;
using fp::test::fraction_of;

void expect_requested_radii(const std::vector<fp::Disk>& disks) {
  for (const fp::Disk& d : disks) {
    ASSERT_TRUE(d.radius == kSmall || d.radius == kLarge) << d.radius;
  }
}

}  // namespace

TEST(Jam, DenserThanTheFrontAndCertified) {
  const fp::Domain domain = unit_square();
  const fp::Packing plain = fp::fill(domain, bidisperse(1, false));
  const fp::Packing jammed = fp::fill(domain, bidisperse(1, true));
  expect_certified(domain, jammed);
  expect_requested_radii(jammed.disks);
  EXPECT_EQ(jammed.certificate.culled, 0u);
  EXPECT_EQ(jammed.certificate.dropped, 0u);
  EXPECT_EQ(jammed.certificate.generated, plain.disks.size() + jammed.stats.jam_inserted);
  EXPECT_GT(jammed.stats.jam_inserted, 0u);
  EXPECT_GE(jammed.stats.jam_rounds, 2u);
  EXPECT_EQ(jammed.disks.size(), plain.disks.size() + jammed.stats.jam_inserted);
  // The front alone gives about 0.80 here (walls are a large part of a small square); jammed,
  // 0.82 and more.
  EXPECT_GT(fraction_of(domain, jammed.disks), fraction_of(domain, plain.disks) + 0.01);
}

TEST(Jam, WideRangeNeverLoses) {
  // At rmax / rmin = 10 the front is already denser than a jammed packing of the same radii
  // (docs/jam.md): most rounds cannot be taken, and those undone leave the packing as it was.
  const fp::Domain domain = unit_square();
  fp::FillOptions o = bidisperse(2, false);
  o.radii = fp::Radii::uniform(0.003, 0.03);
  const fp::Packing plain = fp::fill(domain, o);
  o.jam = true;
  const fp::Packing jammed = fp::fill(domain, o);
  expect_certified(domain, jammed);
  for (const fp::Disk& d : jammed.disks) {
    ASSERT_TRUE(d.radius >= 0.003 && d.radius <= 0.03) << d.radius;
  }
  EXPECT_GE(jammed.stats.jam_rounds, 1u);
  EXPECT_GE(fraction_of(domain, jammed.disks), fraction_of(domain, plain.disks));
}

TEST(Jam, SameSeedSameBits) {
  const fp::Domain domain = unit_square();
  const fp::Packing a = fp::fill(domain, bidisperse(3, true));
  const fp::Packing b = fp::fill(domain, bidisperse(3, true));
  ASSERT_EQ(a.disks.size(), b.disks.size());
  EXPECT_TRUE(a.disks == b.disks);
  EXPECT_EQ(a.stats.jam_steps, b.stats.jam_steps);
}

TEST(Jam, DomainWithHolesEveryMethod) {
  const fp::Domain domain = fp::Domain::from_wkt_file(fp::test::shapes_dir() / "plate_with_holes.wkt");
  for (const fp::Method m : {fp::Method::boundary, fp::Method::closed, fp::Method::open}) {
    fp::FillOptions o = bidisperse(4, true);
    o.method = m;
    o.radii = fp::Radii::discrete({{0.04, 0.5}, {0.056, 0.5}});
    const fp::Packing p = fp::fill(domain, o);
    SCOPED_TRACE(fp::to_string(m));
    expect_certified(domain, p);
    EXPECT_GT(p.stats.jam_inserted, 0u);
  }
}

TEST(Jam, PeriodicCells) {
  for (const fp::Periodicity axes : {fp::Periodicity::xy, fp::Periodicity::x}) {
    const fp::Domain domain = fp::Domain::periodic(fp::Box{0, 0, 0.6, 0.6}, axes);
    const fp::Packing plain = fp::fill(domain, bidisperse(5, false));
    const fp::Packing jammed = fp::fill(domain, bidisperse(5, true));
    expect_certified(domain, jammed);
    expect_requested_radii(jammed.disks);
    for (const fp::Disk& d : jammed.disks) {
      ASSERT_TRUE(d.centre.x >= 0 && d.centre.x < 0.6) << d.centre.x;
      if (axes == fp::Periodicity::xy) {
        ASSERT_TRUE(d.centre.y >= 0 && d.centre.y < 0.6) << d.centre.y;
      }
    }
    EXPECT_GT(fraction_of(domain, jammed.disks), fraction_of(domain, plain.disks) + 0.01);
  }
}

TEST(Jam, EndsWhenItsBoxIsMostlyOutside) {
  // A unit square and a speck 1,000 away: the domain covers a millionth of its box, so nearly
  // every round draws no point of it. Such a round counts as failed, so k shrinks and the stage
  // ends (counted as kept, the rounds went on until one that drew a point failed).
  const fp::Domain domain = fp::Domain::from_wkt(
      "MULTIPOLYGON(((0 0,1 0,1 1,0 1,0 0)),((1000 1000,1000.1 1000,1000.1 1000.1,1000 1000.1,1000 1000)))");
  const fp::Packing p = fp::fill(domain, bidisperse(6, true));
  expect_certified(domain, p);
  EXPECT_GE(p.stats.jam_rounds, 1u);
  EXPECT_LT(p.stats.jam_rounds, 20u);
}

TEST(Jam, RefusesATargetFractionOrACount) {
  const fp::Domain domain = unit_square();
  fp::FillOptions o = bidisperse(1, true);
  o.fraction = 0.6;
  EXPECT_THROW(
      {
        try {
          (void)fp::fill(domain, o);
        } catch (const fp::OptionError& e) {
          EXPECT_NE(std::string(e.what()).find("jam"), std::string::npos) << e.what();
          throw;
        }
      },
      fp::OptionError);
  o.fraction.reset();
  o.method = fp::Method::open;
  o.count = 100;
  EXPECT_THROW((void)fp::fill(domain, o), fp::OptionError);
}

// The progress reports in order: the front (Phase::generate, ending at 1), its certification
// (0 then 1), the stage (Phase::jam, fractions in [0, 1] that never fall), then the stage's own
// certification (0 then 1, with every disk of the result).
TEST(Jam, ProgressReportsEachPhaseInOrder) {
  const fp::Domain domain = unit_square();
  fp::Generator g(domain, bidisperse(1, true));
  std::vector<fp::Progress> reports;
  g.on_progress([&](const fp::Progress& p) {
    reports.push_back(p);
    return true;
  });
  const fp::Packing p = g.run();
  ASSERT_GT(p.stats.jam_inserted, 0u);
  std::vector<fp::Phase> phases;
  for (const fp::Progress& r : reports) {
    if (phases.empty() || phases.back() != r.phase) {
      phases.push_back(r.phase);
    }
  }
  const std::vector<fp::Phase> expected{fp::Phase::generate, fp::Phase::certify, fp::Phase::jam, fp::Phase::certify};
  ASSERT_EQ(phases, expected);
  const auto first_jam =
      std::find_if(reports.begin(), reports.end(), [](const fp::Progress& r) { return r.phase == fp::Phase::jam; });
  ASSERT_GE(first_jam - reports.begin(), 3);
  EXPECT_EQ((first_jam - 2)->phase, fp::Phase::certify);
  EXPECT_EQ((first_jam - 2)->fraction, 0.0);
  EXPECT_EQ((first_jam - 1)->phase, fp::Phase::certify);
  EXPECT_EQ((first_jam - 1)->fraction, 1.0);
  double last = 0;
  for (auto r = first_jam; r != reports.end() && r->phase == fp::Phase::jam; ++r) {
    EXPECT_GE(r->fraction, last);
    EXPECT_LE(r->fraction, 1.0);
    last = r->fraction;
  }
  ASSERT_GE(reports.size(), 2u);
  const fp::Progress& start = reports[reports.size() - 2];
  const fp::Progress& end = reports.back();
  EXPECT_EQ(start.phase, fp::Phase::certify);
  EXPECT_EQ(start.fraction, 0.0);
  EXPECT_EQ(start.disks, p.certificate.generated);
  EXPECT_EQ(end.phase, fp::Phase::certify);
  EXPECT_EQ(end.fraction, 1.0);
  EXPECT_EQ(end.disks, p.certificate.generated);
}
