// Pinned packings: the exact bits of a few fills, so that a change meant to leave every packing
// as it was (a faster scan, a smaller index) is checked to do so, and one that changes them says
// so by failing here. Updating a pin is a decision: the commit that does it says why, and
// docs/density.md is measured again.
//
// The open and boundary fronts compute with +, -, *, / and square roots alone (correctly rounded
// everywhere; the boundary's wall lengths and corner turns included, no longer std::hypot and
// std::atan2, whose last bits differ between C libraries). The only C library functions left
// (std::log and std::exp for the void classes' floors) decide thresholds, where a last bit
// matters only in a near tie; the closed form accumulates std::atan2 and is not pinned. The pins
// were taken on x86-64 with glibc (GCC 12 and Clang 14 agree: CI runs the suite built with each,
// the `release` and `clang` presets); elsewhere the tests are skipped.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <numbers>
#include <ostream>
#include <string>

#include "frontpack/frontpack.hpp"
#include "test_support.hpp"

namespace fp = frontpack;

namespace {

// FNV-1a over the count and the bits of every centre and radius, in order.
std::uint64_t fingerprint(const fp::Packing& p) {
  std::uint64_t h = 1469598103934665603ULL;
  const auto mix = [&h](std::uint64_t v) {
    for (int i = 0; i < 8; ++i) {
      h ^= (v >> (8 * i)) & 0xffU;
      h *= 1099511628211ULL;
    }
  };
  mix(p.disks.size());
  for (const fp::Disk& d : p.disks) {
    mix(std::bit_cast<std::uint64_t>(d.centre.x));
    mix(std::bit_cast<std::uint64_t>(d.centre.y));
    mix(std::bit_cast<std::uint64_t>(d.radius));
  }
  return h;
}

struct Pin {
  const char* shape;
  fp::Method method;
  bool voids;
  double clearance_in_rmax;  // 0: automatic
  bool constant;             // constant radius R instead of uniform in [R, 10 R]
  std::uint64_t seed;
  std::size_t disks;
  std::uint64_t fingerprint;
};

std::string format_g(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

std::string describe(const Pin& pin) {
  return std::string(pin.shape) + ", " + fp::to_string(pin.method) + (pin.voids ? ", voids" : "") +
         (pin.clearance_in_rmax != 0 ? ", clearance " + format_g(pin.clearance_in_rmax) + " rmax" : "") +
         (pin.constant ? ", constant radius" : "") + ", seed " + std::to_string(pin.seed);
}

void PrintTo(const Pin& pin, std::ostream* os) {
  *os << describe(pin);
}

class Pinned : public ::testing::TestWithParam<Pin> {};

TEST_P(Pinned, PackingIsBitForBitThePinnedOne) {
#if !(defined(__x86_64__) && defined(__GLIBC__))
  GTEST_SKIP() << "pins are those of x86-64 with glibc";
#endif
  const Pin& pin = GetParam();
  const fp::Domain d = fp::Domain::from_wkt_file(fp::test::shapes_dir() / (std::string(pin.shape) + ".wkt"));
  // About 4,000 disks: R from the area as tools/density_table.py chooses it (E[r^2] = 37 R^2).
  const double r = pin.constant ? std::sqrt(0.8 * d.area() / (4000 * std::numbers::pi))
                                : std::sqrt(0.8 * d.area() / (4000 * std::numbers::pi * 37.0));
  fp::FillOptions o;
  o.method = pin.method;
  o.fill_voids = pin.voids;
  o.radii = pin.constant ? fp::Radii::constant(r) : fp::Radii::uniform(r, 10 * r);
  o.clearance = pin.clearance_in_rmax * (pin.constant ? r : 10 * r);
  o.seed = pin.seed;
  const fp::Packing p = fp::fill(d, o);
  char got[64];
  std::snprintf(got, sizeof got, "{%zu, 0x%016llxULL}", p.disks.size(),
                static_cast<unsigned long long>(fingerprint(p)));
  EXPECT_EQ(p.disks.size(), pin.disks) << describe(pin) << ": now " << got;
  EXPECT_EQ(fingerprint(p), pin.fingerprint) << describe(pin) << ": now " << got;
}

// The boundary method's large clearances make exact ties between disks in the way common (in
// the band the exact predicate decides, every overlap is as deep as every other); of those a full
// scan finds, the one kept must not depend on the order of the scan. (Which disks share the
// candidate's cell does matter since the disks most often in the way are tried before the scan:
// a change of the grid's cell size changes the boundary method's packings with voids, and these
// pins say so.)
INSTANTIATE_TEST_SUITE_P(
    Fills, Pinned,
    ::testing::Values(Pin{"plate_with_holes", fp::Method::open, false, 0, false, 7, 3879, 0x4ab6402df940cb92ULL},
                      Pin{"plate_with_holes", fp::Method::open, true, 0, false, 7, 3840, 0x468a1a926165b5efULL},
                      Pin{"comb", fp::Method::boundary, true, 0, false, 7, 4057, 0xd14bc7d983e1b1d7ULL},
                      Pin{"big_polygon", fp::Method::boundary, true, 0, false, 3, 4211, 0x0d7a5767fca33da3ULL},
                      Pin{"comb", fp::Method::boundary, true, 0.5, false, 7, 2021, 0x21efa115983744f3ULL},
                      Pin{"plate_with_holes", fp::Method::boundary, true, 0.1, false, 7, 3623, 0x59c811bfbce0776aULL},
                      Pin{"l_shape", fp::Method::boundary, true, 0, true, 7, 4211, 0x86ec661eab409c4bULL}));

}  // namespace
