// The tabulated radius distributions: discrete size classes, and grading curves (passing
// fractions at given sizes, interpolated in log r), by number or by area.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <memory>
#include <numeric>
#include <string>
#include <utility>
#include <vector>

#include "sizes/checks.hpp"

namespace frontpack {

namespace {

using namespace detail;

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

}  // namespace

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

}  // namespace frontpack
