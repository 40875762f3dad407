// The wall chain's verifier (src/walls/wall_chain.hpp), fed planted failures: what a deck says
// about its walls ("no gap a disk of radius rmin could pass", every ring closed, every wall disk
// outside) is refused when it does not hold, naming the ring and the place.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "decks/wall_chain.hpp"
#include "frontpack/domain.hpp"
#include "frontpack/errors.hpp"

namespace {

namespace fp = frontpack;
namespace fd = frontpack::detail;

const fp::Domain kSquare = fp::Domain::from_wkt("POLYGON((0 0,1 0,1 1,0 1,0 0))");
constexpr double kWall = 0.05;
constexpr double kRmin = 0.05;

// The verifier's message for `chain` along the square's ring, or "" if it accepts the chain.
std::string verdict(const std::vector<fd::ChainDisk>& chain) {
  const fp::Domain outside = fd::wall_complement(kSquare, kWall, kRmin);
  try {
    fd::verify_wall_chain(outside, kSquare.polygons()[0].outer, chain, kWall, kRmin, "the outer ring of polygon 1");
  } catch (const fp::OptionError& e) {
    return e.what();
  }
  return "";
}

std::vector<fd::ChainDisk> built_chain() {
  const fp::Domain outside = fd::wall_complement(kSquare, kWall, kRmin);
  return fd::ring_walls(outside, kSquare.polygons()[0].outer, kWall).chain;
}

TEST(WallChain, TheBuiltChainIsAccepted) {
  const std::vector<fd::ChainDisk> chain = built_chain();
  ASSERT_GT(chain.size(), 80U);
  EXPECT_EQ(verdict(chain), "");
}

TEST(WallChain, AGapIsRefused) {
  std::vector<fd::ChainDisk> chain = built_chain();
  chain.erase(chain.begin() + 10, chain.begin() + 20);  // ten disks out along the bottom edge
  const std::string m = verdict(chain);
  EXPECT_NE(m.find("the outer ring of polygon 1 leave a gap between"), std::string::npos) << m;
  EXPECT_NE(m.find("that a disk of radius 0.05 could pass"), std::string::npos) << m;
}

TEST(WallChain, AChainAroundOneCornerOnlyIsRefused) {
  // What a wall radius below the coordinates' precision gave: three disks at one corner, no gap
  // between them, and the rest of the ring open.
  std::vector<fd::ChainDisk> chain = built_chain();
  chain.resize(3);
  const std::string m = verdict(chain);
  EXPECT_NE(m.find("does not cover the outer ring of polygon 1: its vertex (1 0)"), std::string::npos) << m;
}

TEST(WallChain, ADiskInsideTheDomainIsRefused) {
  std::vector<fd::ChainDisk> chain = built_chain();
  chain[5].disk.centre.y = -0.5 * kWall;  // overlaps the bottom edge
  const std::string m = verdict(chain);
  EXPECT_NE(m.find("is not outside the domain"), std::string::npos) << m;
}

TEST(WallChain, PrecisionFloorFollowsTheCoordinates) {
  EXPECT_NEAR(fd::wall_radius_floor(fp::Box{0, 0, 1, 1}), 1.78e-9, 0.01e-9);
  EXPECT_NEAR(fd::wall_radius_floor(fp::Box{-1e6, 0, 0, 1}) / fd::wall_radius_floor(fp::Box{0, 0, 1, 1}), 0x1p19, 1e-9);
}

}  // namespace
