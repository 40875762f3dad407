// Radius distributions: each one's samples against its CDF written out independently here
// (Kolmogorov-Smirnov at a fixed seed, with a threshold that a slightly wrong distribution
// fails), by-area compensation, golden first radii (bit-identical across builds), the spec
// syntax and the CSV size tables with their exact error messages.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <functional>
#include <numbers>
#include <string>
#include <vector>

#include "frontpack/frontpack.hpp"
#include "test_support.hpp"

namespace fp = frontpack;

namespace {

constexpr std::size_t kSamples = 200'000;
constexpr std::uint64_t kSeed = 20240611;

// KS critical value at significance about 0.001 for n independent samples: 1.95 / sqrt(n).
double ks_threshold(double n) {
  return 1.95 / std::sqrt(n);
}

// sup |F_n - F| for samples (sorted here), F given; both sides of every jump.
double ks_number(std::vector<double> x, const std::function<double(double)>& cdf) {
  std::sort(x.begin(), x.end());
  const auto n = static_cast<double>(x.size());
  double d = 0;
  for (std::size_t k = 0; k < x.size();) {
    std::size_t m = k;
    while (m < x.size() && x[m] == x[k]) {
      ++m;
    }
    d = std::max({d, std::abs(static_cast<double>(m) / n - cdf(x[k])),
                  std::abs(static_cast<double>(k) / n - cdf(std::nextafter(x[k], 0.0)))});
    k = m;
  }
  return d;
}

// The same with every sample weighted by r^2 (the area distribution); also returns the
// effective sample size (sum w)^2 / sum w^2 for the threshold.
double ks_area(std::vector<double> x, const std::function<double(double)>& area_cdf, double& n_eff) {
  std::sort(x.begin(), x.end());
  double total = 0;
  double total2 = 0;
  for (const double r : x) {
    total += r * r;
    total2 += r * r * r * r;
  }
  n_eff = total * total / total2;
  double d = 0;
  double acc = 0;
  for (std::size_t k = 0; k < x.size();) {
    const double before = acc;
    std::size_t m = k;
    while (m < x.size() && x[m] == x[k]) {
      acc += x[m] * x[m];
      ++m;
    }
    d = std::max(
        {d, std::abs(acc / total - area_cdf(x[k])), std::abs(before / total - area_cdf(std::nextafter(x[k], 0.0)))});
    k = m;
  }
  return d;
}

// Independent reference CDFs (not the library's code).
double phi(double z) {
  return 0.5 * std::erfc(-z / std::sqrt(2.0));
}

std::function<double(double)> normal_cdf(double mean, double sd, double lo, double hi) {
  return [=](double r) {
    if (r < lo) {
      return 0.0;
    }
    if (r >= hi) {
      return 1.0;
    }
    const double a = phi((lo - mean) / sd);
    return (phi((r - mean) / sd) - a) / (phi((hi - mean) / sd) - a);
  };
}

std::function<double(double)> lognormal_cdf(double median, double gsd, double lo, double hi) {
  const double mu = std::log(median);
  const double s = std::log(gsd);
  return [=](double r) {
    if (r < lo) {
      return 0.0;
    }
    if (r >= hi) {
      return 1.0;
    }
    const double a = phi((std::log(lo) - mu) / s);
    return (phi((std::log(r) - mu) / s) - a) / (phi((std::log(hi) - mu) / s) - a);
  };
}

// A grading curve's cumulative fraction (in its own basis), linear in log size between points.
std::function<double(double)> curve_cdf(std::vector<fp::SizeFraction> points, double scale) {
  return [points, scale](double r) {
    const double s = r * scale;  // back to the curve's sizes
    if (s <= points.front().size) {
      return 0.0;
    }
    for (std::size_t k = 1; k < points.size(); ++k) {
      if (s <= points[k].size) {
        const double t = std::log(s / points[k - 1].size) / std::log(points[k].size / points[k - 1].size);
        return points[k - 1].fraction + t * (points[k].fraction - points[k - 1].fraction);
      }
    }
    return 1.0;
  };
}

const std::vector<fp::SizeFraction> kSand = {{0.25, 0.00}, {0.30, 0.04}, {0.425, 0.16}, {0.60, 0.38},
                                             {0.85, 0.62}, {1.18, 0.83}, {1.70, 0.96},  {2.00, 1.00}};

std::string message_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const fp::OptionError& e) {
    return e.what();
  }
  return "(no OptionError)";
}

}  // namespace

TEST(Distributions, UniformMatchesItsCdf) {
  const auto x = fp::sample_radii(fp::Radii::uniform(0.01, 0.05), kSamples, kSeed);
  const auto cdf = [](double r) { return std::clamp((r - 0.01) / 0.04, 0.0, 1.0); };
  EXPECT_LT(ks_number(x, cdf), ks_threshold(kSamples));
  // A wrong range (5% too wide) fails the same threshold.
  const auto wrong = fp::sample_radii(fp::Radii::uniform(0.01, 0.052), kSamples, kSeed);
  EXPECT_GT(ks_number(wrong, cdf), ks_threshold(kSamples));
}

TEST(Distributions, NormalMatchesItsCdf) {
  const auto ref = normal_cdf(1.0, 0.2, 0.5, 1.6);
  const fp::Radii radii = fp::Radii::normal(1.0, 0.2, 0.5, 1.6);
  const auto x = fp::sample_radii(radii, kSamples, kSeed);
  EXPECT_LT(ks_number(x, ref), ks_threshold(kSamples));
  EXPECT_TRUE(std::all_of(x.begin(), x.end(), [](double r) { return r >= 0.5 && r <= 1.6; }));
  // A standard deviation 3% off fails.
  const auto wrong = fp::sample_radii(fp::Radii::normal(1.0, 0.206, 0.5, 1.6), kSamples, kSeed);
  EXPECT_GT(ks_number(wrong, ref), ks_threshold(kSamples));
  // The library's own cdf agrees with the reference, and inverts its quantile.
  const fp::RadiusDistribution& d = radii.distribution();
  for (double r = 0.5; r <= 1.6; r += 0.01) {
    EXPECT_NEAR(d.cdf(r), ref(r), 1e-14) << r;
  }
  for (double u = 0.0005; u < 1; u += 0.001) {
    EXPECT_NEAR(d.cdf(d.quantile(u)), u, 1e-13) << u;
  }
}

TEST(Distributions, NormalTailWindowsAreAccurate) {
  // Windows far in either tail (mean 3, sd 0.25: [5, 6] is 8 to 12 sd above the mean, [0.5, 1]
  // 10 to 8 sd below), where cdf differences of the untruncated law would be all rounding.
  for (const auto& window : {std::pair{5.0, 6.0}, std::pair{0.5, 1.0}}) {
    // Plain variables, not structured bindings: the lambdas below capture them, which C++20
    // allows but Clang before 16 refuses.
    const double lo = window.first;
    const double hi = window.second;
    const fp::Radii radii = fp::Radii::normal(3.0, 0.25, lo, hi);
    const auto x = fp::sample_radii(radii, 50'000, kSeed);
    // Reference: upper-tail probabilities Q(z) = Phi(-z) for the upper window, Phi(z) below.
    const auto q = [](double r) { return phi(-(r - 3.0) / 0.25); };
    const auto cdf = [&](double r) {
      r = std::clamp(r, lo, hi);
      return lo > 3 ? (q(lo) - q(r)) / (q(lo) - q(hi))
                    : (phi((r - 3) / 0.25) - phi((lo - 3) / 0.25)) / (phi((hi - 3) / 0.25) - phi((lo - 3) / 0.25));
    };
    EXPECT_LT(ks_number(x, cdf), ks_threshold(50'000)) << lo << " " << hi;
    EXPECT_TRUE(std::all_of(x.begin(), x.end(), [&](double r) { return r >= lo && r <= hi; }));
  }
}

TEST(Distributions, LognormalMatchesItsCdf) {
  const auto ref = lognormal_cdf(1.0, 1.5, 0.3, 4.0);
  const auto x = fp::sample_radii(fp::Radii::lognormal(1.0, 1.5, 0.3, 4.0), kSamples, kSeed);
  EXPECT_LT(ks_number(x, ref), ks_threshold(kSamples));
  const auto wrong = fp::sample_radii(fp::Radii::lognormal(1.0, 1.55, 0.3, 4.0), kSamples, kSeed);
  EXPECT_GT(ks_number(wrong, ref), ks_threshold(kSamples));
  // Area cdf: against the samples weighted by r^2.
  const fp::Radii radii = fp::Radii::lognormal(1.0, 1.5, 0.3, 4.0);
  const fp::RadiusDistribution& d = radii.distribution();
  double n_eff = 0;
  EXPECT_LT(ks_area(
                x, [&d](double r) { return d.area_cdf(r); }, n_eff),
            ks_threshold(n_eff));
}

TEST(Distributions, DiscreteByNumberAndByArea) {
  const std::vector<fp::SizeFraction> classes = {{1.0, 0.5}, {2.0, 0.3}, {3.0, 0.2}};
  const auto number_cdf = [](double r) { return r < 1 ? 0.0 : r < 2 ? 0.5 : r < 3 ? 0.8 : 1.0; };
  const auto x = fp::sample_radii(fp::Radii::discrete(classes), kSamples, kSeed);
  EXPECT_LT(ks_number(x, number_cdf), ks_threshold(kSamples));
  // By area: the same fractions are of the area; the number fractions are f / r^2, normalised.
  const fp::Radii by_area = fp::Radii::discrete(classes, fp::Basis::area);
  const auto y = fp::sample_radii(by_area, kSamples, kSeed);
  double n_eff = 0;
  EXPECT_LT(ks_area(y, number_cdf, n_eff), ks_threshold(n_eff));
  EXPECT_GT(ks_area(x, number_cdf, n_eff), ks_threshold(n_eff)) << "no compensation must fail";
  const double w1 = 0.5 / 1;
  const double w2 = 0.3 / 4;
  const double w3 = 0.2 / 9;
  EXPECT_NEAR(by_area.distribution().cdf(1.5), w1 / (w1 + w2 + w3), 1e-15);
  EXPECT_NEAR(by_area.distribution().area_cdf(2.5), 0.8, 1e-15);
  EXPECT_EQ(by_area.distribution().class_radii(), (std::vector<double>{1, 2, 3}));
  // Diameters are halved exactly.
  const fp::Radii d = fp::Radii::discrete(classes, fp::Basis::number, fp::SizeKind::diameter);
  EXPECT_EQ(d.min(), 0.5);
  EXPECT_EQ(d.max(), 1.5);
}

TEST(Distributions, GradingCurveByNumber) {
  const fp::Radii radii = fp::Radii::grading_curve(kSand, fp::Basis::number, fp::SizeKind::diameter);
  EXPECT_EQ(radii.min(), 0.125);
  EXPECT_EQ(radii.max(), 1.0);
  const auto ref = curve_cdf(kSand, 2.0);
  const auto x = fp::sample_radii(radii, kSamples, kSeed);
  EXPECT_LT(ks_number(x, ref), ks_threshold(kSamples));
  for (double r = 0.125; r <= 1; r += 0.01) {
    EXPECT_NEAR(radii.distribution().cdf(r), ref(r), 1e-14);
  }
}

TEST(Distributions, GradingCurveByAreaIsCompensated) {
  const fp::Radii radii = fp::Radii::grading_curve(kSand, fp::Basis::area, fp::SizeKind::diameter);
  const auto ref = curve_cdf(kSand, 2.0);
  const auto x = fp::sample_radii(radii, kSamples, kSeed);
  double n_eff = 0;
  const double d = ks_area(x, ref, n_eff);
  EXPECT_LT(d, ks_threshold(n_eff)) << "n_eff " << n_eff;
  // Drawing by number from the same curve (no compensation) is far off by area.
  const auto uncompensated =
      fp::sample_radii(fp::Radii::grading_curve(kSand, fp::Basis::number, fp::SizeKind::diameter), kSamples, kSeed);
  EXPECT_GT(ks_area(uncompensated, ref, n_eff), 0.1);
  // The library's area cdf is the curve itself.
  for (double r = 0.125; r <= 1; r += 0.01) {
    EXPECT_NEAR(radii.distribution().area_cdf(r), ref(r), 1e-14);
  }
  // mean_square agrees with the samples.
  double m2 = 0;
  for (const double r : x) {
    m2 += r * r;
  }
  EXPECT_NEAR(m2 / static_cast<double>(x.size()) / radii.distribution().mean_square(), 1.0, 0.005);
}

// The first radii for a fixed seed, as exact hex-float literals: the same in every build that
// uses the same C math library (Release and the ASan RelWithDebInfo build included).
TEST(Distributions, GoldenFirstRadii) {
  const auto first = [](const fp::Radii& r) { return fp::sample_radii(r, 4, 7); };
  EXPECT_EQ(first(fp::Radii::uniform(0.01, 0.05)), (std::vector<double>{0x1.377c22843c209p-5, 0x1.5a85bc6212a44p-6,
                                                                        0x1.650c939162c85p-5, 0x1.9367f655e99a3p-5}));
  EXPECT_EQ(
      first(fp::Radii::normal(1.0, 0.2, 0.5, 1.6)),
      (std::vector<double>{0x1.1b11a8adb3e72p+0, 0x1.c52ed7a5b430ep-1, 0x1.32cf1bc17d239p+0, 0x1.6909620cbc111p+0}));
  EXPECT_EQ(
      first(fp::Radii::lognormal(1.0, 1.5, 0.3, 4.0)),
      (std::vector<double>{0x1.3cf2ed6b09e6p+0, 0x1.941c618e16455p-1, 0x1.7ee28411d3b8bp+0, 0x1.2867607dfa787p+1}));
  EXPECT_EQ(first(fp::Radii::discrete({{1.0, 0.5}, {2.0, 0.3}, {3.0, 0.2}}, fp::Basis::area)),
            (std::vector<double>{0x1p+0, 0x1p+0, 0x1p+1, 0x1.8p+1}));
  EXPECT_EQ(
      first(fp::Radii::grading_curve(kSand, fp::Basis::number)),
      (std::vector<double>{0x1.ed92c0eac3a5cp-2, 0x1.061e48f73dc8ep-2, 0x1.365c075d228bep-1, 0x1.da2693c71f3b1p-1}));
  EXPECT_EQ(
      first(fp::Radii::grading_curve(kSand, fp::Basis::area)),
      (std::vector<double>{0x1.193b7426754cfp-2, 0x1.52e30dbef721p-3, 0x1.69aa1cbc06e72p-2, 0x1.46bc6ccbe4cfep-1}));
}

TEST(Distributions, SameSeedSameRadii) {
  for (const char* spec :
       {"uniform:1,2", "normal:1,0.1", "lognormal:1,1.3", "discrete:1:0.2,2:0.8@area", "curve:0.25:0,0.5:0.3,1:1"}) {
    const fp::Radii r = fp::parse_radii(spec);
    EXPECT_EQ(fp::sample_radii(r, 1000, 99), fp::sample_radii(r, 1000, 99)) << spec;
    EXPECT_NE(fp::sample_radii(r, 1000, 99), fp::sample_radii(r, 1000, 100)) << spec;
  }
  // fill draws the same stream: its disks (one polygon, none culled in the middle) carry the
  // radii in drawing order, from the fourth on after the three seeds of the closed form.
  const fp::Domain d = fp::Domain::from_wkt("POLYGON((0 0,1 0,1 1,0 1,0 0))");
  fp::FillOptions o;
  o.radii = fp::parse_radii("normal:0.02,0.004");
  o.seed = 5;
  const fp::Packing a = fp::fill(d, o);
  const fp::Packing b = fp::fill(d, o);
  EXPECT_EQ(a.disks, b.disks);
  const auto drawn = fp::sample_radii(o.radii, 3, 5);
  for (std::size_t k = 0; k < 3; ++k) {
    EXPECT_EQ(a.disks[k].radius, drawn[k]);
  }
}

TEST(Distributions, FactoryErrors) {
  using fp::SizeFraction;
  EXPECT_EQ(message_of([] { (void)fp::Radii::uniform(0.2, 0.1); }), "radius: rmin (0.2) must not exceed rmax (0.1)");
  EXPECT_EQ(message_of([] { (void)fp::Radii::constant(NAN); }),
            "radius: the radius must be a finite number > 0, got nan");
  EXPECT_EQ(message_of([] { (void)fp::Radii::normal(1, 0, 0.5, 1.5); }),
            "radius: normal: the standard deviation must be a finite number > 0, got 0");
  EXPECT_EQ(message_of([] { (void)fp::Radii::normal(1, 0.1, 1.5, 0.5); }),
            "radius: normal: the lower bound (1.5) must be less than the upper bound (0.5)");
  EXPECT_EQ(message_of([] { (void)fp::Radii::normal(1, 0.01, 2, 3); }),
            "radius: normal: the truncation bounds [2, 3] keep a probability of 0 (less than 1e-300) of the "
            "distribution");
  EXPECT_EQ(message_of([] { (void)fp::Radii::normal(1, 0.1, -1, 3); }),
            "radius: normal: the lower bound must be a finite number > 0, got -1");
  EXPECT_EQ(message_of([] { (void)fp::Radii::lognormal(1, 1, 0.5, 2); }),
            "radius: lognormal: the geometric standard deviation must be a finite number > 1, got 1");
  EXPECT_EQ(message_of([] {
              (void)fp::Radii::discrete({{1, 0.5}, {2, 0.6}});
            }),
            "radius: discrete: the fractions must add up to 1, they add up to 1.1");
  EXPECT_EQ(message_of([] {
              (void)fp::Radii::discrete({{1, 0.5}, {-2, 0.5}});
            }),
            "radius: discrete: class 2: the radius must be a finite number > 0, got -2");
  EXPECT_EQ(message_of([] {
              (void)fp::Radii::discrete({{1, 1.5}, {2, -0.5}});
            }),
            "radius: discrete: class 1: the fraction must be a number in [0, 1], got 1.5");
  EXPECT_EQ(message_of([] {
              (void)fp::Radii::discrete({{1, 0.5}, {1, 0.5}});
            }),
            "radius: discrete: two classes have the same radius 1");
  EXPECT_EQ(message_of([] {
              (void)fp::Radii::grading_curve({{1, 0}, {0.5, 1}});
            }),
            "radius: grading curve: point 2: the diameter 0.5 must be larger than the previous one (1); give the "
            "points from the smallest size to the largest");
  EXPECT_EQ(message_of([] {
              (void)fp::Radii::grading_curve({{1, 0}, {2, 0.6}, {3, 0.5}, {4, 1}});
            }),
            "radius: grading curve: point 3: the fraction passing 0.5 is less than the previous one (0.6); a "
            "grading curve never decreases");
  EXPECT_EQ(message_of([] {
              (void)fp::Radii::grading_curve({{1, 0}, {2, 0.9}});
            }),
            "radius: grading curve: the last point must pass 1 (the largest size bounds the curve), got 0.9");
  EXPECT_EQ(message_of([] {
              (void)fp::Radii::grading_curve({{1, 0.1}, {2, 1}});
            }),
            "radius: grading curve: the first point must pass 0 (the smallest size bounds the curve), got 0.1");
  EXPECT_EQ(message_of([] {
              (void)fp::Radii::grading_curve({{1, 0}, {2, NAN}});
            }),
            "radius: grading curve: point 2: the fraction passing must be a number in [0, 1], got nan");
  EXPECT_EQ(message_of([] {
              (void)fp::Radii::grading_curve({{1, 0}});
            }),
            "radius: grading curve: at least 2 points are needed, got 1");
}

TEST(ParseRadii, Syntax) {
  EXPECT_EQ(fp::parse_radii("uniform:0.01,0.05").describe(), "uniform: radius in [0.01, 0.05]");
  EXPECT_EQ(fp::parse_radii("constant:0.1").describe(), "constant: radius 0.1");
  EXPECT_EQ(fp::parse_radii("normal:1,0.1").describe(), "normal: radius mean 1, sd 0.1, truncated to [0.7, 1.3]");
  EXPECT_EQ(fp::parse_radii("normal:1, 0.3, 0.5, 2").describe(),
            "normal: radius mean 1, sd 0.3, truncated to [0.5, 2]");
  EXPECT_EQ(fp::parse_radii("lognormal:1,2").describe(),
            "lognormal: radius median 1, geometric sd 2, truncated to [0.125, 8]");
  EXPECT_EQ(fp::parse_radii("discrete:1:0.25,2:0.75").describe(),
            "discrete: 2 classes of radius [1, 2], fractions by number (sizes given as radius)");
  EXPECT_EQ(fp::parse_radii("discrete:2:0.25,4:0.75@area@diameter").describe(),
            "discrete: 2 classes of radius [1, 2], fractions by area (sizes given as diameter)");
  EXPECT_EQ(fp::parse_radii("curve:0.5:0,1:0.4,2:1").describe(),
            "grading curve: 3 points, radius [0.25, 1], passing by area (sizes given as diameter)");
  EXPECT_EQ(fp::parse_radii("curve:0.5:0,1:1@number@radius").describe(),
            "grading curve: 2 points, radius [0.5, 1], passing by number (sizes given as radius)");
  const std::string file = (fp::test::data_dir() / "sand_grading.csv").string();
  EXPECT_EQ(fp::parse_radii("curve:" + file).describe(),
            "grading curve: 8 points, radius [0.125, 1], passing by area (sizes given as diameter)");
  // The file form and the inline form are the same distribution.
  EXPECT_EQ(fp::sample_radii(fp::parse_radii("curve:" + file), 100, 1),
            fp::sample_radii(fp::Radii::grading_curve(kSand, fp::Basis::area, fp::SizeKind::diameter), 100, 1));
}

TEST(ParseRadii, Errors) {
  const auto msg = [](const std::string& spec) { return message_of([&spec] { (void)fp::parse_radii(spec); }); };
  EXPECT_EQ(msg("gauss:1"),
            "radius 'gauss:1': unknown distribution 'gauss'; expected uniform:RMIN,RMAX or constant:R or "
            "normal:MEAN,SD[,LO,HI] or lognormal:MEDIAN,GSD[,LO,HI] or discrete:S:F,...[@area] or discrete:FILE.csv "
            "or curve:D:P,...[@number] or curve:FILE.csv");
  EXPECT_EQ(msg("0.1").rfind("radius '0.1': expected uniform:RMIN,RMAX or constant:R", 0), 0U);
  EXPECT_EQ(msg("uniform:0.2,0.1"), "radius 'uniform:0.2,0.1': rmin (0.2) must not exceed rmax (0.1)");
  EXPECT_EQ(msg("constant:nan"), "radius 'constant:nan': the radius must be a finite number > 0, got nan");
  EXPECT_EQ(msg("uniform:1"), "radius 'uniform:1': uniform takes RMIN,RMAX, got 1 value");
  EXPECT_EQ(msg("uniform:1,x"), "radius 'uniform:1,x': 'x' is not a number (uniform:RMIN,RMAX)");
  EXPECT_EQ(msg("normal:0.1,0.05"),
            "radius 'normal:0.1,0.05': normal: the default lower bound MEAN - 3 SD = -0.05000000000000002 (MEAN "
            "'0.1', SD '0.05') is not > 0; give the bounds: normal:MEAN,SD,LO,HI");
  // Bounds the user did not give are named by the numbers given, as written (they were named by a
  // bound of 0, or of 0.05 twice, that the user never wrote).
  EXPECT_EQ(msg("lognormal:0.05,1e308"),
            "radius 'lognormal:0.05,1e308': lognormal: the default lower bound MEDIAN / GSD^3 (MEDIAN '0.05', GSD "
            "'1e308') underflows to 0; give the bounds: lognormal:MEDIAN,GSD,LO,HI");
  EXPECT_EQ(msg("lognormal:1e300,1e10"),
            "radius 'lognormal:1e300,1e10': lognormal: the default upper bound MEDIAN * GSD^3 (MEDIAN '1e300', GSD "
            "'1e10') overflows to infinity; give the bounds: lognormal:MEDIAN,GSD,LO,HI");
  EXPECT_EQ(msg("normal:0.05,1e-320"),
            "radius 'normal:0.05,1e-320': normal: the default bounds MEAN -/+ 3 SD (MEAN '0.05', SD '1e-320') round "
            "to the same number, 0.05: SD is below the precision of MEAN; give the bounds: normal:MEAN,SD,LO,HI");
  EXPECT_EQ(msg("normal:1.7e308,1e307"),
            "radius 'normal:1.7e308,1e307': normal: the default upper bound MEAN + 3 SD (MEAN '1.7e308', SD '1e307') "
            "overflows to infinity; give the bounds: normal:MEAN,SD,LO,HI");
  // Numbers out of the range of doubles (the same rule and words as every reader).
  EXPECT_EQ(msg("constant:1e-400"),
            "radius 'constant:1e-400': '1e-400' is out of the range of a double (underflows to 0)");
  EXPECT_EQ(msg("uniform:0.01, 1e400"),
            "radius 'uniform:0.01, 1e400': '1e400' is out of the range of a double (overflows to infinity)");
  EXPECT_EQ(msg("discrete:1:0.5,2e-999:0.5"),
            "radius 'discrete:1:0.5,2e-999:0.5': discrete: item 2: '2e-999' is out of the range of a double "
            "(underflows to 0)");
  // A token is quoted escaped and cut to 40 characters.
  EXPECT_EQ(msg("constant:" + std::string(100, '1') + "x"), "radius 'constant:" + std::string(100, '1') + "x': '" +
                                                                std::string(40, '1') +
                                                                "...' (101 characters) is not a number (constant:R)");
  EXPECT_EQ(msg("constant:1\x1b"), "radius 'constant:1\\x1B': '1\\x1B' is not a number (constant:R)");
  EXPECT_EQ(msg("normal:1,0.1,0.5"), "radius 'normal:1,0.1,0.5': normal takes MEAN,SD or MEAN,SD,LO,HI, got 3 values");
  EXPECT_EQ(msg("uniform:1,2@area"), "radius 'uniform:1,2@area': @ modifiers apply to discrete: and curve: only");
  EXPECT_EQ(msg("discrete:1:0.5,2:0.5@mass"),
            "radius 'discrete:1:0.5,2:0.5@mass': unknown modifier '@mass'; expected @area, @number, @radius or "
            "@diameter");
  EXPECT_EQ(msg("discrete:1:0.5,2:0.5@area@number"),
            "radius 'discrete:1:0.5,2:0.5@area@number': modifier '@number' conflicts with or repeats an earlier one");
  EXPECT_EQ(msg("discrete:1:0.5,2"),
            "radius 'discrete:1:0.5,2': discrete: item 2 '2' is not SIZE:FRACTION (two numbers)");
  EXPECT_EQ(msg("discrete:1:0.5,2:0.4"),
            "radius 'discrete:1:0.5,2:0.4': discrete: the fractions must add up to 1, they add up to 0.9");
  EXPECT_EQ(msg("curve:1:0,0.5:1"),
            "radius 'curve:1:0,0.5:1': grading curve: point 2: the diameter 0.5 must be larger than the previous one "
            "(1); give the points from the smallest size to the largest");
  const std::string file = (fp::test::data_dir() / "sand_grading.csv").string();
  EXPECT_EQ(msg("discrete:" + file), "radius 'discrete:" + file + "': '" + file +
                                         "' has a 'passing' column (a grading curve): use curve:" + file);
  EXPECT_THROW((void)fp::parse_radii("curve:/nonexistent/sieve.csv"), fp::IoError);
}

TEST(SizeTable, ReadsAndNamesTheBadLine) {
  const fp::SizeTable t = fp::read_size_table(fp::test::data_dir() / "sand_grading.csv");
  EXPECT_EQ(t.kind, fp::SizeKind::diameter);
  EXPECT_TRUE(t.cumulative);
  EXPECT_EQ(t.rows, kSand);
  const fp::SizeTable c = fp::parse_size_table("# classes\r\nradius , fraction\r\n\r\n1,0.5\r\n 2 , 0.5 \r\n", "c.csv");
  EXPECT_EQ(c.kind, fp::SizeKind::radius);
  EXPECT_FALSE(c.cumulative);
  EXPECT_EQ(c.rows, (std::vector<fp::SizeFraction>{{1, 0.5}, {2, 0.5}}));
  const auto msg = [](const std::string& text) {
    return message_of([&text] { (void)fp::parse_size_table(text, "s.csv"); });
  };
  EXPECT_EQ(msg("size,passing\n1,0\n"),
            "s.csv:1: expected a header 'radius,fraction', 'diameter,fraction', "
            "'radius,passing' or 'diameter,passing', got 'size,passing'");
  EXPECT_EQ(msg("diameter,passing\n1,0\n2,x\n"), "s.csv:3: 'x' is not a number");
  EXPECT_EQ(msg("diameter,passing\n1,0\n2,1e-400\n"),
            "s.csv:3: '1e-400' is out of the range of a double (underflows to 0)");
  EXPECT_EQ(msg("diameter,passing\n1,0\n2,0.5,3\n"),
            "s.csv:3: expected SIZE,FRACTION (2 comma-separated numbers), got '2,0.5,3'");
  EXPECT_EQ(msg("diameter,passing\n0.1,0\n0.2,40\n0.4,100\n"),
            "s.csv:3: the fraction passing must be a number in [0, 1] (a fraction, not a percentage), got '40'");
  EXPECT_EQ(msg("diameter,passing\n0.1,0\n0.3,0.5\n0.2,1\n"),
            "s.csv:4: the diameter 0.2 must be larger than the previous one (0.3); give the points from the smallest "
            "size to the largest");
  EXPECT_EQ(msg("diameter,passing\n0.1,0\n0.2,0.5\n0.3,0.4\n"),
            "s.csv:4: the fraction passing 0.4 is less than the previous one (0.5); a grading curve never decreases");
  EXPECT_EQ(msg("radius,fraction\n0,1\n"), "s.csv:2: the radius must be a finite number > 0, got '0'");
  EXPECT_EQ(msg("radius,fraction\ninf,1\n"), "s.csv:2: the radius must be a finite number > 0, got 'inf'");
  EXPECT_EQ(msg("radius,fraction\n"), "s.csv: no rows after the header");
  EXPECT_EQ(msg("\n# nothing\n"), "s.csv: empty; expected a header line such as 'diameter,passing' and rows");
}
