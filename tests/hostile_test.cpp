// Hostile domains and parameters (issue #7). Each case ends in an exactly certified packing
// (checked again here by an independent certify() call) or in a specific error; none may hang:
// every test runs under a CTest time limit (tests/CMakeLists.txt), which fails it on a hang.
// docs/robustness.md has the table of cases and outcomes.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <numbers>
#include <string>
#include <utility>
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

// A channel narrower than 2 rmin holds no disk: NothingFitsError, naming the widest disk it holds.
TEST(Hostile, ChannelNarrowerThanTwoRminFitsNothing) {
  const fp::Domain d = fp::Domain::from_wkt("POLYGON((0 0,10 0,10 0.019,0 0.019,0 0))");
  for (const fp::Method m : kForms) {
    SCOPED_TRACE(fp::to_string(m));
    fp::test::expect_nothing_fits([&] { return fill(d, m, fp::Radii::uniform(0.01, 0.02)); },
                                  "none of radius above 0.0095)");
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

// Every radius above the largest disk the unit square holds (0.5): no disk fits, and the error
// says so, with the radius and the bound, whichever method.
TEST(Hostile, RmaxLargerThanTheDomain) {
  const fp::Domain d = fp::Domain::from_wkt("POLYGON((0 0,1 0,1 1,0 1,0 0))");
  for (const fp::Method m : kForms) {
    SCOPED_TRACE(fp::to_string(m));
    try {
      (void)fill(d, m, fp::Radii::uniform(0.6, 10));
      ADD_FAILURE() << "a disk of radius >= 0.6 was placed in the unit square";
    } catch (const fp::NothingFitsError& e) {
      EXPECT_NE(std::string(e.what()).find("0.6 (uniform: radius in [0.6, 10]), is larger than any disk this domain "
                                           "holds (none of radius above 0.5)"),
                std::string::npos)
          << e.what();
    }
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
    EXPECT_NE(std::string(e.what()).find("would make about"), std::string::npos) << e.what();
  }
  // An estimate beyond any integer (1e600 disks) saturates instead of overflowing.
  try {
    (void)fill(d, fp::Method::closed, fp::Radii::constant(1e-300));
    ADD_FAILURE() << "not refused";
  } catch (const fp::LimitError& e) {
    EXPECT_EQ(e.estimate(), std::numeric_limits<std::size_t>::max());
  }
}

// A domain whose area and E[r^2] underflow (1e-400 and 1e-402: the disk-count estimate was
// 0 / 0, a NaN that passed both limit checks and reached a reserve()): an exactly certified
// packing with every method, disks and all, as at unit scale.
TEST(Hostile, DomainWhoseAreaUnderflowsIsPacked) {
  struct Case {
    const char* wkt;
    fp::Radii radii;
  };
  const Case cases[] = {
      {"POLYGON((0 0,1e-200 0,1e-200 1e-200,0 1e-200,0 0))", fp::Radii::constant(1e-201)},
      {"POLYGON((0 0,1e-300 0,1e-300 1e-300,0 1e-300,0 0))", fp::Radii::constant(1e-301)},
      {"POLYGON((0 0,1e-300 0,1e-300 1e-300,0 1e-300,0 0))", fp::Radii::uniform(1e-302, 1e-301)},
  };
  for (const Case& c : cases) {
    const fp::Domain d = fp::Domain::from_wkt(c.wkt);
    for (const fp::Method m : {fp::Method::closed, fp::Method::open, fp::Method::boundary}) {
      SCOPED_TRACE(std::string(c.wkt) + " " + c.radii.describe() + " " + fp::to_string(m));
      const fp::Packing p = fill(d, m, c.radii);
      expect_certified(d, p);
      EXPECT_GE(p.disks.size(), 15U);  // 17 to 58 at unit scale (0.53 to 0.73 of the area)
      const fp::PackingStats s = fp::measure(d, p.disks);
      EXPECT_GT(s.packing_fraction, 0.5);  // measured at unit scale too (the areas underflow)
      EXPECT_LT(s.packing_fraction, 0.91);
    }
  }
}

// Where even a clearance of a few ulps underflows (every coordinate subnormal), the request is
// refused, saying why.
TEST(Hostile, SubnormalDomainIsRefusedSayingWhy) {
  const fp::Domain d = fp::Domain::from_wkt("POLYGON((0 0,4e-320 0,4e-320 4e-320,0 4e-320,0 0))");
  for (const fp::Method m : {fp::Method::closed, fp::Method::open, fp::Method::boundary}) {
    SCOPED_TRACE(fp::to_string(m));
    try {
      (void)fill(d, m, fp::Radii::constant(1e-321));
      ADD_FAILURE() << "not refused";
    } catch (const fp::OptionError& e) {
      EXPECT_NE(std::string(e.what()).find("too small"), std::string::npos) << e.what();
    }
  }
}

// Radii up to the largest double (5 rmax and the grid's margin of 4 rmax overflow; the boundary
// method sized its grid from that and ran out of memory): no disk fits the unit square, and every
// method says so (NothingFitsError: the radii, or the clearance such radii need).
TEST(Hostile, RadiiNearTheLargestDoubleFitNothing) {
  const fp::Domain d = fp::Domain::from_wkt("POLYGON((0 0,1 0,1 1,0 1,0 0))");
  const std::pair<fp::Radii, const char*> radii[] = {
      {fp::Radii::constant(3e307), "no disk fits: the smallest radius, 3e+307 "},
      {fp::Radii::constant(std::numeric_limits<double>::max()), "no disk fits: the smallest radius, 1.79"},
      {fp::Radii::uniform(0.01, 1e308), "at the scale of this fill (largest |coordinate| + 5 rmax = 1.8e+308)"},
      {fp::Radii::uniform(1e200, 1e300), "no disk fits: the smallest radius, 1e+200 "}};
  for (const auto& [spec, why] : radii) {
    for (const fp::Method m : {fp::Method::closed, fp::Method::open, fp::Method::boundary}) {
      SCOPED_TRACE(spec.describe() + " " + fp::to_string(m));
      fp::test::expect_nothing_fits([&d, m, &r = spec] { return fill(d, m, r); }, why);
    }
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
    EXPECT_NE(std::string(e.what()).find("raise memory_limit (--memory-limit)"), std::string::npos) << e.what();
  }
  o.memory_limit = 100'000'000;  // 100 MB: enough
  EXPECT_NO_THROW((void)fp::fill(d, o));
}

// The memory limit holds during the run, not only for the estimate, which assumes a dense packing
// of the box: the closed and open forms fill a sliver 1e-5 high with disks of about half its
// height 1.7 to 2.5 times over (the disks that overhang the box are culled), and their grid has
// more cells than disks; the boundary method lists the walls near each cell of its grid. Given a
// limit that the estimate (about 133,600 disks, 8.6 MB) passes, every method stops with a
// LimitError naming the option, before the grid or the disks exceed it. (Peak RSS against the
// limit: docs/robustness.md, "Memory".)
TEST(Hostile, MemoryLimitHoldsDuringTheRun) {
  const fp::Domain d = fp::Domain::from_wkt("POLYGON((0 0,1 0,1 1e-5,0 0))");
  struct Case {
    fp::Method method;
    std::size_t limit;
    const char* what;
  };
  const Case cases[] = {
      {fp::Method::open, 9'000'000, "the grid over a polygon's box"},
      {fp::Method::open, 16'000'000, "it had generated"},
      {fp::Method::closed, 16'000'000, "it had generated"},
      {fp::Method::boundary, 9'000'000, "the grid over the polygon's box"},
      {fp::Method::boundary, 30'000'000, "the domain's edges come within reach of"},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(std::string(fp::to_string(c.method)) + " " + std::to_string(c.limit));
    fp::FillOptions o;
    o.method = c.method;
    o.radii = fp::Radii::constant(4.5e-6);
    o.memory_limit = c.limit;
    try {
      (void)fp::fill(d, o);
      ADD_FAILURE() << "not stopped";
    } catch (const fp::LimitError& e) {
      const std::string what = e.what();
      EXPECT_NE(what.find("memory limit of " + std::to_string(c.limit) + " bytes: " + c.what), std::string::npos)
          << what;
      EXPECT_NE(what.find("raise memory_limit (--memory-limit)"), std::string::npos) << what;
    }
  }
  for (const fp::Method m : {fp::Method::closed, fp::Method::open, fp::Method::boundary}) {
    SCOPED_TRACE(fp::to_string(m));
    fp::FillOptions o;
    o.method = m;
    o.radii = fp::Radii::constant(4.5e-6);
    o.memory_limit = 64'000'000;  // enough: 24 to 43 MB
    const fp::Packing p = fp::fill(d, o);
    expect_certified(d, p);
    EXPECT_GT(p.disks.size(), 5'000U);  // 5,556 kept by the closed form, about 11,100 by the others
  }
}

// Rings collapsed into a few ulps: 131,072 vertices on an 8 x 8 grid of points one ulp apart
// near (1, 1), joined in a random order. Every pair of edge boxes meets, so a validator that
// classifies every box pair needs billions of steps (16,384 vertices took 6.6-8.7 s; this size would
// take minutes and fail the CTest time limit). The refusal must name the problem with the
// smallest pair of edges, the one a full enumeration reports: found here by an independent
// search on the integer grid (exact there), edge by edge.
namespace {

struct Grid {
  std::int64_t x, y;
};

std::int64_t orient(Grid a, Grid b, Grid c) {
  const std::int64_t o = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
  return (o > 0) - (o < 0);
}
bool on_segment(Grid p, Grid a, Grid b) {
  return std::min(a.x, b.x) <= p.x && p.x <= std::max(a.x, b.x) && std::min(a.y, b.y) <= p.y &&
         p.y <= std::max(a.y, b.y);
}
bool segments_meet(Grid a, Grid b, Grid c, Grid d) {
  const std::int64_t o1 = orient(a, b, c);
  const std::int64_t o2 = orient(a, b, d);
  const std::int64_t o3 = orient(c, d, a);
  const std::int64_t o4 = orient(c, d, b);
  if (o1 * o2 < 0 && o3 * o4 < 0) {
    return true;
  }
  return (o1 == 0 && on_segment(c, a, b)) || (o2 == 0 && on_segment(d, a, b)) || (o3 == 0 && on_segment(a, c, d)) ||
         (o4 == 0 && on_segment(b, c, d));
}
// p -> s -> q folds back: q on p's side of s, on the line.
bool folds(Grid p, Grid s, Grid q) {
  return orient(p, s, q) == 0 && (p.x - s.x) * (q.x - s.x) + (p.y - s.y) * (q.y - s.y) > 0;
}

// A random closed walk on the 8 x 8 grid without repeated consecutive points; without spikes
// (folds) unless `spikes`. With `clean` > 0 the ring starts with that many edges of a simple
// zigzag far from the grid (x from 100, y 0 or 50) and reaches the grid over the top (y = 200),
// so its first problem lies beyond the first blocks of the validator's ordered search; it closes
// from the grid through (-50, -50).
std::vector<Grid> collapsed_walk(std::size_t n, bool spikes, std::size_t clean = 0) {
  std::uint64_t state = 2003;
  const auto next = [&state]() {
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    return static_cast<std::int64_t>(state >> 61);  // 0..7
  };
  std::vector<Grid> w;
  for (std::size_t k = 0; k < clean; ++k) {
    w.push_back({100 + static_cast<std::int64_t>(k), static_cast<std::int64_t>(k % 2) * 50});
  }
  if (clean > 0) {
    w.push_back({100 + static_cast<std::int64_t>(clean), 200});
    w.push_back({0, 200});
  } else {
    w = {{0, 0}, {5, 1}};
  }
  const std::size_t end = clean > 0 ? n - 1 : n;
  while (w.size() < end) {
    const Grid q{next(), next()};
    const Grid& s = w.back();
    if ((q.x == s.x && q.y == s.y) || (!spikes && folds(w[w.size() - 2], s, q))) {
      continue;
    }
    w.push_back(q);
  }
  if (clean > 0) {
    const Grid close{-50, -50};
    while (folds(w[w.size() - 2], w.back(), close)) {
      w.pop_back();
    }
    w.push_back(close);
    return w;
  }
  while ((w.back().x == w.front().x && w.back().y == w.front().y) ||
         (!spikes && (folds(w[w.size() - 2], w.back(), w.front()) || folds(w.back(), w.front(), w[1])))) {
    w.pop_back();
  }
  return w;
}

fp::Ring to_ring(const std::vector<Grid>& w) {
  fp::Ring ring;
  for (const Grid& g : w) {
    ring.push_back({1 + static_cast<double>(g.x) * 0x1p-52, 1 + static_cast<double>(g.y) * 0x1p-52});
  }
  return ring;
}

// The two edge numbers a message names ("edge E (...)-(...) and edge F (...)").
std::pair<std::size_t, std::size_t> named_edges(const std::string& message) {
  const std::size_t a = message.find("edge ");
  const std::size_t b = message.find(" and edge ", a);
  if (a == std::string::npos || b == std::string::npos) {
    return {0, 0};
  }
  return {std::stoul(message.substr(a + 5)), std::stoul(message.substr(b + 10))};
}

}  // namespace

TEST(Hostile, RingCollapsedIntoAFewUlpsNamesItsFirstSelfTouch) {
  const std::vector<Grid> w = collapsed_walk(131072, /*spikes=*/false, /*clean=*/300);
  const std::size_t n = w.size();
  for (std::size_t v = 0; v < n; ++v) {
    ASSERT_FALSE(folds(w[(v + n - 1) % n], w[v], w[(v + 1) % n])) << "a spike at vertex " << v;
  }
  // The smallest pair (e, f), e < f, of non-adjacent edges that meet.
  std::pair<std::size_t, std::size_t> first{n, n};
  for (std::size_t e = 0; e < n && first.first == n; ++e) {
    for (std::size_t f = e + 2; f < n; ++f) {
      if ((e == 0 && f == n - 1) || !segments_meet(w[e], w[(e + 1) % n], w[f], w[(f + 1) % n])) {
        continue;
      }
      first = {e, f};
      break;
    }
  }
  ASSERT_GT(first.first, 300U);  // beyond the zigzag, so beyond the first blocks
  ASSERT_LT(first.first, n);
  try {
    (void)fp::Domain::from_rings(to_ring(w));
    ADD_FAILURE() << "a self-intersecting ring was accepted";
  } catch (const fp::InvalidDomainError& e) {
    EXPECT_EQ(e.kind(), fp::InvalidDomainError::Kind::self_intersection) << e.what();
    EXPECT_EQ(named_edges(e.what()), first) << e.what();
  }
}

TEST(Hostile, RingCollapsedIntoAFewUlpsNamesItsFirstSpike) {
  const std::vector<Grid> w = collapsed_walk(131072, /*spikes=*/true);
  const std::size_t n = w.size();
  // The spike with the smallest pair of edges: the first at a vertex e + 1 (edges e and e + 1),
  // or the one at vertex 0 (edges 0 and n - 1), which comes after edges 0 and 1 only.
  std::pair<std::size_t, std::size_t> first{n, n};
  for (std::size_t e = 0; e + 1 < n; ++e) {
    if (folds(w[e], w[e + 1], w[(e + 2) % n])) {
      first = {e, e + 1};
      break;
    }
  }
  if (folds(w[n - 1], w[0], w[1])) {
    first = std::min(first, std::pair<std::size_t, std::size_t>{0, n - 1});
  }
  ASSERT_LT(first.first, n);
  try {
    (void)fp::Domain::from_rings(to_ring(w));
    ADD_FAILURE() << "a ring with a spike was accepted";
  } catch (const fp::InvalidDomainError& e) {
    EXPECT_NE(std::string(e.what()).find("fold back"), std::string::npos) << e.what();
    EXPECT_EQ(named_edges(e.what()), first) << e.what();
  }
  // The only spike at vertex 0, between the closing edge (4) and the first (0).
  try {
    (void)fp::Domain::from_wkt("POLYGON((2 0,0 0,0 2,1 2,1 0,2 0))");
    ADD_FAILURE() << "a ring with a spike at its first vertex was accepted";
  } catch (const fp::InvalidDomainError& e) {
    EXPECT_NE(std::string(e.what()).find("fold back"), std::string::npos) << e.what();
    EXPECT_EQ(named_edges(e.what()), (std::pair<std::size_t, std::size_t>{0, 4})) << e.what();
  }
}

namespace {

// A star of n vertices (n even), alternately at radius 1 and 2 about the origin: its n edges fan
// around the unit disk, and their boxes meet in a number of pairs that grows as n^2 (18M at
// n = 20,000), though no two edges meet but at their shared vertex.
fp::Ring star(std::size_t n) {
  fp::Ring ring;
  for (std::size_t k = 0; k < n; ++k) {
    const double t = 2 * std::numbers::pi * static_cast<double>(k) / static_cast<double>(n);
    const double r = k % 2 == 0 ? 1.0 : 2.0;
    ring.push_back({r * std::cos(t), r * std::sin(t)});
  }
  return ring;
}

// A self-intersecting ring's refusal: its kind, a phrase its message must contain, and the pair
// of edges it names.
void expect_self_intersection(const fp::Ring& ring, const std::string& phrase,
                              std::pair<std::size_t, std::size_t> edges) {
  try {
    (void)fp::Domain::from_rings(ring);
    ADD_FAILURE() << "a self-intersecting ring was accepted";
  } catch (const fp::InvalidDomainError& e) {
    EXPECT_EQ(e.kind(), fp::InvalidDomainError::Kind::self_intersection) << e.what();
    EXPECT_NE(std::string(e.what()).find(phrase), std::string::npos) << e.what();
    EXPECT_EQ(named_edges(e.what()), edges) << e.what();
  }
}

}  // namespace

// Beyond a budget of box pairs with nothing found, a sweep decides that no two edges meet
// (validation took 4.2 s at 50,000 vertices, quadratically, before it; 0.5 s now). A hole touching
// the star at one of its vertices is a touch, which the sweep leaves to the pairwise pass.
TEST(Hostile, StarWithCrowdedEdgeBoxesIsValid) {
  const fp::Domain d = fp::Domain::from_rings(star(20000));
  EXPECT_EQ(d.num_vertices(), 20000U);
  const fp::Ring hole{{1, 0}, {0.5, -0.1}, {0.5, 0.1}};  // (1, 0) is the star's vertex 0
  const fp::Domain e = fp::Domain::from_rings(star(20000), {hole});
  EXPECT_EQ(e.num_vertices(), 20003U);
  EXPECT_LT(e.area(), d.area());
}

// The same star with its vertex 1 moved past vertex 3 (to radius 2, half way to vertex 4): edge 0
// (vertex 0 -> 1) now crosses edges 2 and 3, and edge 1 crosses edge 3. The sweep finds that
// edges meet, and the pairwise pass names the first pair.
TEST(Hostile, StarWithCrowdedEdgeBoxesNamesItsCrossing) {
  const std::size_t n = 20000;
  fp::Ring ring = star(n);
  const double t = 2 * std::numbers::pi * 3.5 / static_cast<double>(n);
  ring[1] = {2 * std::cos(t), 2 * std::sin(t)};
  expect_self_intersection(ring, " cross", {0, 2});
}

// Two holes in the star, each touching it at one of its vertices and the other at the origin:
// with the star's ring they cut its inside in two. The sweep finds no edges meeting inside, and
// the touches, all at points where vertices meet, are the hub pass's (src/domain/validate.cpp, find_hubs()).
TEST(Hostile, StarWithCrowdedEdgeBoxesAndHolesSplittingIt) {
  const std::size_t n = 20000;
  const fp::Ring outer = star(n);
  const fp::Point left = outer[n / 2];  // (-1, 1.2e-16)
  const fp::Ring a{outer[0], {0, 0}, {0.5, 0.1}};
  const fp::Ring b{left, {0, 0}, {-0.5, 0.1}};
  try {
    (void)fp::Domain::from_rings(outer, {a, b});
    ADD_FAILURE() << "a polygon whose holes split its interior was accepted";
  } catch (const fp::InvalidDomainError& e) {
    EXPECT_EQ(e.kind(), fp::InvalidDomainError::Kind::disconnected_interior) << e.what();
  }
}

// Scaling the domain and the radii by a power of two scales the packing by it, bit for bit, at
// 2^-266 and 2^266 (about 1e-80 and 1e80, within the accepted coordinates): the generators'
// lengths are homogeneous, and tangent_to_two, whose terms are fourth powers of lengths, works at
// the scale of rmax (LengthScale). Unscaled, those terms underflowed or overflowed there, and the
// closed form placed under 1% of the disks. At 2^-700 and 2^-960 (about 2e-211 and 1e-289) the
// squares of the overlap tests underflow too: the generators work in the unit of WorkScale there
// (before, such runs never ended, or were refused with a NaN estimate).
TEST(Hostile, ScalingByAPowerOfTwoScalesThePackingExactly) {
  const fp::Ring unit{{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  const fp::Domain d = fp::Domain::from_rings(unit);
  for (const int e : {-266, 266, -700, -960}) {
    fp::Ring scaled;
    for (const fp::Point p : unit) {
      scaled.push_back({std::ldexp(p.x, e), std::ldexp(p.y, e)});
    }
    const fp::Domain ds = fp::Domain::from_rings(scaled);
    for (const fp::Method m : {fp::Method::closed, fp::Method::open, fp::Method::boundary}) {
      SCOPED_TRACE(std::string(fp::to_string(m)) + " at 2^" + std::to_string(e));
      const fp::Packing p = fill(d, m, fp::Radii::uniform(0.005, 0.02));
      const fp::Packing ps = fill(ds, m, fp::Radii::uniform(std::ldexp(0.005, e), std::ldexp(0.02, e)));
      expect_certified(ds, ps);
      ASSERT_GT(p.disks.size(), 1000U);
      ASSERT_EQ(ps.disks.size(), p.disks.size());
      std::size_t differ = 0;
      for (std::size_t i = 0; i < p.disks.size(); ++i) {
        const fp::Disk& a = p.disks[i];
        const fp::Disk& b = ps.disks[i];
        differ += b.centre.x != std::ldexp(a.centre.x, e) || b.centre.y != std::ldexp(a.centre.y, e) ||
                          b.radius != std::ldexp(a.radius, e)
                      ? 1
                      : 0;
      }
      EXPECT_EQ(differ, 0U);
    }
  }
}

// The star with edge 0 laid along the x axis, from (1, 0) to (2, 0), and two vertices added after
// the last, the first of them at (1.5, 0): the ring touches itself there, a vertex inside one of
// its own edges, with no vertex in common and no crossing. Only the sweep's test for a point in an
// edge's interior sends the check back to the pairwise pass, which names the pair.
TEST(Hostile, StarWithCrowdedEdgeBoxesTouchingItselfInsideAnEdge) {
  const std::size_t n = 20000;
  fp::Ring ring = star(n);
  ring[0] = {1, 0};
  ring[1] = {2, 0};
  ring.push_back({1.5, 0});      // vertex n, on edge 0
  ring.push_back({1.2, -1e-4});  // below the axis, then back to vertex 0
  expect_self_intersection(ring, "touch at (1.5 0)", {0, n - 1});
}
