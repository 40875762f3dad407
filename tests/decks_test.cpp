// Types (size classes, regions), typed files read back, and the LAMMPS deck's wall disks:
// outside the domain (exactly), closing every ring, never touching a packed disk.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "frontpack/frontpack.hpp"

namespace fp = frontpack;

namespace {

fp::Domain shape(const std::string& name) {
  return fp::Domain::from_wkt_file(std::string(FRONTPACK_SHAPES_DIR) + "/" + name + ".wkt");
}

fp::Packing fill(const fp::Domain& d, double rmin, double rmax) {
  fp::FillOptions o;
  o.radii = fp::Radii::uniform(rmin, rmax);
  o.seed = 5;
  return fp::fill(d, o);
}

}  // namespace

TEST(Types, SizeClassesByBinEdges) {
  const fp::TypeRule rule = fp::parse_type_rule("size:1,2");
  EXPECT_EQ(rule.count(), 3U);
  const std::vector<fp::Disk> disks = {{{0, 0}, 0.5}, {{0, 0}, 1}, {{0, 0}, 1.5}, {{0, 0}, 2}, {{0, 0}, 7}};
  EXPECT_EQ(fp::assign_types(rule, disks), (std::vector<std::uint32_t>{1, 2, 2, 3, 3}));
}

TEST(Types, RegionsByClosedRegionFirstWins) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "frontpack_types_test";
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "a.wkt") << "POLYGON((0 0,1 0,1 1,0 1,0 0))";
  std::ofstream(dir / "b.wkt") << "POLYGON((0.5 0,2 0,2 1,0.5 1,0.5 0))";
  const fp::TypeRule rule = fp::parse_type_rule("region:" + (dir / "a.wkt").string() + "," + (dir / "b.wkt").string());
  EXPECT_EQ(rule.count(), 3U);
  // On a's boundary (x = 1) is in a; in both, a wins; only in b; in neither.
  const std::vector<fp::Disk> disks = {{{1, 0.5}, 0.1}, {{0.7, 0.5}, 0.1}, {{1.5, 0.5}, 0.1}, {{3, 0.5}, 0.1}};
  EXPECT_EQ(fp::assign_types(rule, disks), (std::vector<std::uint32_t>{2, 2, 3, 1}));
  std::filesystem::remove_all(dir);
}

TEST(Types, BadRulesAreOptionErrors) {
  for (const char* spec : {"size:", "size:2,1", "size:1,1", "size:0", "size:x", "size:1,,2", "bins:1", "size"}) {
    EXPECT_THROW((void)fp::parse_type_rule(spec), fp::OptionError) << spec;
  }
  EXPECT_THROW((void)fp::parse_type_rule("region:/nonexistent/a.wkt"), fp::IoError);
  EXPECT_THROW((void)fp::parse_densities("1:2500", 2), fp::OptionError);
  EXPECT_THROW((void)fp::parse_densities("1:2500,1:3", 1), fp::OptionError);
  EXPECT_THROW((void)fp::parse_densities("3:1", 2), fp::OptionError);
  EXPECT_THROW((void)fp::parse_densities("-1", 2), fp::OptionError);
  EXPECT_EQ(fp::parse_densities("2:7800,1:2500", 2), (std::vector<double>{2500, 7800}));
}

TEST(Types, TypedCsvAndYadeReadBack) {
  const fp::Domain d = shape("l_shape");
  const fp::Packing p = fill(d, 0.02, 0.05);
  const std::vector<std::uint32_t> types = fp::assign_types(fp::size_types({0.035}), p.disks);
  std::ostringstream csv;
  std::ostringstream yade;
  fp::write_csv(csv, p.disks, types);
  fp::write_yade(yade, p.disks, types);
  EXPECT_EQ(csv.str().substr(0, 11), "x,y,r,type\n");
  EXPECT_EQ(yade.str().substr(0, 22), "#format x_y_z_r_matId\n");
  for (const std::string& text : {csv.str(), yade.str()}) {
    std::istringstream in(text);
    std::vector<std::uint32_t> got;
    const std::vector<fp::Disk> disks = text[0] == 'x' ? fp::read_csv(in, "t", got) : fp::read_yade(in, "t", got);
    EXPECT_EQ(disks, p.disks);
    EXPECT_EQ(got, types);
  }
  // Untyped Yade text has no header line: SpherePack.load refuses any '#' line.
  std::ostringstream plain;
  fp::write_yade(plain, p.disks);
  EXPECT_NE(plain.str()[0], '#');
  std::ostringstream vtp;
  fp::write_vtp(vtp, p.disks, types);
  EXPECT_NE(vtp.str().find("<DataArray type=\"Int32\" Name=\"type\""), std::string::npos);
  EXPECT_THROW(fp::write_csv(csv, p.disks, std::vector<std::uint32_t>(3, 1)), fp::OptionError);
}

// The wall disks lie outside the domain (their centres farther than their radius from every
// packed disk's contact, checked here against the packing in floating point with the 1e-6 gap),
// and consecutive chain disks leave no gap of 2 rmin.
TEST(Walls, OutsideClosedAndClearOfThePacking) {
  for (const char* name : {"gear", "plate_with_holes", "annulus", "comb", "islands"}) {
    const fp::Domain d = shape(name);
    const double rmin = 0.01 * std::max(d.bbox().width(), d.bbox().height());
    const fp::Packing p = fill(d, rmin, 2 * rmin);
    const std::vector<fp::Disk> walls = fp::wall_disks(d, rmin, rmin);
    ASSERT_FALSE(walls.empty()) << name;
    for (const fp::Disk& w : walls) {
      ASSERT_EQ(d.locate(w.centre), fp::Location::outside) << name;
      ASSERT_FALSE(d.contains(fp::Disk{w.centre, 0})) << name;
    }
    std::size_t touching = 0;
    for (const fp::Disk& w : walls) {
      for (const fp::Disk& f : p.disks) {
        const double gap = std::hypot(w.centre.x - f.centre.x, w.centre.y - f.centre.y) - (w.radius + f.radius);
        ASSERT_GT(gap, 0) << name << ": wall disk overlaps a packed disk";
        touching += gap < 1e-3 * rmin ? 1 : 0;
      }
    }
    EXPECT_GT(touching, 0U) << name << ": the walls should touch the packing's outer layer";
  }
}

TEST(Walls, TooLargeForASmallHoleIsRefused) {
  // A hole 0.01 wide: no wall disk of radius 0.1 fits in it, so it cannot be walled.
  const fp::Domain d =
      fp::Domain::from_wkt("POLYGON((0 0,1 0,1 1,0 1,0 0),(0.5 0.5,0.5 0.51,0.51 0.51,0.51 0.5,0.5 0.5))");
  EXPECT_THROW((void)fp::wall_disks(d, 0.1, 0.01), fp::OptionError);
  EXPECT_NO_THROW((void)fp::wall_disks(d, 0.004, 0.01));
}

namespace {

// The message of the error `call` throws as `E`, or "" if it throws none.
template <typename E, typename F>
std::string refusal(F call) {
  try {
    call();
  } catch (const E& e) {
    return e.what();
  }
  return "";
}

}  // namespace

// A wall radius below the precision of the coordinates (1e-30 at coordinates up to 2) gave three
// wall disks at one corner, under a deck that said the walls closed every ring. It is refused,
// with the smallest wall radius that the coordinates can hold, even with no count limit.
TEST(Walls, BelowThePrecisionFloorIsRefusedNamingTheFloor) {
  const fp::Domain d = shape("l_shape");
  const fp::Budget unlimited{.max_count = 0, .memory_limit = std::numeric_limits<std::size_t>::max()};
  for (const double w : {1e-30, 1e-200, 1e-300, 1e-12}) {
    const std::string m = refusal<fp::OptionError>([&] { (void)fp::wall_disks(d, w, 0.01, unlimited); });
    EXPECT_NE(m.find("below the precision floor"), std::string::npos) << w << ": " << m;
    EXPECT_NE(m.find("use a wall radius of at least 3.6e-09"), std::string::npos) << w << ": " << m;
  }
}

// The wall-disk count is estimated before any is placed and held to the budget: 1e-10 ended in
// bad_alloc, 1e-6 made 16 million wall disks for 771 free ones.
TEST(Walls, CountIsHeldToTheBudgetBeforeAnyIsPlaced) {
  const fp::Domain d = shape("l_shape");  // perimeter 8: 16 / w wall disks along the edges
  std::string m = refusal<fp::LimitError>([&] { (void)fp::wall_disks(d, 1e-8, 0.01); });
  EXPECT_NE(m.find("about 1600"), std::string::npos) << m;
  EXPECT_NE(m.find(" wall disks, more than max_disks = 50000000; use a wall radius of at least 3.3e-07"),
            std::string::npos)
      << m;
  m = refusal<fp::LimitError>([&] { (void)fp::wall_disks(d, 1e-5, 0.01, {.max_count = 100'000}); });
  EXPECT_NE(m.find("wall disks, more than max_disks = 100000; use a wall radius of at least 0.00017"),
            std::string::npos)
      << m;
  m = refusal<fp::LimitError>(
      [&] { (void)fp::wall_disks(d, 1e-5, 0.01, {.max_count = 0, .memory_limit = 10'000'000}); });
  EXPECT_NE(m.find("wall disks, needing about"), std::string::npos) << m;
  // Through the deck: DeckOptions::budget.
  const fp::Packing p = fill(d, 0.02, 0.04);
  fp::DeckOptions o{.simulator = fp::Simulator::lammps, .densities = {2500}, .wall_radius = 1e-5};
  o.budget.max_count = 100'000;
  m = refusal<fp::LimitError>([&] { (void)fp::make_deck(d, p.disks, {}, o); });
  EXPECT_NE(m.find("wall disks, more than max_disks = 100000"), std::string::npos) << m;
  o.wall_radius = 1e-4;
  o.budget.max_count = 200'000;
  EXPECT_EQ(refusal<fp::LimitError>([&] { (void)fp::make_deck(d, p.disks, {}, o); }), "");
}

// A slit 0.05 wide and 0.5 deep: no wall disk of radius 0.1 fits in it, and the chain closed
// across its mouth with no gap, so the walls were accepted while disks of radius 0.01 could enter
// the slit, leaving the domain. The chain must cover the ring: refused, naming the slit's corner.
TEST(Walls, ASlitNoWallDiskFitsInIsRefused) {
  const fp::Domain d = fp::Domain::from_wkt("POLYGON((0 0,1 0,1 1,0.525 1,0.525 0.5,0.475 0.5,0.475 1,0 1,0 0))");
  const std::string m = refusal<fp::OptionError>([&] { (void)fp::wall_disks(d, 0.1, 0.01); });
  EXPECT_NE(m.find("does not cover the outer ring of polygon 1: its vertex (0.525 0.5)"), std::string::npos) << m;
  EXPECT_EQ(refusal<fp::OptionError>([&] { (void)fp::wall_disks(d, 0.02, 0.01); }), "");
  // The comb's notches (0.1 wide, 1 deep) the same at wall radius 0.05; walls of 0.02 fit in them.
  const fp::Domain comb = shape("comb");
  EXPECT_NE(refusal<fp::OptionError>([&] { (void)fp::wall_disks(comb, 0.05, 0.01); }).find("its vertex (1.6 0.25)"),
            std::string::npos);
  EXPECT_EQ(refusal<fp::OptionError>([&] { (void)fp::wall_disks(comb, 0.02, 0.01); }), "");
  // A narrow outside corner deeper than 2 (w + rmin) is closed by the disk where the offset lines
  // meet (or the one just before it): accepted.
  EXPECT_EQ(refusal<fp::OptionError>([&] { (void)fp::wall_disks(shape("concave_polygon"), 0.02, 0.01); }), "");
}
