// Filling a periodic cell (Domain::periodic(); the boundary method and the closed form wrap around
// it): no two disks overlap through any image, decided by the library's certifier and by an
// independent exact oracle here (CGAL rationals over the exact periods); every centre lies in the
// half-open cell; the front reaches across the sides; the run is deterministic; the options a
// periodic cell cannot take are refused with a message.
#include <gtest/gtest.h>

#include <CGAL/Exact_rational.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "frontpack/frontpack.hpp"

namespace frontpack {
namespace {

using Q = CGAL::Exact_rational;

FillOptions options(Method method, const char* radii, std::uint64_t seed = 1) {
  FillOptions o;
  o.method = method;
  o.radii = parse_radii(radii);
  o.seed = seed;
  return o;
}

// Every pair (i, j), i <= j, that overlaps through some image (shifts of -1, 0, 1 periods on the
// periodic axes; enough for radii below half a period), decided in exact rationals with the
// exact periods xmax - xmin and ymax - ymin. Candidates from a sort by x with a generous window
// (floating point only prunes pairs far apart).
std::size_t oracle_overlaps(const std::vector<Disk>& disks, const Box& cell, bool wrap_y) {
  const Q lx = Q(cell.xmax) - Q(cell.xmin);
  const Q ly = Q(cell.ymax) - Q(cell.ymin);
  const double w = cell.xmax - cell.xmin;
  const double h = cell.ymax - cell.ymin;
  double rmax = 0;
  for (const Disk& d : disks) {
    rmax = std::max(rmax, d.radius);
  }
  std::vector<std::size_t> order(disks.size());
  for (std::size_t i = 0; i < order.size(); ++i) {
    order[i] = i;
  }
  std::sort(order.begin(), order.end(),
            [&](std::size_t a, std::size_t b) { return disks[a].centre.x < disks[b].centre.x; });
  std::size_t found = 0;
  const double reach = 2.01 * rmax;
  for (int sx = -1; sx <= 1; ++sx) {
    for (int sy = wrap_y ? -1 : 0; sy <= (wrap_y ? 1 : 0); ++sy) {
      for (std::size_t a = 0; a < order.size(); ++a) {
        const Disk& p = disks[order[a]];
        // q + (sx, sy) periods near p: q.x near p.x - sx * w.
        const double target = p.centre.x - sx * w;
        auto lo = std::lower_bound(order.begin(), order.end(), target - reach,
                                   [&](std::size_t i, double v) { return disks[i].centre.x < v; });
        for (auto it = lo; it != order.end() && disks[*it].centre.x <= target + reach; ++it) {
          const std::size_t j = *it;
          if (j == order[a] && sx == 0 && sy == 0) {
            continue;
          }
          const Disk& q = disks[j];
          if (std::abs(q.centre.y + sy * h - p.centre.y) > reach) {
            continue;
          }
          const Q dx = Q(q.centre.x) + Q(sx) * lx - Q(p.centre.x);
          const Q dy = Q(q.centre.y) + Q(sy) * ly - Q(p.centre.y);
          const Q rr = Q(p.radius) + Q(q.radius);
          found += dx * dx + dy * dy < rr * rr ? 1U : 0U;
        }
      }
    }
  }
  return found;
}

// Each test runs with both methods that wrap around a cell.
class PeriodicFill : public testing::TestWithParam<Method> {};

TEST_P(PeriodicFill, TorusHasNoOverlapThroughAnyImage) {
  const Box cell{0, 0, 3, 3};
  const Domain domain = Domain::periodic(cell, Periodicity::xy);
  const Packing packing = fill(domain, options(GetParam(), "discrete:0.02:0.5,0.028:0.5"));
  ASSERT_GT(packing.disks.size(), 3000U);
  EXPECT_EQ(packing.certificate.culled, 0U);
  EXPECT_EQ(packing.certificate.dropped, 0U);
  const CertifyReport report = certify(domain, packing.disks);
  EXPECT_TRUE(report.outside.empty());
  EXPECT_TRUE(report.overlapping.empty());
  EXPECT_EQ(oracle_overlaps(packing.disks, cell, true), 0U);
  std::size_t across_x = 0;
  std::size_t across_y = 0;
  double area = 0;
  for (const Disk& d : packing.disks) {
    ASSERT_TRUE(d.centre.x >= cell.xmin && d.centre.x < cell.xmax);
    ASSERT_TRUE(d.centre.y >= cell.ymin && d.centre.y < cell.ymax);
    across_x += d.centre.x - d.radius < cell.xmin || d.centre.x + d.radius > cell.xmax ? 1U : 0U;
    across_y += d.centre.y - d.radius < cell.ymin || d.centre.y + d.radius > cell.ymax ? 1U : 0U;
    area += std::numbers::pi * d.radius * d.radius;
  }
  // The packing reaches across both pairs of sides (a front that stopped at them would not), and
  // it is as dense as each method's interior in a walled square (0.81-0.82 at these radii).
  EXPECT_GT(across_x, 40U);
  EXPECT_GT(across_y, 40U);
  EXPECT_GT(area / 9, 0.79);
}

TEST(PeriodicOracle, SeesAPlantedOverlapAcrossTheSide) {
  // The oracle above can fail: two disks that overlap only through the x period.
  const Box cell{0, 0, 1, 1};
  const std::vector<Disk> disks{{{0.0625, 0.5}, 0.125}, {{0.875, 0.5}, 0.125}};
  EXPECT_EQ(oracle_overlaps(disks, cell, true), 2U);                            // seen from each disk
  const std::vector<Disk> apart{{{0.125, 0.5}, 0.125}, {{0.875, 0.5}, 0.125}};  // touching through the side
  EXPECT_EQ(oracle_overlaps(apart, cell, true), 0U);
}

TEST_P(PeriodicFill, ShearCellWrapsInXAndKeepsBetweenTheWalls) {
  const Box cell{-1, 2, 1.5, 3.5};
  const Domain domain = Domain::periodic(cell, Periodicity::x);
  const Packing packing = fill(domain, options(GetParam(), "uniform:0.01,0.04", 7));
  ASSERT_GT(packing.disks.size(), 1000U);
  if (GetParam() == Method::boundary) {
    EXPECT_EQ(packing.certificate.culled, 0U);  // its walls are the cell's (the closed form culls there)
  }
  EXPECT_EQ(packing.certificate.dropped, 0U);
  const CertifyReport report = certify(domain, packing.disks);
  EXPECT_TRUE(report.outside.empty());
  EXPECT_TRUE(report.overlapping.empty());
  EXPECT_EQ(oracle_overlaps(packing.disks, cell, false), 0U);
  std::size_t across_x = 0;
  double area = 0;
  for (const Disk& d : packing.disks) {
    ASSERT_TRUE(d.centre.x >= cell.xmin && d.centre.x < cell.xmax);
    ASSERT_GE(d.centre.y - d.radius, cell.ymin);
    ASSERT_LE(d.centre.y + d.radius, cell.ymax);
    across_x += d.centre.x - d.radius < cell.xmin || d.centre.x + d.radius > cell.xmax ? 1U : 0U;
    area += std::numbers::pi * d.radius * d.radius;
  }
  EXPECT_GT(across_x, 10U);
  EXPECT_GT(area / (2.5 * 1.5), GetParam() == Method::boundary ? 0.80 : 0.76);  // the closed form culls at the walls
}

TEST_P(PeriodicFill, SameSeedSameBits) {
  const Domain domain = Domain::periodic(Box{0, 0, 1, 1}, Periodicity::xy);
  const Packing a = fill(domain, options(GetParam(), "uniform:0.01,0.05", 3));
  const Packing b = fill(domain, options(GetParam(), "uniform:0.01,0.05", 3));
  const Packing c = fill(domain, options(GetParam(), "uniform:0.01,0.05", 4));
  EXPECT_EQ(a.disks, b.disks);
  EXPECT_NE(a.disks, c.disks);
}

INSTANTIATE_TEST_SUITE_P(Methods, PeriodicFill, testing::Values(Method::boundary, Method::closed),
                         [](const testing::TestParamInfo<Method>& p) {
                           return p.param == Method::boundary ? std::string("boundary") : std::string("closed");
                         });

TEST(PeriodicCell, RefusesWhatACellCannotTake) {
  const Domain domain = Domain::periodic(Box{0, 0, 1, 1}, Periodicity::xy);
  try {
    (void)fill(domain, options(Method::open, "uniform:0.01,0.05"));
    FAIL() << "the open form filled a periodic cell";
  } catch (const OptionError& e) {
    EXPECT_EQ(std::string(e.what()),
              "a periodic cell is filled by the boundary method or the closed form; the open form does not wrap "
              "around a cell");
  }
  try {
    (void)fill(domain, options(Method::boundary, "uniform:0.05,0.2"));
    FAIL() << "a cell 5 rmax wide was filled";
  } catch (const OptionError& e) {
    EXPECT_EQ(std::string(e.what()),
              "a periodic cell must be at least 10 rmax = 2 across each periodic direction; it is 1 x 1");
  }
  EXPECT_THROW((void)Domain::periodic(Box{0, 0, 1, 1}, Periodicity::none), OptionError);
  EXPECT_THROW((void)Domain::periodic(Box{0, 0, 0, 1}, Periodicity::xy), InvalidDomainError);
  EXPECT_THROW((void)Domain::periodic(Box{0, 0, NAN, 1}, Periodicity::xy), InvalidDomainError);
}

}  // namespace
}  // namespace frontpack
