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

#include "common/format.hpp"
#include "frontpack/fill.hpp"
#include "sizes/normal.hpp"
#include "common/rng.hpp"

namespace frontpack {

namespace {

using detail::format_double;

std::string interval(double lo, double hi) {
  std::string out("[");  // (not "[" + string: GCC 12 warns falsely about that, -Wrestrict)
  out += format_double(lo);
  out += ", ";
  out += format_double(hi);
  out += "]";
  return out;
}

void check_radius(double r, const std::string& what) {
  if (!std::isfinite(r) || !(r > 0)) {
    throw OptionError("radius: " + what + " must be a finite number > 0, got " + format_double(r));
  }
}

// Smallest probability a truncation window must keep. The window's probabilities are computed
// in the tail where they are small (TruncatedStandardNormal), so they keep their relative
// accuracy down to underflow; this only refuses windows whose probability underflows.
constexpr double kMinMass = 1e-300;

// Phi(beta) - Phi(alpha) for alpha <= beta, computed in the tail where it is accurate.
double normal_mass(double alpha, double beta) {
  if (alpha > 0) {
    return detail::normal_cdf(-alpha) - detail::normal_cdf(-beta);
  }
  return detail::normal_cdf(beta) - detail::normal_cdf(alpha);
}

double clamp(double r, double lo, double hi) {
  return r < lo ? lo : (r > hi ? hi : r);
}

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

// Cumulative sums of w, normalised so that the last is exactly 1.
std::vector<double> cumulative(const std::vector<double>& w) {
  std::vector<double> c(w.size() + 1, 0.0);
  for (std::size_t k = 0; k < w.size(); ++k) {
    c[k + 1] = c[k] + w[k];
  }
  const double total = c.back();
  for (double& x : c) {
    x /= total;
  }
  c.back() = 1;
  return c;
}

class Discrete final : public RadiusDistribution {
 public:
  // radii increasing; number_weights and area_weights proportional to the classes' number and
  // area fractions.
  Discrete(std::vector<double> radii, const std::vector<double>& number_weights, Basis basis, SizeKind kind)
      : radii_(std::move(radii)), basis_(basis), kind_(kind) {
    std::vector<double> area_weights(radii_.size());
    double number_total = 0;
    double area_total = 0;
    for (std::size_t k = 0; k < radii_.size(); ++k) {
      area_weights[k] = number_weights[k] * radii_[k] * radii_[k];
      number_total += number_weights[k];
      area_total += area_weights[k];
      if (number_weights[k] > 0) {
        lo_ = std::min(lo_, radii_[k]);
        hi_ = std::max(hi_, radii_[k]);
      }
    }
    number_ = cumulative(number_weights);
    area_ = cumulative(area_weights);
    mean_square_ = area_total / number_total;
  }
  [[nodiscard]] double quantile(double u) const override {
    // The first class k with u < number_[k + 1]; a class of fraction 0 is never drawn.
    const auto it = std::upper_bound(number_.begin() + 1, number_.end(), u);
    const auto k = static_cast<std::size_t>(it - number_.begin() - 1);
    return clamp(radii_[std::min(k, radii_.size() - 1)], lo_, hi_);
  }
  [[nodiscard]] double min() const override { return lo_; }
  [[nodiscard]] double max() const override { return hi_; }
  [[nodiscard]] double mean_square() const override { return mean_square_; }
  [[nodiscard]] double cdf(double r) const override { return number_[classes_upto(r)]; }
  [[nodiscard]] double area_cdf(double r) const override { return area_[classes_upto(r)]; }
  [[nodiscard]] std::vector<double> class_radii() const override { return radii_; }
  [[nodiscard]] std::string describe() const override {
    return "discrete: " + std::to_string(radii_.size()) + " classes of radius " +
           interval(radii_.front(), radii_.back()) + ", fractions by " + to_string(basis_) + " (sizes given as " +
           to_string(kind_) + ")";
  }

 private:
  // The number of classes of radius <= r.
  [[nodiscard]] std::size_t classes_upto(double r) const {
    return static_cast<std::size_t>(std::upper_bound(radii_.begin(), radii_.end(), r) - radii_.begin());
  }

  std::vector<double> radii_;
  Basis basis_;
  SizeKind kind_;
  std::vector<double> number_;  // number_[k]: fraction in classes < k (k = 0..K)
  std::vector<double> area_;
  double lo_ = INFINITY;
  double hi_ = -INFINITY;
  double mean_square_ = 0;
};

// A grading curve: on each segment [r_k, r_k+1] the cumulative fraction (by `basis`) is linear
// in log r, so its density in r is proportional to 1 / r in that basis. By number the area
// density is then proportional to r; by area the number density is proportional to 1 / r^3
// (the compensation: area density g(r) ~ 1/r, number density g(r) / r^2).
class GradingCurve final : public RadiusDistribution {
 public:
  GradingCurve(std::vector<double> radii, const std::vector<double>& passing, Basis basis, SizeKind kind)
      : r_(std::move(radii)), basis_(basis), kind_(kind) {
    const std::size_t segments = r_.size() - 1;
    std::vector<double> number(segments);
    std::vector<double> area(segments);
    log_ratio_.resize(segments);
    for (std::size_t k = 0; k < segments; ++k) {
      const double dp = passing[k + 1] - passing[k];
      const double a = r_[k];
      const double b = r_[k + 1];
      log_ratio_[k] = std::log(b / a);
      // With the segment's density c / r in the given basis (c = dp / log(b / a)):
      const double c = dp / log_ratio_[k];
      if (basis == Basis::number) {
        number[k] = dp;
        area[k] = c * (b * b - a * a) / 2;
      } else {
        area[k] = dp;
        number[k] = c * (1 / (a * a) - 1 / (b * b)) / 2;
      }
      if (dp > 0) {
        lo_ = std::min(lo_, a);
        hi_ = std::max(hi_, b);
      }
    }
    double number_total = 0;
    double area_total = 0;
    for (std::size_t k = 0; k < segments; ++k) {
      number_total += number[k];
      area_total += area[k];
    }
    mean_square_ = area_total / number_total;
    number_ = cumulative(number);
    area_ = cumulative(area);
  }
  [[nodiscard]] double quantile(double u) const override {
    // The segment k with number_[k] <= u < number_[k + 1] (never one of zero mass).
    const auto it = std::upper_bound(number_.begin() + 1, number_.end(), u);
    const std::size_t k = std::min(static_cast<std::size_t>(it - number_.begin() - 1), r_.size() - 2);
    const double t = clamp((u - number_[k]) / (number_[k + 1] - number_[k]), 0, 1);
    const double a = r_[k];
    const double b = r_[k + 1];
    double r = 0;
    if (basis_ == Basis::number) {
      r = a * std::exp(t * log_ratio_[k]);  // number fraction linear in log r
    } else {
      // Number cdf within the segment: (a^-2 - r^-2) / (a^-2 - b^-2) = t.
      const double ia = 1 / (a * a);
      r = 1 / std::sqrt(ia - t * (ia - 1 / (b * b)));
    }
    return clamp(clamp(r, a, b), lo_, hi_);
  }
  [[nodiscard]] double min() const override { return lo_; }
  [[nodiscard]] double max() const override { return hi_; }
  [[nodiscard]] double mean_square() const override { return mean_square_; }
  [[nodiscard]] double cdf(double r) const override { return within(r, number_, basis_ == Basis::number); }
  [[nodiscard]] double area_cdf(double r) const override { return within(r, area_, basis_ == Basis::area); }
  [[nodiscard]] std::vector<double> class_radii() const override { return r_; }
  [[nodiscard]] std::string describe() const override {
    return "grading curve: " + std::to_string(r_.size()) + " points, radius " + interval(r_.front(), r_.back()) +
           ", passing by " + to_string(basis_) + " (sizes given as " + to_string(kind_) + ")";
  }

 private:
  // The cumulative fraction c (number_ or area_) at r. In the basis of the curve it is linear
  // in log r on each segment; in the other one the segment's density is r^-3 (number, for a
  // by-area curve) or r (area, for a by-number curve).
  [[nodiscard]] double within(double r, const std::vector<double>& c, bool log_linear) const {
    if (!(r >= r_.front())) {
      return 0;
    }
    if (r >= r_.back()) {
      return 1;
    }
    const auto it = std::upper_bound(r_.begin(), r_.end(), r);
    const auto k = static_cast<std::size_t>(it - r_.begin() - 1);
    const double a = r_[k];
    const double b = r_[k + 1];
    double t = 0;
    if (log_linear) {
      t = std::log(r / a) / log_ratio_[k];
    } else if (basis_ == Basis::area) {  // number within a by-area segment
      t = (1 / (a * a) - 1 / (r * r)) / (1 / (a * a) - 1 / (b * b));
    } else {  // area within a by-number segment
      t = (r * r - a * a) / (b * b - a * a);
    }
    return clamp(c[k] + clamp(t, 0, 1) * (c[k + 1] - c[k]), 0, 1);
  }

  std::vector<double> r_;
  Basis basis_;
  SizeKind kind_;
  std::vector<double> log_ratio_;
  std::vector<double> number_;  // number_[k]: fraction of the number below r_[k]
  std::vector<double> area_;
  double lo_ = INFINITY;
  double hi_ = -INFINITY;
  double mean_square_ = 0;
};

void check_finite_positive_bounds(const char* name, double lo, double hi) {
  check_radius(lo, std::string(name) + ": the lower bound");
  check_radius(hi, std::string(name) + ": the upper bound");
  if (!(lo < hi)) {
    throw OptionError(std::string("radius: ") + name + ": the lower bound (" + format_double(lo) +
                      ") must be less than the upper bound (" + format_double(hi) + ")");
  }
}

void check_mass(const char* name, double mass, double lo, double hi) {
  if (!(mass >= kMinMass)) {
    throw OptionError(std::string("radius: ") + name + ": the truncation bounds " + interval(lo, hi) +
                      " keep a probability of " + format_double(mass) + " (less than 1e-300) of the distribution");
  }
}

const char* size_name(SizeKind kind) {
  return kind == SizeKind::radius ? "radius" : "diameter";
}

// Checks a size and returns it as a radius.
double to_radius(double size, SizeKind kind, const std::string& where) {
  if (!std::isfinite(size) || !(size > 0)) {
    throw OptionError("radius: " + where + ": the " + size_name(kind) + " must be a finite number > 0, got " +
                      format_double(size));
  }
  return kind == SizeKind::diameter ? size / 2 : size;  // exact: a power-of-two scaling
}

void check_fraction(double f, const std::string& where, const char* what) {
  if (!std::isfinite(f) || f < 0 || f > 1) {
    throw OptionError("radius: " + where + ": the " + what + " must be a number in [0, 1], got " + format_double(f));
  }
}

template <class D>
Radii make(std::shared_ptr<const D> d) {
  return Radii::custom(std::move(d));
}

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

Radii Radii::discrete(std::vector<SizeFraction> classes, Basis basis, SizeKind kind) {
  if (classes.empty()) {
    throw OptionError("radius: discrete: no class given");
  }
  std::vector<std::pair<double, double>> rf;  // (radius, fraction)
  double sum = 0;
  for (std::size_t k = 0; k < classes.size(); ++k) {
    const std::string where = "discrete: class " + std::to_string(k + 1);
    rf.emplace_back(to_radius(classes[k].size, kind, where), classes[k].fraction);
    check_fraction(classes[k].fraction, where, "fraction");
    sum += classes[k].fraction;
  }
  if (!(std::abs(sum - 1) <= 1e-6)) {
    throw OptionError("radius: discrete: the fractions must add up to 1, they add up to " + format_double(sum));
  }
  std::sort(rf.begin(), rf.end());
  for (std::size_t k = 1; k < rf.size(); ++k) {
    if (rf[k].first == rf[k - 1].first) {
      throw OptionError("radius: discrete: two classes have the same " + std::string(size_name(kind)) + " " +
                        format_double(kind == SizeKind::diameter ? 2 * rf[k].first : rf[k].first));
    }
  }
  std::vector<double> radii;
  std::vector<double> number_weights;
  for (const auto& [r, f] : rf) {
    radii.push_back(r);
    // By area: a class of area fraction f holds f / r^2 disks per unit of pi * total area.
    number_weights.push_back(basis == Basis::number ? f : f / (r * r));
  }
  return make(std::make_shared<const Discrete>(std::move(radii), number_weights, basis, kind));
}

Radii Radii::grading_curve(std::vector<SizeFraction> points, Basis basis, SizeKind kind) {
  if (points.size() < 2) {
    throw OptionError("radius: grading curve: at least 2 points are needed, got " + std::to_string(points.size()));
  }
  std::vector<double> radii;
  std::vector<double> passing;
  for (std::size_t k = 0; k < points.size(); ++k) {
    const std::string where = "grading curve: point " + std::to_string(k + 1);
    radii.push_back(to_radius(points[k].size, kind, where));
    check_fraction(points[k].fraction, where, "fraction passing");
    passing.push_back(points[k].fraction);
    if (k > 0 && !(points[k].size > points[k - 1].size)) {
      throw OptionError("radius: " + where + ": the " + size_name(kind) + " " + format_double(points[k].size) +
                        " must be larger than the previous one (" + format_double(points[k - 1].size) +
                        "); give the points from the smallest size to the largest");
    }
    if (k > 0 && points[k].fraction < points[k - 1].fraction) {
      throw OptionError("radius: " + where + ": the fraction passing " + format_double(points[k].fraction) +
                        " is less than the previous one (" + format_double(points[k - 1].fraction) +
                        "); a grading curve never decreases");
    }
  }
  if (!(passing.front() <= 1e-6)) {
    throw OptionError("radius: grading curve: the first point must pass 0 (the smallest size bounds the curve), got " +
                      format_double(passing.front()));
  }
  if (!(passing.back() >= 1 - 1e-6)) {
    throw OptionError("radius: grading curve: the last point must pass 1 (the largest size bounds the curve), got " +
                      format_double(passing.back()));
  }
  passing.front() = 0;
  passing.back() = 1;
  return make(std::make_shared<const GradingCurve>(std::move(radii), passing, basis, kind));
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
