#include <cmath>
#include <memory>
#include <string>

#include "format.hpp"
#include "frontpack/fill.hpp"

namespace frontpack {

namespace {

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

 private:
  double lo_;
  double hi_;
};

void check_radius(double r, const char* what) {
  if (!std::isfinite(r) || !(r > 0)) {
    throw OptionError(std::string("radius: ") + what + " must be a finite number > 0, got " + detail::format_double(r));
  }
}

}  // namespace

Radii Radii::uniform(double rmin, double rmax) {
  check_radius(rmin, "rmin");
  check_radius(rmax, "rmax");
  if (rmin > rmax) {
    throw OptionError("radius: rmin (" + detail::format_double(rmin) + ") must not exceed rmax (" +
                      detail::format_double(rmax) + ")");
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

const char* to_string(Method method) noexcept {
  switch (method) {
    case Method::closed: return "closed";
    case Method::open: return "open";
  }
  return "unknown";
}

}  // namespace frontpack
