// Scaled radii and the way back (scaled_radii.hpp).
#include "targets/scaled_radii.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "common/format.hpp"

namespace frontpack::detail {

namespace {

class Scaled final : public RadiusDistribution {
 public:
  Scaled(std::shared_ptr<const RadiusDistribution> base, double s) : base_(std::move(base)), s_(s) {}
  double quantile(double u) const override { return s_ * base_->quantile(u); }
  double min() const override { return s_ * base_->min(); }
  double max() const override { return s_ * base_->max(); }
  double mean_square() const override { return s_ * s_ * base_->mean_square(); }
  double cdf(double r) const override { return base_->cdf(r / s_); }
  double area_cdf(double r) const override { return base_->area_cdf(r / s_); }
  std::vector<double> class_radii() const override {
    std::vector<double> c = base_->class_radii();
    for (double& r : c) {
      r *= s_;
    }
    return c;
  }
  std::string describe() const override { return base_->describe() + ", scaled by " + format_double(s_); }

 private:
  std::shared_ptr<const RadiusDistribution> base_;
  double s_;
};

// A non-owning handle on `base` for the wrapper (Radii shares its distribution).
struct Keep {
  Radii radii;
};

}  // namespace

Radii scaled_radii(const Radii& base, double s) {
  // The wrapper keeps `base` alive through a Radii copy held by the aliasing shared_ptr.
  auto keep = std::make_shared<Keep>(Keep{base});
  std::shared_ptr<const RadiusDistribution> alias(keep, &keep->radii.distribution());
  return Radii::custom(std::make_shared<const Scaled>(std::move(alias), s));
}

double unscaled_radius(const RadiusDistribution& base, double s, double placed) {
  for (const double c : base.class_radii()) {
    if (s * c == placed) {
      return c;
    }
  }
  // fl(s * r) == placed holds for r within an ulp or two of placed / s; take the largest.
  double r = placed / s;
  for (int k = 0; k < 3; ++k) {
    r = std::nextafter(r, std::numeric_limits<double>::infinity());
  }
  for (int k = 0; k < 7; ++k) {
    if (s * r == placed && r <= placed) {
      return r;
    }
    r = std::nextafter(r, 0.0);
  }
  // Unreachable for radii this distribution drew; stay inside the placed disk regardless.
  return std::min(placed / s, placed);
}

}  // namespace frontpack::detail
