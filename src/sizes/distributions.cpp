// Radius distributions (include/frontpack/sizes.hpp): every one is sampled by inverse transform
// of frontpack's own 53-bit uniform variate, with closed-form quantiles (the normal one is
// Acklam's approximation refined by a Halley step, sizes/normal.hpp), so that nothing depends on the
// implementation-defined std:: distributions. Each distribution also knows its cdf by number and
// by area exactly (closed forms), for the statistics (stats/stats.cpp).
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <memory>
#include <numeric>
#include <string>
#include <utility>
#include <vector>

#include "common/rng.hpp"
#include "sizes/checks.hpp"

namespace frontpack {

namespace {

using namespace detail;

class Uniform final : public RadiusDistribution {
 public:
  Uniform(double lo, double hi) : lo_(lo), hi_(hi) {}
  [[nodiscard]] double quantile(double u) const override {
    const double r = lo_ + (hi_ - lo_) * u;
    return r > hi_ ? hi_ : r;  // rounding must not leave [lo, hi]
  }
  [[nodiscard]] double min() const override { return lo_; }
  [[nodiscard]] double max() const override { return hi_; }
  [[nodiscard]] double mean_square() const override { return (lo_ * lo_ + lo_ * hi_ + hi_ * hi_) / 3; }
  [[nodiscard]] double cdf(double r) const override {
    if (r < lo_) {
      return 0;
    }
    return r >= hi_ ? 1 : (r - lo_) / (hi_ - lo_);
  }
  [[nodiscard]] double area_cdf(double r) const override {
    if (r < lo_) {
      return 0;
    }
    return r >= hi_ ? 1 : (r * r * r - lo_ * lo_ * lo_) / (hi_ * hi_ * hi_ - lo_ * lo_ * lo_);
  }
  [[nodiscard]] std::vector<double> class_radii() const override {
    return lo_ == hi_ ? std::vector<double>{lo_} : std::vector<double>{};
  }
  [[nodiscard]] std::string describe() const override {
    return lo_ == hi_ ? "constant: radius " + format_double(lo_) : "uniform: radius in " + interval(lo_, hi_);
  }

 private:
  double lo_;
  double hi_;
};

// A standard normal variable z truncated to [alpha, beta], mapped to a radius by `map` (x -> mean
// + sd x for the normal, exp(mu + sigma x) for the lognormal). When the window lies above the
// median the computation is mirrored (z -> -z) so that the probabilities used are the small,
// accurately represented ones.
class TruncatedStandardNormal {
 public:
  TruncatedStandardNormal(double alpha, double beta) : alpha_(alpha), beta_(beta), mirror_(alpha > 0) {
    p_lo_ = mirror_ ? detail::normal_cdf(-beta) : detail::normal_cdf(alpha);
    p_hi_ = mirror_ ? detail::normal_cdf(-alpha) : detail::normal_cdf(beta);
    mass_ = normal_mass(alpha, beta);
  }
  [[nodiscard]] double mass() const { return mass_; }
  [[nodiscard]] double alpha() const { return alpha_; }
  [[nodiscard]] double beta() const { return beta_; }
  /// The standard value at cumulative probability u of the truncated law.
  [[nodiscard]] double quantile(double u) const {
    if (mirror_) {
      return -detail::normal_quantile(p_hi_ - u * (p_hi_ - p_lo_));
    }
    return detail::normal_quantile(p_lo_ + u * (p_hi_ - p_lo_));
  }
  /// P(Z <= z) of the truncated law.
  [[nodiscard]] double cdf(double z) const {
    if (!(z > alpha_)) {
      return 0;
    }
    if (z >= beta_) {
      return 1;
    }
    return std::min(1.0, normal_mass(alpha_, z) / mass_);
  }

 private:
  double alpha_;
  double beta_;
  bool mirror_;
  double p_lo_ = 0;
  double p_hi_ = 0;
  double mass_ = 0;
};

class Normal final : public RadiusDistribution {
 public:
  Normal(double mean, double sd, double lo, double hi)
      : mean_(mean), sd_(sd), lo_(lo), hi_(hi), z_((lo - mean) / sd, (hi - mean) / sd) {
    total_m2_ = m2(z_.alpha(), z_.beta());
  }
  [[nodiscard]] double mass() const { return z_.mass(); }
  [[nodiscard]] double quantile(double u) const override { return clamp(mean_ + sd_ * z_.quantile(u), lo_, hi_); }
  [[nodiscard]] double min() const override { return lo_; }
  [[nodiscard]] double max() const override { return hi_; }
  [[nodiscard]] double mean_square() const override { return total_m2_ / z_.mass(); }
  [[nodiscard]] double cdf(double r) const override { return z_.cdf((r - mean_) / sd_); }
  [[nodiscard]] double area_cdf(double r) const override {
    if (!(r > lo_)) {
      return 0;
    }
    if (r >= hi_) {
      return 1;
    }
    return clamp(m2(z_.alpha(), (r - mean_) / sd_) / total_m2_, 0, 1);
  }
  [[nodiscard]] std::string describe() const override {
    return "normal: radius mean " + format_double(mean_) + ", sd " + format_double(sd_) + ", truncated to " +
           interval(lo_, hi_);
  }

 private:
  // Integral of (mean + sd z)^2 phi(z) over [a, b]: mean^2 P + 2 mean sd (phi(a) - phi(b)) +
  // sd^2 (P + a phi(a) - b phi(b)), with P = Phi(b) - Phi(a).
  [[nodiscard]] double m2(double a, double b) const {
    const double p = normal_mass(a, b);
    const double pa = detail::normal_pdf(a);
    const double pb = detail::normal_pdf(b);
    return mean_ * mean_ * p + 2 * mean_ * sd_ * (pa - pb) + sd_ * sd_ * (p + a * pa - b * pb);
  }

  double mean_;
  double sd_;
  double lo_;
  double hi_;
  TruncatedStandardNormal z_;
  double total_m2_ = 0;
};

class LogNormal final : public RadiusDistribution {
 public:
  LogNormal(double median, double gsd, double lo, double hi)
      : median_(median),
        gsd_(gsd),
        mu_(std::log(median)),
        sigma_(std::log(gsd)),
        lo_(lo),
        hi_(hi),
        z_((std::log(lo) - mu_) / sigma_, (std::log(hi) - mu_) / sigma_),
        // R^2 weights the law of log R like a normal shifted by 2 sigma (in standard units).
        area_z_(z_.alpha() - 2 * sigma_, z_.beta() - 2 * sigma_) {}
  [[nodiscard]] double mass() const { return z_.mass(); }
  [[nodiscard]] double quantile(double u) const override {
    return clamp(std::exp(mu_ + sigma_ * z_.quantile(u)), lo_, hi_);
  }
  [[nodiscard]] double min() const override { return lo_; }
  [[nodiscard]] double max() const override { return hi_; }
  [[nodiscard]] double mean_square() const override {
    // E[R^2 1{lo <= R <= hi}] = exp(2 mu + 2 sigma^2) (Phi(beta - 2 sigma) - Phi(alpha - 2 sigma)).
    return std::exp(2 * mu_ + 2 * sigma_ * sigma_) * area_z_.mass() / z_.mass();
  }
  [[nodiscard]] double cdf(double r) const override { return r > 0 ? z_.cdf((std::log(r) - mu_) / sigma_) : 0; }
  [[nodiscard]] double area_cdf(double r) const override {
    return r > 0 ? area_z_.cdf((std::log(r) - mu_) / sigma_ - 2 * sigma_) : 0;
  }
  [[nodiscard]] std::string describe() const override {
    return "lognormal: radius median " + format_double(median_) + ", geometric sd " + format_double(gsd_) +
           ", truncated to " + interval(lo_, hi_);
  }

 private:
  double median_;
  double gsd_;
  double mu_;
  double sigma_;
  double lo_;
  double hi_;
  TruncatedStandardNormal z_;
  TruncatedStandardNormal area_z_;
};

}  // namespace

const char* to_string(Basis basis) noexcept {
  return basis == Basis::number ? "number" : "area";
}
const char* to_string(SizeKind kind) noexcept {
  return size_name(kind);
}

double RadiusDistribution::cdf(double r) const {
  // sup { u : quantile(u) <= r }, by bisection (quantile is monotone).
  if (quantile(0) > r) {
    return 0;
  }
  double lo = 0;
  double hi = 1;
  for (int i = 0; i < 53; ++i) {
    const double mid = (lo + hi) / 2;
    if (quantile(mid) <= r) {
      lo = mid;
    } else {
      hi = mid;
    }
  }
  return hi >= 1 && quantile(std::nextafter(1.0, 0.0)) <= r ? 1 : lo;
}

double RadiusDistribution::area_cdf(double r) const {
  constexpr int n = 4096;
  double part = 0;
  double total = 0;
  for (int i = 0; i < n; ++i) {
    const double q = quantile((i + 0.5) / n);
    total += q * q;
    part += q <= r ? q * q : 0;
  }
  return total > 0 ? part / total : 0;
}

std::vector<double> RadiusDistribution::class_radii() const {
  return {};
}

std::string RadiusDistribution::describe() const {
  return "custom: radius in " + interval(min(), max());
}

Radii Radii::uniform(double rmin, double rmax) {
  check_radius(rmin, "rmin");
  check_radius(rmax, "rmax");
  if (rmin > rmax) {
    throw OptionError("radius: rmin (" + format_double(rmin) + ") must not exceed rmax (" + format_double(rmax) + ")");
  }
  Radii r;
  r.d_ = std::make_shared<Uniform>(rmin, rmax);
  return r;
}

Radii Radii::constant(double radius) {
  check_radius(radius, "the radius");
  Radii r;
  r.d_ = std::make_shared<Uniform>(radius, radius);
  return r;
}

Radii Radii::normal(double mean, double sd, double lo, double hi) {
  if (!std::isfinite(mean)) {
    throw OptionError("radius: normal: the mean must be a finite number, got " + format_double(mean));
  }
  check_radius(sd, "normal: the standard deviation");
  check_finite_positive_bounds("normal", lo, hi);
  auto d = std::make_shared<const Normal>(mean, sd, lo, hi);
  check_mass("normal", d->mass(), lo, hi);
  return make(std::move(d));
}

Radii Radii::lognormal(double median, double gsd, double lo, double hi) {
  check_radius(median, "lognormal: the median");
  if (!std::isfinite(gsd) || !(gsd > 1)) {
    throw OptionError("radius: lognormal: the geometric standard deviation must be a finite number > 1, got " +
                      format_double(gsd));
  }
  check_finite_positive_bounds("lognormal", lo, hi);
  auto d = std::make_shared<const LogNormal>(median, gsd, lo, hi);
  check_mass("lognormal", d->mass(), lo, hi);
  return make(std::move(d));
}

Radii Radii::custom(std::shared_ptr<const RadiusDistribution> distribution) {
  if (!distribution) {
    throw OptionError("radius: no distribution given");
  }
  check_radius(distribution->min(), "the distribution's minimum");
  check_radius(distribution->max(), "the distribution's maximum");
  if (distribution->min() > distribution->max()) {
    throw OptionError("radius: the distribution's minimum exceeds its maximum");
  }
  Radii r;
  r.d_ = std::move(distribution);
  return r;
}

const RadiusDistribution& Radii::distribution() const {
  if (!d_) {
    throw OptionError("radius: no distribution given");
  }
  return *d_;
}

std::vector<double> sample_radii(const Radii& radii, std::size_t n, std::uint64_t seed) {
  const RadiusDistribution& d = radii.distribution();
  detail::Rng rng(seed);
  std::vector<double> out(n);
  for (double& r : out) {
    r = d.quantile(rng.uniform());
  }
  return out;
}

}  // namespace frontpack
