// Periodic cells (Domain::periodic): exact containment in the cell and between a shear cell's
// walls, and certify()'s overlap pass across the images, against planted cases whose exact answer
// is known and against a brute-force exact oracle (CGAL::Gmpq, every shift in a range wide enough
// for the set) on random sets.
#include <CGAL/Gmpq.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <random>
#include <utility>
#include <vector>

#include "frontpack/frontpack.hpp"

namespace fp = frontpack;

namespace {

using Pairs = std::vector<std::pair<std::size_t, std::size_t>>;

fp::Domain torus(double lx, double ly) {
  return fp::Domain::periodic(fp::Box{0, 0, lx, ly}, fp::Periodicity::xy);
}

Pairs pairs_of(const fp::Domain& domain, const std::vector<fp::Disk>& disks) {
  return fp::certify(domain, disks).overlapping;
}

// The oracle: (i, j), i <= j, overlap when |c_i - c_j - (kx Lx, ky Ly)| < r_i + r_j for some
// shift in [-K, K]^2 (ky = 0 without y periodicity; (0, 0) skipped for i = j), in exact rationals;
// the periods are the exact differences of the bounds.
Pairs oracle(const fp::Box& cell, fp::Periodicity axes, const std::vector<fp::Disk>& disks, int K) {
  using Q = CGAL::Gmpq;
  const Q lx = Q(cell.xmax) - Q(cell.xmin);
  const Q ly = Q(cell.ymax) - Q(cell.ymin);
  const int ky_max = axes == fp::Periodicity::xy ? K : 0;
  Pairs out;
  for (std::size_t i = 0; i < disks.size(); ++i) {
    for (std::size_t j = i; j < disks.size(); ++j) {
      // Shifts whose image is far apart in double (by a margin a million times any rounding)
      // are skipped: exact rationals on every shift take half a minute.
      const double s_d = disks[i].radius + disks[j].radius;
      const double margin = 1e-6 * (1 + s_d + std::abs(cell.xmax) + std::abs(cell.xmin) + std::abs(cell.ymax) +
                                    std::abs(cell.ymin) + std::abs(disks[i].centre.x) + std::abs(disks[j].centre.x) +
                                    std::abs(disks[i].centre.y) + std::abs(disks[j].centre.y));
      const double dx_d = disks[i].centre.x - disks[j].centre.x;
      const double dy_d = disks[i].centre.y - disks[j].centre.y;
      struct Exact {
        Q s2;  // (r_i + r_j)^2
        Q dx0;
        Q dy0;
      };
      std::optional<Exact> exact;
      bool overlap = false;
      for (int kx = -K; kx <= K && !overlap; ++kx) {
        for (int ky = -ky_max; ky <= ky_max && !overlap; ++ky) {
          if ((i == j && kx == 0 && ky == 0) || std::abs(dx_d - kx * (cell.xmax - cell.xmin)) > s_d + margin ||
              std::abs(dy_d - ky * (cell.ymax - cell.ymin)) > s_d + margin) {
            continue;
          }
          if (!exact) {
            exact = Exact{Q(disks[i].radius) + Q(disks[j].radius), Q(disks[i].centre.x) - Q(disks[j].centre.x),
                          Q(disks[i].centre.y) - Q(disks[j].centre.y)};
            exact->s2 = exact->s2 * exact->s2;
          }
          const Q dx = exact->dx0 - Q(kx) * lx;
          const Q dy = exact->dy0 - Q(ky) * ly;
          overlap = dx * dx + dy * dy < exact->s2;
        }
      }
      if (overlap) {
        out.emplace_back(i, j);
      }
    }
  }
  return out;
}

TEST(PeriodicCertify, OverlapAcrossTheXSeam) {
  // (9.25, 5)'s image at (-0.75, 5) lies 1.25 from (0.5, 5): closer than the radii's sum 2.
  const std::vector<fp::Disk> disks = {{{0.5, 5}, 1}, {{5, 5}, 1}, {{9.25, 5}, 1}};
  EXPECT_EQ(pairs_of(torus(10, 10), disks), (Pairs{{0, 2}}));
  EXPECT_EQ(pairs_of(fp::Domain::periodic(fp::Box{0, 0, 10, 10}, fp::Periodicity::x), disks), (Pairs{{0, 2}}));
  // A walled square sees no overlap there.
  EXPECT_TRUE(pairs_of(fp::Domain::from_wkt("POLYGON((0 0,10 0,10 10,0 10,0 0))"), disks).empty());
}

TEST(PeriodicCertify, OverlapAcrossTheYSeamOnlyOnATorus) {
  const std::vector<fp::Disk> disks = {{{5, 0.5}, 1}, {{5, 9.25}, 1}};
  EXPECT_EQ(pairs_of(torus(10, 10), disks), (Pairs{{0, 1}}));
  // In a shear cell the bottom and top are walls: no image in y (both disks cross a wall).
  const fp::CertifyReport shear = fp::certify(fp::Domain::periodic(fp::Box{0, 0, 10, 10}, fp::Periodicity::x), disks);
  EXPECT_TRUE(shear.overlapping.empty());
  EXPECT_EQ(shear.outside, (std::vector<std::size_t>{0, 1}));
}

TEST(PeriodicCertify, OverlapsAtTheFourCorners) {
  // One disk at each corner: every two of them meet across a seam or the corner (the diagonal
  // images are 0.25 sqrt(2) apart, below 0.5).
  const std::vector<fp::Disk> disks = {
      {{0.125, 0.125}, 0.25}, {{9.875, 0.125}, 0.25}, {{0.125, 9.875}, 0.25}, {{9.875, 9.875}, 0.25}};
  EXPECT_EQ(pairs_of(torus(10, 10), disks), (Pairs{{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}}));
  // Each corner alone with a disk across the opposite corner (through the corner only).
  for (std::size_t c = 0; c < 4; ++c) {
    const std::vector<fp::Disk> pair = {disks[c], disks[3 - c]};
    EXPECT_EQ(pairs_of(torus(10, 10), pair), (Pairs{{0, 1}})) << "corner " << c;
  }
}

TEST(PeriodicCertify, TouchingAcrossASeamIsNoOverlap) {
  // The image of (9.5, 5) is (-0.5, 5), exactly 1 from (0.5, 5) = r + r: touching.
  const std::vector<fp::Disk> touch = {{{0.5, 5}, 0.5}, {{9.5, 5}, 0.5}};
  const fp::CertifyReport r = fp::certify(torus(10, 10), touch);
  EXPECT_TRUE(r.overlapping.empty());
  EXPECT_TRUE(r.outside.empty());
  EXPECT_EQ(r.certificate.candidate_pairs, 1u);
  // The same across the y seam, and across the corner: B's image (-0.125, -0.25) lies
  // (0.375, 0.5) from A, 0.625 = 0.3125 + 0.3125 (a 3-4-5 triangle).
  EXPECT_TRUE(pairs_of(torus(10, 10), {{{5, 0.5}, 0.5}, {{5, 9.5}, 0.5}}).empty());
  EXPECT_TRUE(pairs_of(torus(10, 10), {{{0.25, 0.25}, 0.3125}, {{9.875, 9.75}, 0.3125}}).empty());
  EXPECT_EQ(pairs_of(torus(10, 10), {{{0.25, 0.25}, 0.3125}, {{9.875, 9.75}, std::nextafter(0.3125, 1.0)}}),
            (Pairs{{0, 1}}));
  // One ulp more radius overlaps.
  const std::vector<fp::Disk> over = {{{0.5, 5}, 0.5}, {{9.5, 5}, std::nextafter(0.5, 1.0)}};
  EXPECT_EQ(pairs_of(torus(10, 10), over), (Pairs{{0, 1}}));
}

// A cell whose period xmax - xmin is not a double: the pair is decided by the exact period,
// whichever way the rounded one would decide it.
TEST(PeriodicCertify, TheExactPeriodDecides) {
  using Q = CGAL::Gmpq;
  int checked_up = 0;
  int checked_down = 0;
  for (int k = 1; k <= 64 && (checked_up == 0 || checked_down == 0); ++k) {
    const double xmin = 0.1 * k;
    const double xmax = 1e6 + 0.3 * k;
    const Q exact = Q(xmax) - Q(xmin);
    const double rounded = xmax - xmin;
    if (Q(rounded) == exact) {
      continue;
    }
    const fp::Box cell{xmin, 0, xmax, 10};
    const double x1 = xmin + 0.5;
    const double x2 = xmax - 0.75;
    // The image of disk 2 lies at x2 - L; its distance to x1 is g = x1 - x2 + L.
    const Q g_exact = Q(x1) - Q(x2) + exact;
    const Q g_rounded = Q(x1) - Q(x2) + Q(rounded);
    // A radius sum R strictly between the two gaps: exactly one of them is below it.
    const double lo = std::min(CGAL::to_double(g_exact), CGAL::to_double(g_rounded));
    const double hi = std::max(CGAL::to_double(g_exact), CGAL::to_double(g_rounded));
    const double R = 0.5 * (lo + hi);
    const Q sum = Q(R / 2) + Q(R / 2);
    ASSERT_TRUE(sum > CGAL::min(g_exact, g_rounded) && sum < CGAL::max(g_exact, g_rounded));
    const bool exact_overlap = g_exact < sum;
    EXPECT_NE(exact_overlap, g_rounded < sum);  // the rounded period would decide the other way
    const std::vector<fp::Disk> disks = {{{x1, 5}, R / 2}, {{x2, 5}, R / 2}};
    const fp::Domain domain = fp::Domain::periodic(cell, fp::Periodicity::xy);
    EXPECT_EQ(pairs_of(domain, disks), exact_overlap ? (Pairs{{0, 1}}) : Pairs{})
        << "xmin " << xmin << " xmax " << xmax;
    (exact_overlap ? checked_up : checked_down) += 1;
  }
  EXPECT_GT(checked_up, 0);
  EXPECT_GT(checked_down, 0);
}

TEST(PeriodicCertify, ADiskWiderThanThePeriodMeetsItsOwnImage) {
  const fp::Domain cell = fp::Domain::periodic(fp::Box{0, 0, 1, 2}, fp::Periodicity::xy);
  EXPECT_EQ(pairs_of(cell, {{{0.5, 1}, 0.625}}), (Pairs{{0, 0}}));
  EXPECT_TRUE(pairs_of(cell, {{{0.5, 1}, 0.5}}).empty());  // diameter = period: touches its image
  // Through y only: the period in y is 2.
  const fp::Domain tall = fp::Domain::periodic(fp::Box{0, 0, 2, 1}, fp::Periodicity::xy);
  EXPECT_EQ(pairs_of(tall, {{{1, 0.5}, 0.625}}), (Pairs{{0, 0}}));
  // A shear cell has no image in y: only the x period counts.
  const fp::Domain shear = fp::Domain::periodic(fp::Box{0, 0, 2, 1.5}, fp::Periodicity::x);
  EXPECT_TRUE(pairs_of(shear, {{{1, 0.75}, 0.75}}).empty());
  const fp::CertifyReport r = fp::certify(fp::Domain::periodic(fp::Box{0, 0, 1, 3}, fp::Periodicity::x),
                                          std::vector<fp::Disk>{{{0.5, 1.5}, 0.75}, {{0.5, 0.625}, 0.25}});
  EXPECT_EQ(r.overlapping, (Pairs{{0, 0}, {0, 1}}));
  ASSERT_TRUE(r.deepest_overlap.has_value());
  EXPECT_EQ(*r.deepest_overlap, (std::pair<std::size_t, std::size_t>{0, 0}));
  EXPECT_EQ(r.deepest_overlap_depth, 0.5);  // 1.5 - 1
  // Many times the period: still one pair per disk, and with every other disk.
  const std::vector<fp::Disk> huge = {{{0.25, 0.25}, 7}, {{0.75, 0.75}, 0.125}};
  EXPECT_EQ(pairs_of(torus(1, 1), huge), (Pairs{{0, 0}, {0, 1}}));
}

TEST(PeriodicCertify, ContainmentIsHalfOpenOnAPeriodicAxis) {
  const fp::Domain d = torus(10, 10);
  EXPECT_TRUE(d.contains(fp::Disk{{0, 0}, 3}));  // reaching across both seams is fine
  EXPECT_FALSE(d.contains(fp::Disk{{10, 5}, 1}));
  EXPECT_FALSE(d.contains(fp::Disk{{5, 10}, 1}));
  EXPECT_TRUE(d.contains(fp::Disk{{std::nextafter(10.0, 0.0), 5}, 1}));
  EXPECT_FALSE(d.contains(fp::Disk{{5, 5}, -1}));
  EXPECT_FALSE(d.contains(fp::Disk{{5, 5}, std::nan("")}));
  EXPECT_FALSE(d.contains(fp::Disk{{std::nan(""), 5}, 1}));
  EXPECT_EQ(d.locate({0, 0}), fp::Location::inside);
  EXPECT_EQ(d.locate({10, 5}), fp::Location::outside);
  const std::vector<fp::Disk> disks = {{{0, 0}, 1}, {{10, 0}, 1}, {{-1, 5}, 1}};
  std::vector<std::uint8_t> out(disks.size());
  d.contains(disks, out);
  EXPECT_EQ(out, (std::vector<std::uint8_t>{1, 0, 0}));
  const fp::CertifyReport r = fp::certify(d, disks);
  EXPECT_EQ(r.outside, (std::vector<std::size_t>{1, 2}));
  // (10, 0) is (0, 0)'s own position one period on: the two coincide. (-1, 5) is (9, 5): apart.
  EXPECT_EQ(r.overlapping, (Pairs{{0, 1}}));
  ASSERT_TRUE(r.farthest_outside.has_value());
  EXPECT_EQ(*r.farthest_outside, 2u);
  EXPECT_EQ(r.farthest_outside_by, 2.0);
}

// The shear cell's walls: y - r >= ymin and y + r <= ymax decided exactly where y - r and y + r
// round onto the wall.
TEST(PeriodicCertify, ShearCellWallsAreExact) {
  using Q = CGAL::Gmpq;
  int rounded_cases = 0;
  for (const double y : {0.3, 0.7, 0.9, 1.1, 2.3}) {
    for (const double r : {0.1, 0.2, 0.3, 0.05}) {
      const double bottom = y - r;  // rounded
      const double top = y + r;
      const fp::Domain low = fp::Domain::periodic(fp::Box{0, bottom, 1, bottom + 10}, fp::Periodicity::x);
      const fp::Domain high = fp::Domain::periodic(fp::Box{0, top - 10, 1, top}, fp::Periodicity::x);
      const fp::Disk disk{{0.5, y}, r};
      EXPECT_EQ(low.contains(disk), Q(y) - Q(r) >= Q(bottom)) << y << " " << r;
      EXPECT_EQ(high.contains(disk), Q(y) + Q(r) <= Q(top)) << y << " " << r;
      rounded_cases += (Q(y) - Q(r) != Q(bottom)) + (Q(y) + Q(r) != Q(top));
    }
  }
  EXPECT_GT(rounded_cases, 4);  // the rounding happened: the floating-point test would be wrong there
  const fp::Domain shear = fp::Domain::periodic(fp::Box{0, 0, 4, 2}, fp::Periodicity::x);
  EXPECT_TRUE(shear.contains(fp::Disk{{0, 0.5}, 0.5}));  // touching the bottom wall
  EXPECT_TRUE(shear.contains(fp::Disk{{3.5, 1.5}, 0.5}));
  EXPECT_FALSE(shear.contains(fp::Disk{{3.5, 1.5}, std::nextafter(0.5, 1.0)}));
  EXPECT_EQ(shear.locate({1, 0}), fp::Location::boundary);
  EXPECT_EQ(shear.locate({1, 2}), fp::Location::boundary);
  EXPECT_EQ(shear.locate({1, 1}), fp::Location::inside);
  EXPECT_EQ(shear.locate({4, 1}), fp::Location::outside);
  EXPECT_EQ(shear.locate({1, 2.5}), fp::Location::outside);
  const fp::CertifyReport r = fp::certify(shear, std::vector<fp::Disk>{{{3.5, 1.75}, 0.5}});
  ASSERT_TRUE(r.farthest_outside.has_value());
  EXPECT_EQ(r.farthest_outside_by, 0.25);
}

struct RandomCase {
  fp::Box cell;
  fp::Periodicity axes = fp::Periodicity::xy;
  double rmin = 0;
  double rmax = 0;
  std::size_t n = 0;
  int K = 0;  // the oracle's shift range
};

std::vector<fp::Disk> random_disks(const RandomCase& c, std::uint32_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<fp::Disk> disks;
  const double lx = c.cell.xmax - c.cell.xmin;
  const double ly = c.cell.ymax - c.cell.ymin;
  for (std::size_t i = 0; i < c.n; ++i) {
    fp::Disk d{{c.cell.xmin + u(rng) * lx, c.cell.ymin + u(rng) * ly}, c.rmin + u(rng) * (c.rmax - c.rmin)};
    // Some centres a period or two away (a simulation's unwrapped dump), some on a side.
    const double roll = u(rng);
    if (roll < 0.1) {
      d.centre.x += std::floor(u(rng) * 5 - 2) * lx;
      if (c.axes == fp::Periodicity::xy) {
        d.centre.y -= std::floor(u(rng) * 5 - 2) * ly;
      }
    } else if (roll < 0.15) {
      d.centre.x = c.cell.xmin;
    }
    disks.push_back(d);
  }
  // A few exact duplicates one period apart, and a touching image pair.
  disks.push_back(fp::Disk{{disks[0].centre.x + lx, disks[0].centre.y}, disks[0].radius});
  return disks;
}

TEST(PeriodicCertify, AgreesWithABruteForceOracle) {
  const std::vector<RandomCase> cases = {
      {.cell = {0, 0, 10, 10}, .axes = fp::Periodicity::xy, .rmin = 0.2, .rmax = 0.6, .n = 300, .K = 4},
      {.cell = {-3.3, 1.7, 4.1, 9.9}, .axes = fp::Periodicity::xy, .rmin = 0.05, .rmax = 1.5, .n = 200, .K = 4},
      {.cell = {0.1, -7, 3.7, 2.2}, .axes = fp::Periodicity::x, .rmin = 0.1, .rmax = 0.4, .n = 250, .K = 4},
      // A tiny cell: radii up to three periods.
      {.cell = {0, 0, 1, 0.7}, .axes = fp::Periodicity::xy, .rmin = 0.01, .rmax = 2, .n = 40, .K = 9},
      {.cell = {1e6, 1e6, 1e6 + 1.3, 1e6 + 2.9},
       .axes = fp::Periodicity::xy,
       .rmin = 0.01,
       .rmax = 0.2,
       .n = 150,
       .K = 4},
  };
  std::size_t total = 0;
  for (std::size_t c = 0; c < cases.size(); ++c) {
    for (std::uint32_t seed = 1; seed <= 3; ++seed) {
      const std::vector<fp::Disk> disks = random_disks(cases[c], seed);
      const fp::Domain domain = fp::Domain::periodic(cases[c].cell, cases[c].axes);
      const Pairs expected = oracle(cases[c].cell, cases[c].axes, disks, cases[c].K);
      EXPECT_EQ(pairs_of(domain, disks), expected) << "case " << c << " seed " << seed;
      total += expected.size();
    }
  }
  EXPECT_GT(total, 100u);  // the sets do overlap
}

// fill()'s closed form in a periodic cell, certified by the same pass (certify_fill): nothing
// dropped, and certify() agrees with the oracle on the fill and on the fill with a disk across
// the left side grown into its neighbours.
TEST(PeriodicCertify, RealFillsAgreeWithTheOracle) {
  for (const fp::Periodicity axes : {fp::Periodicity::xy, fp::Periodicity::x}) {
    const fp::Box cell{0.1, -0.2, 1.7, 1.1};
    const fp::Domain domain = fp::Domain::periodic(cell, axes);
    fp::FillOptions options;
    options.method = fp::Method::closed;
    options.radii = fp::Radii::uniform(0.01, 0.05);
    options.seed = 9;
    const fp::Packing packing = fp::fill(domain, options);
    ASSERT_GT(packing.disks.size(), 500u);
    EXPECT_EQ(packing.certificate.dropped, 0u);
    std::vector<fp::Disk> disks = packing.disks;
    const fp::CertifyReport clean = fp::certify(domain, disks);
    EXPECT_TRUE(clean.outside.empty());
    EXPECT_TRUE(clean.overlapping.empty());
    EXPECT_TRUE(oracle(cell, axes, disks, 2).empty());
    std::size_t crossing = 0;
    for (fp::Disk& d : disks) {
      if (d.centre.x - d.radius < cell.xmin) {
        d.radius *= 1.2;
        ++crossing;
      }
    }
    ASSERT_GT(crossing, 3u);
    const Pairs found = pairs_of(domain, disks);
    EXPECT_FALSE(found.empty());
    EXPECT_EQ(found, oracle(cell, axes, disks, 2)) << fp::to_string(axes);
  }
}

}  // namespace
