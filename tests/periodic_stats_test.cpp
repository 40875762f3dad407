// Packing statistics in periodic cells (frontpack::measure on Domain::periodic): a hexagonal
// lattice of equal touching disks that tiles the cell, whose contacts, fractions, cell coverage,
// largest empty circle and holes are known, measured as placed and shifted so that disks straddle
// the sides; the same disks measured as a walled box give other answers (so these can fail).
#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>
#include <numbers>
#include <vector>

#include "frontpack/frontpack.hpp"

namespace fp = frontpack;

namespace {

const double kHex = std::numbers::pi / (2 * std::sqrt(3.0));  // the lattice's packing fraction
const double kHoleRadius = 2 / std::sqrt(3.0) - 1;            // its holes', per unit radius

// Disks of radius r on the hexagonal lattice, `columns` per row 2r apart, `rows` rows sqrt(3) r
// apart and shifted by r every other row, from (x0, y0). With an even number of rows it is
// periodic with periods 2 r columns and sqrt(3) r rows.
std::vector<fp::Disk> hexagonal(int columns, int rows, double r, double x0, double y0) {
  std::vector<fp::Disk> disks;
  for (int j = 0; j < rows; ++j) {
    for (int i = 0; i < columns; ++i) {
      disks.push_back({{x0 + r * (2 * i + (j % 2)), y0 + std::sqrt(3.0) * r * j}, r});
    }
  }
  return disks;
}

// The disks moved by (dx, dy) and brought back into the cell along its periodic axes.
std::vector<fp::Disk> shifted(std::vector<fp::Disk> disks, const fp::Box& cell, double dx, double dy) {
  const auto wrap = [](double v, double lo, double hi) { return v >= hi ? v - (hi - lo) : v; };
  for (fp::Disk& d : disks) {
    d.centre = {wrap(d.centre.x + dx, cell.xmin, cell.xmax), wrap(d.centre.y + dy, cell.ymin, cell.ymax)};
  }
  return disks;
}

fp::Domain walled(const fp::Box& b) {
  return fp::Domain::from_rings({{b.xmin, b.ymin}, {b.xmax, b.ymin}, {b.xmax, b.ymax}, {b.xmin, b.ymax}});
}

// What the lattice in a cell periodic in x and y must give.
void expect_torus_lattice(const fp::Domain& domain, const std::vector<fp::Disk>& disks, double r) {
  const std::size_t n = disks.size();
  fp::StatsOptions o;
  o.hole_radii = {0.1 * r, r};
  const fp::PackingStats s = fp::measure(domain, disks, o);
  // Every disk touches six, across both sides too; no wall.
  EXPECT_EQ(s.contacts, 3 * n);
  EXPECT_EQ(s.overlaps, 0U);
  EXPECT_EQ(s.wall_contacts, 0U);
  ASSERT_EQ(s.coordination_histogram.size(), 7U);
  EXPECT_EQ(s.coordination_histogram[6], n);
  EXPECT_EQ(s.rattlers, 0U);
  EXPECT_EQ(s.mean_coordination, 6.0);
  // No wall, no band: everything is interior.
  EXPECT_FALSE(s.walls);
  EXPECT_EQ(s.band_samples, 0U);
  EXPECT_EQ(s.band_disks, 0U);
  EXPECT_EQ(s.interior_disks, n);
  EXPECT_EQ(s.interior_coordination, 6.0);
  EXPECT_NEAR(s.packing_fraction, kHex, 1e-12);
  EXPECT_NEAR(s.interior_fraction, kHex, 3 * s.interior_error);
  EXPECT_LT(s.interior_error, 1e-3);
  EXPECT_NEAR(s.interior_area, domain.area(), 1e-9 * domain.area());
  ASSERT_EQ(s.coverage_profile.size(), 7U);
  EXPECT_EQ(s.coverage_profile[6].samples, s.interior_samples);
  for (std::size_t k = 0; k < 6; ++k) {
    EXPECT_EQ(s.coverage_profile[k].samples, 0U);
  }
  // Squares of 8 r tile the cell (none dropped), and their coverage is the lattice's.
  const fp::Box b = domain.bbox();
  const auto squares = [r](double l) { return static_cast<std::size_t>(std::ceil(l / (8 * r))); };
  EXPECT_EQ(s.cell_coverage.cells, squares(b.width()) * squares(b.height()));
  EXPECT_GT(s.cell_coverage.p1, kHex - 0.015);
  EXPECT_LT(s.cell_coverage.p50, kHex + 0.015);
  EXPECT_LT(s.cell_coverage.sd, 0.01);
  // The largest empty circle is the lattice's hole, to the measure's tolerance.
  const fp::EmptyCircle& e = s.largest_empty_circle;
  ASSERT_TRUE(e.computed);
  EXPECT_LE(e.radius, kHoleRadius * r + 1e-12);
  EXPECT_GE(e.radius_upper, kHoleRadius * r - 1e-12);
  EXPECT_LE(e.radius_upper - e.radius, e.tolerance);
  EXPECT_EQ(domain.locate(e.centre), fp::Location::inside);
  // Two holes per disk (the lattice's triangles), each taking a disk of 0.1 r, counted once
  // however they straddle the sides; none takes a disk of radius r.
  ASSERT_EQ(s.holes.size(), 2U);
  EXPECT_EQ(s.holes[0].count, 2 * n);
  EXPECT_EQ(s.holes[1].count, 0U);
}

}  // namespace

TEST(PeriodicStats, HexagonalLatticeInATorus) {
  // 12 columns and 16 rows of disks of radius 1: a cell 24 x 16 sqrt(3), 3 x 4 squares of 8.
  const double r = 1;
  const fp::Box cell{0, 0, 24, 16 * std::sqrt(3.0)};
  const fp::Domain domain = fp::Domain::periodic(cell, fp::Periodicity::xy);
  const std::vector<fp::Disk> disks = hexagonal(12, 16, r, 0, 0);
  {
    SCOPED_TRACE("as placed");
    expect_torus_lattice(domain, disks, r);
  }
  {
    SCOPED_TRACE("shifted: disks straddle both sides");
    expect_torus_lattice(domain, shifted(disks, cell, 0.37, 0.61), r);
  }
  {
    // A cell away from the origin, not a whole number of squares wide.
    SCOPED_TRACE("another cell");
    const fp::Box other{-7.5, 3.25, -7.5 + 2 * 11, 3.25 + 14 * std::sqrt(3.0)};
    expect_torus_lattice(fp::Domain::periodic(other, fp::Periodicity::xy),
                         shifted(hexagonal(11, 14, r, other.xmin, other.ymin), other, 1.3, 0.2), r);
  }
  // The same disks as a walled box: the contacts across the sides are lost, the band appears.
  const fp::PackingStats w = fp::measure(walled(cell), disks);
  EXPECT_TRUE(w.walls);
  EXPECT_LT(w.contacts, 3 * disks.size() - 12);
  EXPECT_GT(w.band_samples, 0U);
  EXPECT_GT(w.rattlers + w.wall_contacts, 0U);
}

TEST(PeriodicStats, CellNarrowerThanTheReach) {
  // The smallest rectangular cell of the lattice: two disks, 2r x 2 sqrt(3) r. Each disk touches
  // its own images left and right and four images of the other: images of several periods.
  const double r = 0.5;
  const fp::Box cell{0, 0, 2 * r, 2 * std::sqrt(3.0) * r};
  const fp::Domain domain = fp::Domain::periodic(cell);
  const std::vector<fp::Disk> disks = hexagonal(1, 2, r, 0, 0);
  fp::StatsOptions o;
  o.hole_radii = {0.1 * r};
  const fp::PackingStats s = fp::measure(domain, disks, o);
  EXPECT_EQ(s.contacts, 6U);
  ASSERT_EQ(s.coordination_histogram.size(), 7U);
  EXPECT_EQ(s.coordination_histogram[6], 2U);
  EXPECT_EQ(s.rattlers, 0U);
  EXPECT_NEAR(s.interior_fraction, kHex, 3 * s.interior_error);
  EXPECT_NEAR(s.largest_empty_circle.radius, kHoleRadius * r, s.largest_empty_circle.tolerance);
  ASSERT_EQ(s.holes.size(), 1U);
  EXPECT_EQ(s.holes[0].count, 4U);
  // A hole radius far beyond the cell: no hole, and no images beyond what f can need.
  o.hole_radii = {1e6};
  o.empty_circle = false;
  const fp::PackingStats big = fp::measure(domain, disks, o);
  ASSERT_EQ(big.holes.size(), 1U);
  EXPECT_EQ(big.holes[0].count, 0U);
  o = {};
  o.hole_radii = {0.1 * r * 1e-200};
  // At a scale where squared lengths underflow (measured scaled back up): the same answers.
  std::vector<fp::Disk> tiny = disks;
  for (fp::Disk& d : tiny) {
    d = {{d.centre.x * 1e-200, d.centre.y * 1e-200}, d.radius * 1e-200};
  }
  const fp::Box c = cell;
  const fp::PackingStats t =
      fp::measure(fp::Domain::periodic({c.xmin * 1e-200, c.ymin * 1e-200, c.xmax * 1e-200, c.ymax * 1e-200}), tiny, o);
  EXPECT_EQ(t.contacts, 6U);
  EXPECT_FALSE(t.walls);
  ASSERT_EQ(t.holes.size(), 1U);
  EXPECT_EQ(t.holes[0].count, 4U);
}

TEST(PeriodicStats, ShearCellWalls) {
  // Periodic in x, walls at the bottom and top: 12 columns and 16 rows of radius 1, the bottom
  // row on the bottom wall and the top row under the top wall.
  const double r = 1;
  const int columns = 12;
  const int rows = 16;
  const double height = 2 * r + (rows - 1) * std::sqrt(3.0) * r;
  const fp::Box cell{0, 0, 2 * r * columns, height};
  const fp::Domain domain = fp::Domain::periodic(cell, fp::Periodicity::x);
  for (const double dx : {0.0, 0.73}) {
    SCOPED_TRACE(dx);
    const std::vector<fp::Disk> disks = shifted(hexagonal(columns, rows, r, 0, r), cell, dx, 0);
    const fp::PackingStats s = fp::measure(domain, disks);
    const std::size_t c = columns;
    EXPECT_EQ(s.contacts, c * (3 * rows - 2));  // rows, and between rows
    EXPECT_EQ(s.wall_contacts, 2 * c);          // the bottom and top rows, nothing at the sides
    EXPECT_EQ(s.rattlers, 0U);
    EXPECT_TRUE(s.walls);
    // The band is along the walls only: two strips 2r high.
    EXPECT_NEAR(s.band_area, 2 * 2 * r * cell.width(), 0.01 * s.band_area);
    EXPECT_EQ(s.band_disks, 2 * c);  // gaps to a wall below r: the rows on them
    EXPECT_EQ(s.interior_disks, c * (rows - 4));
    EXPECT_EQ(s.interior_coordination, 6.0);
    // The largest empty circle: in a pocket between two disks and a wall, r / 4.
    EXPECT_NEAR(s.largest_empty_circle.radius, r / 4, s.largest_empty_circle.tolerance);
    // The squares of 8 r (centres at y = 4, 12, 20, 28 in a cell 2 + 15 sqrt(3) high): all three
    // columns, and the two rows whose squares keep 2r from the walls (centres at 12 and 20).
    EXPECT_EQ(s.cell_coverage.cells, 6U);
    EXPECT_GT(s.cell_coverage.p1, kHex - 0.015);
    // As a walled box: one contact per row and one per pair of rows across the side are lost,
    // the sides are walls, and only the middle column of squares keeps clear of them.
    const fp::PackingStats w = fp::measure(walled(cell), disks);
    EXPECT_EQ(w.contacts, s.contacts - (2 * rows - 1));
    EXPECT_GT(w.wall_contacts, s.wall_contacts);
    EXPECT_EQ(w.cell_coverage.cells, 2U);
  }
}
