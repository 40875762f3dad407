// CellGrid (src/generate/disk_grid.hpp; WorkScale: src/generate/scale.hpp), the generators' uniform grid, at the ends
// of the double range: a radius whose margin of 4 rmax overflows, or whose cell's reciprocal does, gets one cell that
// every finite coordinate near the box maps into (the grid was sized from a NaN before: an
// undefined conversion, and the boundary method asked for an absurd allocation); ordinary radii
// keep their grid.
#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>

#include "generate/disk_grid.hpp"
#include "generate/scale.hpp"

namespace {

using frontpack::detail::CellGrid;
using frontpack::detail::WorkScale;

TEST(CellGrid, OrdinaryRadiiGetCellsOfRmax) {
  const CellGrid g(0, 0, 1, 2, 0.01);
  EXPECT_FALSE(g.coarse);
  EXPECT_EQ(g.side, 0.01);
  // (w + 8 rmax) / rmax cells, the last one cut at the edge.
  EXPECT_GE(static_cast<double>(g.nx) * g.side, 1 + 8 * 0.01);
  EXPECT_LE(g.nx, 109U);
  EXPECT_GE(static_cast<double>(g.ny) * g.side, 2 + 8 * 0.01);
  EXPECT_LE(g.ny, 209U);
  EXPECT_EQ(g.col(0.5), 54);  // 0.54 from the grid's corner
  EXPECT_EQ(g.col(-1e300), 0);
  EXPECT_EQ(g.row(1e300), static_cast<std::int64_t>(g.ny) - 1);
  EXPECT_EQ(g.col(std::numeric_limits<double>::quiet_NaN()), 0);
}

TEST(CellGrid, RadiiWhoseMarginOverflowsGetOneCell) {
  for (const double rmax : {3e307, 1e308, std::numeric_limits<double>::max()}) {
    SCOPED_TRACE(rmax);
    const CellGrid g(0, 0, 1, 1, rmax);
    EXPECT_TRUE(g.coarse);
    EXPECT_EQ(g.nx, 1U);
    EXPECT_EQ(g.ny, 1U);
    EXPECT_EQ(g.cells(), 1U);
    EXPECT_TRUE(std::isfinite(g.x0) && std::isfinite(g.y0) && std::isfinite(g.inv_side));
    for (const double x : {0.0, 1.0, -1e300, 1e300, 1e100}) {
      EXPECT_EQ(g.col(x), 0);
      EXPECT_EQ(g.row(x), 0);
      EXPECT_EQ(g.col_inside(x), 0);
    }
  }
}

TEST(CellGrid, SubnormalRadiiInADomainAsSmallGetOneCell) {
  const CellGrid g(0, 0, 4e-320, 4e-320, 1e-321);
  EXPECT_TRUE(g.coarse);
  EXPECT_EQ(g.cells(), 1U);
  EXPECT_EQ(g.col(2e-320), 0);
}

// The generators' unit: 1 (nothing scaled) for rmax in [2^-300, 2^300], a power of two bringing
// rmax to [1, 2) outside.
TEST(WorkScale, IsOneButForExtremeRadii) {
  for (const double rmax : {1.0, 1e-80, 0x1p-300, 1e80, 0x1p300}) {
    const WorkScale u(rmax);
    EXPECT_EQ(u.k, 1.0) << rmax;
    EXPECT_EQ(u.inv_k, 1.0) << rmax;
  }
  for (const double rmax : {1e-201, 1e-301, 0x1p-301, 0x1.8p300, 1e200, 1e300}) {
    const WorkScale u(rmax);
    EXPECT_GE(rmax * u.k, 1.0) << rmax;
    EXPECT_LT(rmax * u.k, 2.0) << rmax;
    EXPECT_EQ(u.k * u.inv_k, 1.0) << rmax;
    EXPECT_EQ(std::ilogb(u.k), -std::ilogb(u.inv_k)) << rmax;
  }
  // Beyond 2^1000 either way: as far as a finite k goes (2^-1000 or 2^1000).
  const WorkScale big(std::numeric_limits<double>::max());
  EXPECT_EQ(big.k, 0x1p-1000);
  EXPECT_LT(std::numeric_limits<double>::max() * big.k, 0x1p24);
  const WorkScale u(3e-310);
  EXPECT_EQ(u.k, 0x1p1000);
  EXPECT_GT(3e-310 * u.k, 0x1p-75);
}

}  // namespace
