// Where the jam stage inserts its disks (src/jam/insertion.hpp): in the holes of the packing, the
// largest first, each hole taking one disk of a round (the disks appended before count), across
// the sides of a periodic cell, and only inside the domain; and the cells of its neighbour
// searches (src/jam/disk_cells.hpp) find every disk within their reach, wrapped on periodic axes.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

#include "common/rng.hpp"
#include "domain/edge_distance.hpp"
#include "frontpack/domain.hpp"
#include "frontpack/sizes.hpp"
#include "jam/disk_cells.hpp"
#include "jam/insertion.hpp"

namespace fp = frontpack;
using fp::detail::DiskCells;
using fp::detail::EdgeDistanceIndex;
using fp::detail::Insertion;
using fp::detail::Rng;

namespace {

constexpr double kR = 0.025;  // a square lattice of touching disks of this radius, 20 x 20 in the unit square

// The lattice's disks but those whose centres are listed in `gone` (by lattice index i + 20 j).
std::vector<fp::Disk> lattice_without(const std::vector<std::size_t>& gone) {
  std::vector<fp::Disk> disks;
  for (std::size_t j = 0; j < 20; ++j) {
    for (std::size_t i = 0; i < 20; ++i) {
      if (std::find(gone.begin(), gone.end(), i + 20 * j) == gone.end()) {
        disks.push_back(fp::Disk{{kR * static_cast<double>(2 * i + 1), kR * static_cast<double>(2 * j + 1)}, kR});
      }
    }
  }
  return disks;
}

fp::Point lattice_centre(std::size_t q) {
  return {kR * static_cast<double>(2 * (q % 20) + 1), kR * static_cast<double>(2 * (q / 20) + 1)};
}

double distance(fp::Point a, fp::Point b) {
  return std::hypot(a.x - b.x, a.y - b.y);
}

struct Stage {
  fp::Domain domain;
  EdgeDistanceIndex walls;
  explicit Stage(fp::Domain d) : domain(std::move(d)), walls(domain, 2 * kR) {}
  Insertion insertion(const std::vector<fp::Disk>& disks, Rng& rng, double rmax = kR) const {
    return Insertion(domain, walls, domain.periodicity(), domain.bbox(), kR, rmax, disks, rng);
  }
};

}  // namespace

TEST(JamInsertion, FillsTheHolesLargestFirst) {
  // Two holes: one disk missing at lattice index 210 (inside), two side by side at 85 and 86 (a
  // larger hole). The first disk goes into the larger hole, the second into the other, each
  // within a quarter of a spacing of the hole's centre (the climb's last steps are h/4 and h/8).
  // Clearances are capped at rmax: 2 kR here, so that the larger hole's shows.
  const Stage s(fp::Domain::from_wkt("POLYGON((0 0,1 0,1 1,0 1,0 0))"));
  std::vector<fp::Disk> disks = lattice_without({210, 85, 86});
  Rng rng(7);
  Insertion insertion = s.insertion(disks, rng, 2 * kR);
  const fp::Radii radii = fp::Radii::constant(kR);
  const std::size_t before = disks.size();
  ASSERT_EQ(insertion.insert(disks, 2, radii.distribution(), rng), 2U);
  ASSERT_EQ(disks.size(), before + 2);
  const fp::Point big{(lattice_centre(85).x + lattice_centre(86).x) / 2, lattice_centre(85).y};
  // In the larger hole the clearance is largest midway between the two missing centres (1.236 kR,
  // against kR in the single hole).
  EXPECT_LE(distance(disks[before].centre, big), insertion.spacing() / 4);
  EXPECT_LE(distance(disks[before + 1].centre, lattice_centre(210)), insertion.spacing() / 4);
  EXPECT_EQ(disks[before + 1].radius, kR);
}

TEST(JamInsertion, EachHoleTakesOneDiskOfARound) {
  // The hole of two missing disks (85 and 86) has the most room, 1.236 kR midway, and its lattice
  // points the largest clearances before the round (every other point lies in a gap of four
  // touching disks, with at most 0.414 kR). A round of two: the first disk goes in midway; the
  // second, with the first counted, where a point is clear of it (farther than kR from its
  // centre). Were the disks appended in the round not counted, the second would go into the same
  // hole, less than a spacing (0.71 kR) from the first.
  const Stage s(fp::Domain::from_wkt("POLYGON((0 0,1 0,1 1,0 1,0 0))"));
  std::vector<fp::Disk> disks = lattice_without({85, 86});
  for (const std::uint64_t seed : {1U, 2U, 3U, 4U, 5U}) {
    std::vector<fp::Disk> trial = disks;
    Rng rng(seed);
    Insertion insertion = s.insertion(trial, rng, 2 * kR);
    ASSERT_EQ(insertion.insert(trial, 2, fp::Radii::constant(kR).distribution(), rng), 2U);
    const fp::Disk& first = trial[disks.size()];
    const fp::Disk& second = trial[disks.size() + 1];
    const fp::Point mid{(lattice_centre(85).x + lattice_centre(86).x) / 2, lattice_centre(85).y};
    EXPECT_LE(distance(first.centre, mid), insertion.spacing() / 4) << "seed " << seed;
    EXPECT_GT(distance(second.centre, first.centre), kR) << "seed " << seed;
  }
}

TEST(JamInsertion, APartFarAwayLeavesTheLatticeFine) {
  // The lattice's square and a speck of a domain 1e9 away: the lattice's spacing follows the
  // disks' scale, not the box's (1e9 across, a billion billion times the square's area), so the
  // hole in the square takes the disk.
  const Stage s(
      fp::Domain::from_wkt("MULTIPOLYGON(((0 0,1 0,1 1,0 1,0 0)),((1000000000 1000000000,1000000000.5 1000000000,"
                           "1000000000.5 1000000000.5,1000000000 1000000000.5,1000000000 1000000000)))"));
  std::vector<fp::Disk> disks = lattice_without({210});
  Rng rng(9);
  Insertion insertion = s.insertion(disks, rng);
  EXPECT_LE(insertion.spacing(), kR);
  const std::size_t before = disks.size();
  ASSERT_EQ(insertion.insert(disks, 1, fp::Radii::constant(kR).distribution(), rng), 1U);
  EXPECT_LE(distance(disks[before].centre, lattice_centre(210)), insertion.spacing() / 4);
}

TEST(JamInsertion, FindsAHoleAcrossAPeriodicSide) {
  // The unit cell, periodic in x and y, with the disk at the cell's corner missing: the lattice of
  // disks moved by half a spacing, so that the missing centre (0, 0) lies on both periodic sides.
  const Stage s(fp::Domain::periodic(fp::Box{0, 0, 1, 1}));
  std::vector<fp::Disk> disks;
  for (std::size_t j = 0; j < 20; ++j) {
    for (std::size_t i = 0; i < 20; ++i) {
      if (i + j > 0) {
        disks.push_back(fp::Disk{{2 * kR * static_cast<double>(i), 2 * kR * static_cast<double>(j)}, kR});
      }
    }
  }
  Rng rng(11);
  Insertion insertion = s.insertion(disks, rng);
  ASSERT_EQ(insertion.insert(disks, 1, fp::Radii::constant(kR).distribution(), rng), 1U);
  const fp::Point c = disks.back().centre;
  EXPECT_TRUE(c.x >= 0 && c.x < 1 && c.y >= 0 && c.y < 1) << c.x << " " << c.y;
  // The nearest image of the corner.
  const double dx = std::min(c.x, 1 - c.x);
  const double dy = std::min(c.y, 1 - c.y);
  EXPECT_LE(std::hypot(dx, dy), insertion.spacing() / 4);
}

TEST(JamInsertion, OnlyInsideTheDomain) {
  // A square with a square hole that the lattice's disks leave uncovered: the hole is not the
  // domain's, so nothing goes there, however much room it has (clearances measured up to 4 kR: 4
  // times the gap's); the disk goes into the one gap left.
  const Stage s(fp::Domain::from_wkt("POLYGON((0 0,1 0,1 1,0 1,0 0),(0.3 0.3,0.7 0.3,0.7 0.7,0.3 0.7,0.3 0.3))"));
  std::vector<fp::Disk> disks;
  for (const fp::Disk& d : lattice_without({44})) {
    if (!(d.centre.x > 0.3 && d.centre.x < 0.7 && d.centre.y > 0.3 && d.centre.y < 0.7)) {  // (the rest touch it)
      disks.push_back(d);
    }
  }
  Rng rng(5);
  Insertion insertion = s.insertion(disks, rng, 4 * kR);
  const std::size_t before = disks.size();
  ASSERT_EQ(insertion.insert(disks, 1, fp::Radii::constant(kR).distribution(), rng), 1U);
  EXPECT_LE(distance(disks[before].centre, lattice_centre(44)), insertion.spacing() / 4);
  EXPECT_EQ(s.domain.locate(disks[before].centre), fp::Location::inside);
}

TEST(JamDiskCells, FindEveryDiskWithinReachAcrossPeriodicSides) {
  // Disks at random points of a periodic cell: for each, the cells around its own list every disk
  // whose nearest image lies within reach (checked against all pairs).
  Rng rng(1);
  std::vector<fp::Disk> disks;
  for (int i = 0; i < 400; ++i) {
    disks.push_back(fp::Disk{{rng.uniform() * 3, 1 + rng.uniform() * 2}, 0.01});
  }
  const fp::Box cell{0, 1, 3, 3};
  for (const bool wrap : {false, true}) {
    DiskCells cells;
    const double reach = 0.3;
    cells.build(disks, cell, wrap, wrap, reach);
    const auto image = [&](double d, double period) { return wrap ? d - period * std::round(d / period) : d; };
    for (std::size_t i = 0; i < disks.size(); ++i) {
      std::vector<bool> seen(disks.size(), false);
      cells.neighbours(cells.cell_of(disks[i].centre), [&](std::size_t k) {
        for (std::uint32_t e = cells.begin(k); e < cells.end(k); ++e) {
          seen[cells.item(e)] = true;
        }
      });
      for (std::size_t j = 0; j < disks.size(); ++j) {
        const double dx = image(disks[j].centre.x - disks[i].centre.x, 3);
        const double dy = image(disks[j].centre.y - disks[i].centre.y, 2);
        if (std::hypot(dx, dy) <= reach) {
          ASSERT_TRUE(seen[j]) << "wrap " << wrap << ": disk " << j << " near " << i;
        }
      }
    }
  }
}
