// The advancing front and its certificate: exact non-overlap and containment on every shape,
// checked again by an independent brute force; the hexagonal lattice for equal radii;
// determinism; termination on hostile requests; translation invariance.
#include <gtest/gtest.h>

#include <CGAL/Gmpq.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <numbers>
#include <random>
#include <string>
#include <unordered_map>
#include <vector>

#include "frontpack/frontpack.hpp"
#include "test_support.hpp"

namespace fp = frontpack;

namespace {

// Independent exact pair predicate (rationals, no filter): the interiors intersect.
bool overlap_exact(const fp::Disk& a, const fp::Disk& b) {
  const CGAL::Gmpq dx = CGAL::Gmpq(a.centre.x) - CGAL::Gmpq(b.centre.x);
  const CGAL::Gmpq dy = CGAL::Gmpq(a.centre.y) - CGAL::Gmpq(b.centre.y);
  const CGAL::Gmpq s = CGAL::Gmpq(a.radius) + CGAL::Gmpq(b.radius);
  return dx * dx + dy * dy < s * s;
}

// Brute force over all pairs whose boxes meet, via a hash grid (the test's own index).
std::size_t brute_force_overlaps(const std::vector<fp::Disk>& disks, std::size_t limit) {
  if (disks.empty()) {
    return 0;
  }
  double rmax = 0;
  for (const auto& d : disks) {
    rmax = std::max(rmax, d.radius);
  }
  const double h = 2 * rmax;
  std::unordered_map<std::int64_t, std::vector<std::size_t>> cells;
  const auto key = [h](double x, double y) {
    return (static_cast<std::int64_t>(std::floor(x / h)) << 32) ^
           (static_cast<std::int64_t>(std::floor(y / h)) & 0xffffffff);
  };
  for (std::size_t i = 0; i < disks.size(); ++i) {
    cells[key(disks[i].centre.x, disks[i].centre.y)].push_back(i);
  }
  std::size_t found = 0;
  for (std::size_t i = 0; i < std::min(limit, disks.size()); ++i) {
    const fp::Disk& a = disks[i];
    for (int dx = -1; dx <= 1; ++dx) {
      for (int dy = -1; dy <= 1; ++dy) {
        const auto it = cells.find(key(a.centre.x + dx * h, a.centre.y + dy * h));
        if (it == cells.end()) {
          continue;
        }
        for (const std::size_t j : it->second) {
          if (j > i && overlap_exact(a, disks[j])) {
            ++found;
          }
        }
      }
    }
  }
  return found;
}

fp::Packing fill(const fp::Domain& d, fp::Method m, fp::Radii radii, std::uint64_t seed, double clearance = 0) {
  fp::FillOptions o;
  o.clearance = clearance;
  o.method = m;
  o.radii = std::move(radii);
  o.seed = seed;
  return fp::fill(d, o);
}

double covered_fraction(const fp::Domain& d, const std::vector<fp::Disk>& disks) {
  double a = 0;
  for (const auto& k : disks) {
    a += std::numbers::pi * k.radius * k.radius;
  }
  return a / d.area();
}

}  // namespace

// Every shape x both forms x 3 seeds, radii [r, 10r] sized for 1k-50k disks.
class FillShapes : public ::testing::TestWithParam<std::string> {};

TEST_P(FillShapes, CertifiedOnBothFormsAndThreeSeeds) {
  const fp::Domain d = fp::Domain::from_wkt_file(fp::test::shapes_dir() / GetParam());
  // Size r so that about 4000 disks of mean area fit the bounding box of the largest part.
  const fp::Box b = d.bbox();
  const double r =
      std::sqrt(b.width() * b.height() / (4000 * std::numbers::pi * 37.0));  // E[r^2] = 37 r^2 for [r, 10r]
  for (const fp::Method m : {fp::Method::closed, fp::Method::open}) {
    for (const std::uint64_t seed : {1ULL, 2ULL, 0xfeedULL}) {
      SCOPED_TRACE(std::string(fp::to_string(m)) + " seed " + std::to_string(seed));
      const fp::Packing p = fill(d, m, fp::Radii::uniform(r, 10 * r), seed);
      EXPECT_GE(p.disks.size(), 300U);
      EXPECT_LE(p.disks.size(), 50000U);
      EXPECT_EQ(p.certificate.dropped, 0U) << "the generator itself produced an overlap";
      EXPECT_TRUE(p.certificate.exact);
      EXPECT_EQ(p.certificate.generated, p.disks.size() + p.certificate.culled);
      // The certifier, run again on the result: nothing outside, no overlapping pair.
      const fp::CertifyReport again = fp::certify(d, p.disks);
      EXPECT_TRUE(again.outside.empty());
      EXPECT_TRUE(again.overlapping.empty());
      // And an independent brute force (exact rationals) on a subset of the disks.
      EXPECT_EQ(brute_force_overlaps(p.disks, 2000), 0U);
      for (std::size_t i = 0; i < p.disks.size(); i += 7) {
        ASSERT_TRUE(d.contains(p.disks[i]));
      }
      EXPECT_GT(covered_fraction(d, p.disks), 0.45);
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Shapes, FillShapes, ::testing::ValuesIn(fp::test::shape_names()), fp::test::ShapeTestName());

// The per-shape tests take their shapes from shapes/ itself; this guards against an empty or
// moved directory (no instances would run).
TEST(FillShapes, CorpusCoversEveryShape) {
  EXPECT_GE(fp::test::shape_files().size(), 14U) << "shapes/ lost a shape";
}

// The certifier must find what is there: a planted overlap and a planted outside disk.
TEST(Certify, FindsPlantedDefects) {
  const fp::Domain d = fp::Domain::from_wkt("POLYGON((0 0,10 0,10 10,0 10,0 0))");
  std::vector<fp::Disk> disks = {{{2, 2}, 1}, {{4, 2}, 1}, {{5.9, 2}, 1}, {{9.5, 5}, 1}, {{5, 5}, 1}};
  // 0-1 touch exactly (fine); 1-2 overlap; 3 pokes out of x = 10.
  const fp::CertifyReport r = fp::certify(d, disks);
  ASSERT_EQ(r.overlapping.size(), 1U);
  EXPECT_EQ(r.overlapping[0], (std::pair<std::size_t, std::size_t>{1, 2}));
  ASSERT_EQ(r.outside.size(), 1U);
  EXPECT_EQ(r.outside[0], 3U);
  // One ulp apart is decided exactly both ways.
  const double x = std::nextafter(4.0, 0.0);
  const fp::CertifyReport ulp = fp::certify(d, std::vector<fp::Disk>{{{2, 2}, 1}, {{x, 2}, 1}});
  EXPECT_EQ(ulp.overlapping.size(), 1U);
}

TEST(Fill, EqualRadiiClosedFormIsHexagonal) {
  // Paper Fig. 9(a): equal disks give the hexagonal lattice. 1 x 1 with r = 0.004: ~18,000 disks.
  const double r = 0.004;
  const fp::Domain d = fp::Domain::from_wkt("POLYGON((0 0,1 0,1 1,0 1,0 0))");
  const fp::Packing p = fill(d, fp::Method::closed, fp::Radii::constant(r), 5);
  ASSERT_GE(p.disks.size(), 10000U);
  EXPECT_EQ(p.stats.blocked_segments, 0U);
  // Interior disks: farther than 4r from the boundary. Contact: centre distance <= 2r (1 + 1e-9).
  const double contact = 2 * r * (1 + 1e-9);
  std::unordered_map<std::int64_t, std::vector<std::size_t>> cells;
  const double h = 2.5 * r;
  const auto key = [h](double x, double y) {
    return (static_cast<std::int64_t>(std::floor(x / h)) << 32) ^ static_cast<std::int64_t>(std::floor(y / h));
  };
  for (std::size_t i = 0; i < p.disks.size(); ++i) {
    cells[key(p.disks[i].centre.x, p.disks[i].centre.y)].push_back(i);
  }
  std::size_t interior = 0;
  for (std::size_t i = 0; i < p.disks.size(); ++i) {
    const fp::Point c = p.disks[i].centre;
    if (c.x < 4 * r || c.x > 1 - 4 * r || c.y < 4 * r || c.y > 1 - 4 * r) {
      continue;
    }
    ++interior;
    int neighbours = 0;
    for (int dx = -1; dx <= 1; ++dx) {
      for (int dy = -1; dy <= 1; ++dy) {
        const auto it = cells.find(key(c.x + dx * h, c.y + dy * h));
        if (it == cells.end()) {
          continue;
        }
        for (const std::size_t j : it->second) {
          if (j != i && std::hypot(p.disks[j].centre.x - c.x, p.disks[j].centre.y - c.y) <= contact) {
            ++neighbours;
          }
        }
      }
    }
    ASSERT_EQ(neighbours, 6) << "disk " << i << " at " << c.x << " " << c.y;
  }
  EXPECT_GT(interior, 8000U);
  // Interior packing fraction: the exact disk area inside the window [8r, 1 - 8r]^2 (disks cut
  // by the window integrated numerically), over the window's area.
  const double lo = 8 * r;
  const double hi = 1 - 8 * r;
  double covered = 0;
  for (const fp::Disk& k : p.disks) {
    const fp::Point c = k.centre;
    if (c.x - r >= lo && c.x + r <= hi && c.y - r >= lo && c.y + r <= hi) {
      covered += std::numbers::pi * r * r;
    } else if (c.x + r > lo && c.x - r < hi && c.y + r > lo && c.y - r < hi) {
      constexpr int steps = 2000;  // midpoint rule on the vertical chords
      const double x0 = std::max(c.x - r, lo);
      const double x1 = std::min(c.x + r, hi);
      const double dxs = (x1 - x0) / steps;
      for (int s = 0; s < steps; ++s) {
        const double x = x0 + (s + 0.5) * dxs;
        const double half = std::sqrt(std::max(0.0, r * r - (x - c.x) * (x - c.x)));
        covered += std::max(0.0, std::min(c.y + half, hi) - std::max(c.y - half, lo)) * dxs;
      }
    }
  }
  const double phi = covered / ((hi - lo) * (hi - lo));
  EXPECT_NEAR(phi, std::numbers::pi / std::sqrt(12.0), 1e-3);
}

TEST(Fill, SameSeedIsBitIdenticalAndAnotherSeedDiffers) {
  const fp::Domain d = fp::Domain::from_wkt_file(fp::test::shapes_dir() / "concave_polygon.wkt");
  for (const fp::Method m : {fp::Method::closed, fp::Method::open}) {
    const fp::Packing a = fill(d, m, fp::Radii::uniform(0.005, 0.02), 42);
    const fp::Packing b = fill(d, m, fp::Radii::uniform(0.005, 0.02), 42);
    const fp::Packing c = fill(d, m, fp::Radii::uniform(0.005, 0.02), 43);
    ASSERT_EQ(a.disks.size(), b.disks.size());
    for (std::size_t i = 0; i < a.disks.size(); ++i) {
      ASSERT_EQ(std::memcmp(&a.disks[i], &b.disks[i], sizeof(fp::Disk)), 0) << i;
    }
    EXPECT_NE(a.disks, c.disks);
  }
}

TEST(Fill, TranslationByAnExactOffsetTranslatesThePacking) {
  // The front works in coordinates local to each box's corner, so a domain translated by an
  // exactly representable offset runs the very same computation (given the same clearance: the
  // automatic one grows with the coordinates); only the final addition of the corner rounds
  // differently, by at most an ulp of the output.
  const fp::Domain d = fp::Domain::from_wkt_file(fp::test::shapes_dir() / "l_shape.wkt");
  const double offset = 1024;
  std::vector<fp::Polygon> moved = d.polygons();
  for (fp::Polygon& p : moved) {
    for (fp::Point& v : p.outer) {
      v = {v.x + offset, v.y - offset};
      ASSERT_EQ(v.x - offset + offset, v.x);  // exact
    }
  }
  const fp::Domain t = fp::Domain::from_polygons(moved);
  for (const fp::Method m : {fp::Method::closed, fp::Method::open}) {
    SCOPED_TRACE(fp::to_string(m));
    const fp::Packing a = fill(d, m, fp::Radii::uniform(0.01, 0.05), 7, 1e-10);
    const fp::Packing b = fill(t, m, fp::Radii::uniform(0.01, 0.05), 7, 1e-10);
    ASSERT_EQ(a.certificate.generated, b.certificate.generated);
    ASSERT_EQ(a.disks.size(), b.disks.size());
    for (std::size_t i = 0; i < a.disks.size(); ++i) {
      EXPECT_EQ(a.disks[i].radius, b.disks[i].radius);
      const double ulp = std::nextafter(std::abs(b.disks[i].centre.x), INFINITY) - std::abs(b.disks[i].centre.x);
      EXPECT_LE(std::abs(a.disks[i].centre.x + offset - b.disks[i].centre.x), 2 * ulp) << i;
      EXPECT_LE(std::abs(a.disks[i].centre.y - offset - b.disks[i].centre.y), 2 * ulp) << i;
    }
  }
}

TEST(Fill, TerminatesOnHostileRadii) {
  const fp::Domain square = fp::Domain::from_wkt("POLYGON((0 0,1 0,1 1,0 1,0 0))");
  const fp::Domain channel = fp::Domain::from_wkt("POLYGON((0 0,10 0,10 0.01,0 0.01,0 0))");
  for (const fp::Method m : {fp::Method::closed, fp::Method::open}) {
    SCOPED_TRACE(fp::to_string(m));
    // rmin larger than the domain: no disk fits, and the error says so; rmax larger: a few disks.
    fp::test::expect_nothing_fits([&] { return fill(square, m, fp::Radii::uniform(2, 3), 1); },
                                  "no disk fits: the smallest radius, 2 ");
    // (None placed is NothingFitsError: the run ended and said why.)
    std::size_t placed = 0;
    try {
      placed = fill(square, m, fp::Radii::uniform(0.3, 5), 1).disks.size();
    } catch (const fp::NothingFitsError& e) {
      EXPECT_NE(std::string(e.what()).find("none lay inside the domain"), std::string::npos) << e.what();
    }
    EXPECT_LE(placed, 4U);
    // A domain narrower than 2 rmin: the same error, naming the widest disk it holds.
    fp::test::expect_nothing_fits([&] { return fill(channel, m, fp::Radii::uniform(0.01, 0.02), 1); },
                                  "none of radius above 0.005)");
    // rmax / rmin = 100.
    const fp::Packing wide = fill(square, m, fp::Radii::uniform(0.001, 0.1), 1);
    EXPECT_EQ(wide.certificate.dropped, 0U);
    EXPECT_GT(wide.disks.size(), 40U);  // E[r^2] = 0.0034: about 80 disks fit
  }
}

// A polygon's disks are culled against that polygon, not the whole domain: here the L's box
// contains the square, and the L's fill covers it too (found by the fill fuzzer).
TEST(Fill, PolygonsWhoseBoxesOverlapKeepTheirOwnDisks) {
  const fp::Domain domain =
      fp::Domain::from_wkt("MULTIPOLYGON(((0 0,2 0,2 1,1 1,1 2,0 2,0 0)),((1.1 1.1,2 1.1,2 2,1.1 2,1.1 1.1)))");
  for (const fp::Method m : {fp::Method::closed, fp::Method::open}) {
    for (const std::uint64_t seed : {1U, 2U, 3U}) {
      SCOPED_TRACE(std::string(fp::to_string(m)) + " seed " + std::to_string(seed));
      const fp::Packing p = fill(domain, m, fp::Radii::uniform(0.01, 0.05), seed);
      EXPECT_EQ(p.certificate.dropped, 0U);
      EXPECT_GT(p.disks.size(), 500U);
      const fp::CertifyReport again = fp::certify(domain, p.disks);
      EXPECT_TRUE(again.overlapping.empty());
      EXPECT_TRUE(again.outside.empty());
    }
  }
}

// The paper's forms fill the domain's box and cull: in a triangle, about half of what they
// generate. The packing must not keep the culled disks' memory (it held a copy of every disk
// once: a 10M-disk packing is 240 MB).
TEST(Fill, PackingKeepsNoMemoryOfCulledDisks) {
  const fp::Domain triangle = fp::Domain::from_wkt("POLYGON((0 0,2 0,0 2,0 0))");
  for (const fp::Method m : {fp::Method::closed, fp::Method::open}) {
    SCOPED_TRACE(fp::to_string(m));
    const fp::Packing p = fill(triangle, m, fp::Radii::uniform(0.005, 0.02), 7);
    ASSERT_GT(p.certificate.culled, p.disks.size() / 4) << "the test needs heavy culling";
    EXPECT_LE(p.disks.capacity() - p.disks.size(), p.disks.size() / 8);
  }
}

TEST(Fill, OptionsAreChecked) {
  EXPECT_THROW((void)fp::Radii::uniform(0.2, 0.1), fp::OptionError);
  EXPECT_THROW((void)fp::Radii::uniform(0, 0.1), fp::OptionError);
  EXPECT_THROW((void)fp::Radii::uniform(-1, 0.1), fp::OptionError);
  EXPECT_THROW((void)fp::Radii::uniform(NAN, 0.1), fp::OptionError);
  EXPECT_THROW((void)fp::Radii::constant(INFINITY), fp::OptionError);
  const fp::Domain d = fp::Domain::from_wkt("POLYGON((0 0,1 0,1 1,0 1,0 0))");
  fp::FillOptions o;
  o.radii = fp::Radii::constant(1e-4);
  o.max_disks = 1000;
  o.clearance = 1e-20;  // below the safe minimum for a unit domain
  EXPECT_THROW((void)fp::fill(d, o), fp::OptionError);
  o.clearance = 0;
  try {
    (void)fp::fill(d, o);
    FAIL() << "no LimitError";
  } catch (const fp::LimitError& e) {
    EXPECT_GT(e.estimate(), 10000U);
    EXPECT_NE(std::string(e.what()).find("max_disks"), std::string::npos);
  }
}

TEST(Fill, ProgressAndCancellation) {
  const fp::Domain d = fp::Domain::from_wkt("POLYGON((0 0,1 0,1 1,0 1,0 0))");
  fp::FillOptions o;
  o.radii = fp::Radii::uniform(0.001, 0.002);
  fp::Generator g(d, o);
  std::size_t calls = 0;
  g.on_progress([&](const fp::Progress& p) {
    ++calls;
    EXPECT_GE(p.fraction, 0.0);
    EXPECT_LE(p.fraction, 1.0);
    return p.disks < 40000;
  });
  const fp::Packing p = g.run();
  EXPECT_TRUE(p.cancelled);
  EXPECT_GT(calls, 1U);
  EXPECT_LT(p.certificate.generated, 60000U);
  EXPECT_EQ(p.certificate.dropped, 0U);
  EXPECT_TRUE(fp::certify(d, p.disks).overlapping.empty());
}

// Progress is the fraction of the area to fill that is filled: it grows with every report, is
// close to 1 at the last report before the front ends (the density estimate is good), and is 1
// as it ends, with the area of every disk generated; then the certification starts (0) and ends
// (1). On a domain with holes too: the boundary method's area to fill is the domain's, not the
// polygons' boxes'.
void expect_progress_is_the_area_filled(const fp::Domain& d, fp::Method method, double last_tick_at_least) {
  fp::FillOptions o;
  o.method = method;
  o.radii = fp::Radii::uniform(0.001, 0.002);
  fp::Generator g(d, o);
  std::vector<fp::Progress> reports;
  g.on_progress([&](const fp::Progress& p) {
    reports.push_back(p);
    return true;
  });
  const fp::Packing p = g.run();
  ASSERT_GE(reports.size(), 5U);
  const std::size_t n = reports.size() - 2;  // the generation's reports
  for (std::size_t i = 0; i < n; ++i) {
    EXPECT_EQ(reports[i].phase, fp::Phase::generate);
  }
  for (std::size_t i = 1; i < n; ++i) {
    EXPECT_GT(reports[i].fraction, reports[i - 1].fraction);
    EXPECT_GT(reports[i].area, reports[i - 1].area);
  }
  const fp::Progress& last_tick = reports[n - 2];
  EXPECT_GT(last_tick.fraction, last_tick_at_least);
  EXPECT_LE(last_tick.fraction, 0.99);
  EXPECT_EQ(reports[n - 1].fraction, 1.0);
  EXPECT_EQ(reports[n - 1].disks, p.certificate.generated);
  EXPECT_GE(reports[n - 1].area, covered_fraction(d, p.disks) * d.area());
  EXPECT_EQ(reports[n].phase, fp::Phase::certify);
  EXPECT_EQ(reports[n].fraction, 0.0);
  EXPECT_EQ(reports[n + 1].phase, fp::Phase::certify);
  EXPECT_EQ(reports[n + 1].fraction, 1.0);
  EXPECT_EQ(reports[n + 1].disks, p.certificate.generated);
}

TEST(Fill, ProgressIsTheAreaFilled) {
  const fp::Domain square = fp::Domain::from_wkt("POLYGON((0 0,1 0,1 1,0 1,0 0))");
  expect_progress_is_the_area_filled(square, fp::Method::boundary, 0.75);
  expect_progress_is_the_area_filled(square, fp::Method::closed, 0.6);
  // A square with a hole of half its area.
  const fp::Domain holed = fp::Domain::from_wkt(
      "POLYGON((0 0,1 0,1 1,0 1,0 0),(0.1464466 0.1464466,0.1464466 0.8535534,0.8535534 0.8535534,"
      "0.8535534 0.1464466,0.1464466 0.1464466))");
  expect_progress_is_the_area_filled(holed, fp::Method::boundary, 0.75);  // 0.42 with the boxes
}

// The overlap pass works tile by tile beyond 2^18 disks. 600,000 disks on a jittered lattice with
// radii that make many of them overlap (also across tile borders) must give exactly the pairs
// of a brute force. Coordinates and radii are multiples of 2^-20 below 2^10, so the brute force
// in double arithmetic is exact.
TEST(Certify, TiledOverlapPassFindsExactlyTheOverlappingPairs) {
  const fp::Domain d = fp::Domain::from_wkt("POLYGON((-1 -1,800 -1,800 800,-1 800,-1 -1))");
  std::mt19937_64 rng(99);
  const auto q = [](double v) { return std::round(v * 0x1p20) * 0x1p-20; };
  std::vector<fp::Disk> disks;
  const int side = 775;  // 600,625 disks, spacing 1
  for (int i = 0; i < side; ++i) {
    for (int j = 0; j < side; ++j) {
      const double jx = static_cast<double>(rng() >> 11) * 0x1p-53 - 0.5;
      const double jy = static_cast<double>(rng() >> 11) * 0x1p-53 - 0.5;
      const double r = 0.3 + 0.25 * (static_cast<double>(rng() >> 11) * 0x1p-53);
      disks.push_back({{q(i + 0.2 * jx), q(j + 0.2 * jy)}, q(r)});
    }
  }
  std::vector<std::pair<std::size_t, std::size_t>> expected;
  for (int i = 0; i < side; ++i) {
    for (int j = 0; j < side; ++j) {
      const std::size_t a = static_cast<std::size_t>(i) * side + static_cast<std::size_t>(j);
      for (int di = -1; di <= 1; ++di) {
        for (int dj = -1; dj <= 1; ++dj) {
          const int ni = i + di;
          const int nj = j + dj;
          if (ni < 0 || nj < 0 || ni >= side || nj >= side) {
            continue;
          }
          const std::size_t b = static_cast<std::size_t>(ni) * side + static_cast<std::size_t>(nj);
          if (b <= a) {
            continue;
          }
          const double dx = disks[a].centre.x - disks[b].centre.x;
          const double dy = disks[a].centre.y - disks[b].centre.y;
          const double s = disks[a].radius + disks[b].radius;
          if (dx * dx + dy * dy < s * s) {  // exact for these dyadic values
            expected.emplace_back(a, b);
          }
        }
      }
    }
  }
  std::sort(expected.begin(), expected.end());
  ASSERT_GT(expected.size(), 10000U);
  const fp::CertifyReport r = fp::certify(d, disks);
  EXPECT_TRUE(r.outside.empty());
  ASSERT_EQ(r.overlapping.size(), expected.size());
  EXPECT_EQ(r.overlapping, expected);
}

// The window M (Sec. 2.4.3): 0 means the whole front (with the half-turn rule of Sec. 2.4.2 in
// the closed form), 1 the nearest disk on each side. Every setting gives a certified packing;
// a smaller window finds fewer cases (b)-(d) and retires more segments.
TEST(Fill, WindowSizesAllCertify) {
  const fp::Domain d = fp::Domain::from_wkt_file(fp::test::shapes_dir() / "concave_polygon.wkt");
  for (const fp::Method m : {fp::Method::closed, fp::Method::open}) {
    std::size_t blocked_small = 0;
    std::size_t blocked_whole = 0;
    for (const std::size_t window : {std::size_t{0}, std::size_t{1}, std::size_t{5}, std::size_t{50}}) {
      SCOPED_TRACE(std::string(fp::to_string(m)) + " window " + std::to_string(window));
      fp::FillOptions o;
      o.method = m;
      o.radii = fp::Radii::uniform(0.004, 0.02);
      o.window = window;
      const fp::Packing p = fp::fill(d, o);
      EXPECT_GT(p.disks.size(), 500U);
      EXPECT_EQ(p.certificate.dropped, 0U);
      EXPECT_TRUE(fp::certify(d, p.disks).overlapping.empty());
      EXPECT_GT(covered_fraction(d, p.disks), 0.6);
      if (window == 1) {
        blocked_small = p.stats.blocked_segments;
      } else if (window == 0) {
        blocked_whole = p.stats.blocked_segments;
      }
    }
    // With M = 1 most overlaps beyond the nearest neighbours retire a segment (about 100 here);
    // with the whole front every front disk is reachable.
    EXPECT_GT(blocked_small, blocked_whole) << fp::to_string(m);
  }
}

// docs/robustness.md, "Acceptance": the generators accept a disk only if it keeps every other
// one at least r1 + r2 + clearance / 2 away. With a clearance the user gives, comparable to the
// radii, the grid scans must reach that far: they once reached r + rmax only, and disks of
// radius near rmax just beyond it went unseen (pairs at 0.03-0.2 of the clearance instead of
// 0.5). Checked on every pair closer than r1 + r2 + clearance, in the output's doubles (their
// rounding is below 1e-13 here, against a clearance of 0.2 or 0.5).
TEST(Fill, EveryPairKeepsHalfTheClearance) {
  const fp::Domain d = fp::Domain::from_wkt("POLYGON((0 0,60 0,60 60,0 60,0 0))");
  for (const double clearance : {0.2, 0.5}) {
    for (const fp::Method m : {fp::Method::closed, fp::Method::open, fp::Method::boundary}) {
      fp::FillOptions o;
      o.method = m;
      o.radii = fp::Radii::uniform(0.49, 0.5);
      o.window = 1;
      o.clearance = clearance;
      o.seed = 7;
      const fp::Packing p = fp::fill(d, o);
      ASSERT_GT(p.disks.size(), 1000U);
      std::vector<fp::Disk> disks = p.disks;
      std::sort(disks.begin(), disks.end(),
                [](const fp::Disk& a, const fp::Disk& b) { return a.centre.x < b.centre.x; });
      double worst = clearance;
      for (std::size_t i = 0; i < disks.size(); ++i) {
        for (std::size_t j = i + 1; j < disks.size() && disks[j].centre.x - disks[i].centre.x < 1 + clearance; ++j) {
          const double gap = std::hypot(disks[j].centre.x - disks[i].centre.x, disks[j].centre.y - disks[i].centre.y) -
                             disks[i].radius - disks[j].radius;
          worst = std::min(worst, gap);
        }
      }
      EXPECT_GE(worst, clearance / 2 - 1e-9) << "method " << static_cast<int>(m) << ", clearance " << clearance;
    }
  }
}

// `frontpack fill DOMAIN` runs fill(domain, FillOptions{}): the tool takes its default method and
// radius spec from the library, and the spec must parse to the library's default distribution.
TEST(FillOptions, DefaultsAreTheToolsAndTheSpecParsesToTheDefaultRadii) {
  const fp::FillOptions defaults;
  EXPECT_EQ(defaults.method, fp::Method::boundary);
  EXPECT_TRUE(defaults.fill_voids);
  const fp::Radii parsed = fp::parse_radii(fp::default_radius_spec);
  EXPECT_EQ(parsed.describe(), defaults.radii.describe());
  EXPECT_EQ(parsed.min(), 0.01);
  EXPECT_EQ(parsed.max(), 0.05);
}

// fill_voids = false is the paper's forms as published; the boundary method's voids are part of
// it, and without them it left large empty areas, so it refuses the option rather than return
// such a packing.
TEST(FillOptions, BoundaryRefusesFillVoidsOffAndThePaperFormsTakeIt) {
  const fp::Domain square = fp::Domain::from_wkt("POLYGON((0 0,1 0,1 1,0 1,0 0))");
  fp::FillOptions o;
  o.radii = fp::Radii::uniform(0.02, 0.05);
  o.fill_voids = false;
  o.method = fp::Method::boundary;
  try {
    (void)fp::fill(square, o);
    ADD_FAILURE() << "boundary with fill_voids = false was not refused";
  } catch (const fp::OptionError& e) {
    EXPECT_NE(std::string(e.what()).find("boundary method keeps its voids"), std::string::npos) << e.what();
  }
  for (const fp::Method m : {fp::Method::closed, fp::Method::open}) {
    o.method = m;
    const fp::Packing p = fp::fill(square, o);
    EXPECT_GT(p.disks.size(), 100U) << fp::to_string(m);
  }
}
