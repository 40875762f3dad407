// RadiusClasses (src/generate/void_buckets.hpp), the void buckets' radius classes: its table lookup gives
// exactly the class a binary search over the same floors gives, for radii across and beyond the
// range, at and next to every floor, for ranges from a few ulps wide to 600 orders of magnitude.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "generate/void_buckets.hpp"

namespace {

using frontpack::detail::RadiusClasses;

constexpr double kInf = std::numeric_limits<double>::infinity();

// The floors RadiusClasses documents (log-spaced, above rmin, non-decreasing) and the largest k
// with r >= floor[k], found by bisection: the reference.
template <int N>
struct Reference {
  std::array<double, static_cast<std::size_t>(N)> floor{};

  Reference(double rmin, double rmax) {
    floor.fill(kInf);
    floor[0] = -kInf;
    const double log_rmin = std::log(rmin);
    const double span = std::log(rmax) - log_rmin;
    if (!(span > 0)) {
      return;
    }
    const double above_rmin = std::nextafter(rmin, kInf);
    for (std::size_t k = 1; k < N; ++k) {
      floor[k] = std::max({std::exp(log_rmin + span * static_cast<double>(k) / N), above_rmin, floor[k - 1]});
    }
  }

  [[nodiscard]] int of(double r) const {
    std::size_t lo = 0;  // floor[lo] <= r (floor[0] = -inf), for r not NaN
    std::size_t hi = N;  // the first index above: floor[hi] > r, or N
    if (std::isnan(r)) {
      return 0;
    }
    while (hi - lo > 1) {
      const std::size_t mid = (lo + hi) / 2;
      (r >= floor[mid] ? lo : hi) = mid;
    }
    return static_cast<int>(lo);
  }
};

template <int N>
void expect_same_classes(double rmin, double rmax) {
  SCOPED_TRACE("N = " + std::to_string(N) + ", radii [" + std::to_string(rmin) + ", " + std::to_string(rmax) + "]");
  const RadiusClasses<N> classes(rmin, rmax);
  const Reference<N> ref(rmin, rmax);
  std::vector<double> radii{0.0,
                            -1.0,
                            rmin,
                            rmax,
                            std::nextafter(rmin, kInf),
                            std::nextafter(rmax, 0.0),
                            1e308,
                            5e-324,
                            std::numeric_limits<double>::quiet_NaN()};
  for (const double f : ref.floor) {
    if (std::isfinite(f)) {
      radii.insert(radii.end(), {f, std::nextafter(f, 0.0), std::nextafter(f, kInf)});
    }
  }
  std::mt19937_64 rng(N);
  std::uniform_real_distribution<double> t(-0.2, 1.2);  // a tenth of the range beyond either end
  const double log_rmin = std::log(rmin);
  const double log_span = std::log(rmax) - log_rmin;
  for (int i = 0; i < 20000; ++i) {
    radii.push_back(std::exp(log_rmin + t(rng) * log_span));
  }
  int wrong = 0;
  for (const double r : radii) {
    if (classes.of(r) != ref.of(r) && ++wrong <= 5) {
      ADD_FAILURE() << "r = " << r << ": class " << classes.of(r) << ", reference " << ref.of(r);
    }
  }
  EXPECT_EQ(wrong, 0) << "of " << radii.size() << " radii";
}

template <int N>
void expect_same_classes_on_every_range() {
  const double ranges[][2] = {
      {5e-4, 5e-3},           {1, 10},         {0.1, 1000},     {1e-5, 1}, {7, 8}, {1, 1.0000001},
      {2.5, 2.5000000000025}, {1e-300, 1e300}, {3e-308, 1e-307}};
  for (const auto& r : ranges) {
    expect_same_classes<N>(r[0], r[1]);
  }
  expect_same_classes<N>(1, std::nextafter(1.0, 2.0));  // two doubles
}

TEST(RadiusClasses, TableLookupMatchesBisection128) {
  expect_same_classes_on_every_range<128>();
}

TEST(RadiusClasses, TableLookupMatchesBisection16) {
  expect_same_classes_on_every_range<16>();
}

TEST(RadiusClasses, TableLookupMatchesBisectionTwoClasses) {
  expect_same_classes_on_every_range<2>();
}

// With rmin = rmax every radius is class 0.
TEST(RadiusClasses, EqualRadiiAreAllClassZero) {
  const RadiusClasses<128> classes(0.25, 0.25);
  for (const double r : {0.0, 0.25, 0.5, 1e300}) {
    EXPECT_EQ(classes.of(r), 0) << "r = " << r;
  }
}

// The classes are log-spaced: rmax's class is the last, and radii a factor (rmax / rmin)^(1/N)
// apart are a class apart.
TEST(RadiusClasses, LogSpaced) {
  const RadiusClasses<128> classes(1, 10);
  EXPECT_EQ(classes.of(10), 127);
  EXPECT_EQ(classes.of(1), 0);
  const double step = std::pow(10.0, 1.0 / 128);
  EXPECT_EQ(classes.of(std::pow(step, 64.5)), 64);
  EXPECT_EQ(classes.of(std::pow(step, 65.5)), 65);
}

}  // namespace
