// The standard normal distribution: cdf and quantile, deterministic given the C math library
// (std::erfc, std::exp, std::log, std::sqrt); no std:: random distribution is involved.
#pragma once

#include <cmath>
#include <limits>
#include <numbers>

namespace frontpack::detail {

/// Phi(z) = P(Z <= z), via erfc so that the lower tail keeps its relative accuracy.
[[nodiscard]] inline double normal_cdf(double z) noexcept {
  return 0.5 * std::erfc(-z / std::numbers::sqrt2);
}

/// phi(z), the standard normal density.
[[nodiscard]] inline double normal_pdf(double z) noexcept {
  return std::exp(-0.5 * z * z) / std::sqrt(2 * std::numbers::pi);
}

/// Phi^-1(p) for p in [0, 1] (-inf at 0, +inf at 1). P. J. Acklam's rational approximation
/// (relative error below 1.15e-9, as published), followed by one Halley step on
/// Phi(x) - p = 0 with the erfc-based cdf, which brings it to a few ulps.
[[nodiscard]] inline double normal_quantile(double p) noexcept {
  if (!(p > 0)) {
    return -std::numeric_limits<double>::infinity();
  }
  if (!(p < 1)) {
    return std::numeric_limits<double>::infinity();
  }
  constexpr double a[] = {-3.969683028665376e+01, 2.209460984245205e+02,  -2.759285104469687e+02,
                          1.383577518672690e+02,  -3.066479806614716e+01, 2.506628277459239e+00};
  constexpr double b[] = {-5.447609879822406e+01, 1.615858368580409e+02, -1.556989798598866e+02, 6.680131188771972e+01,
                          -1.328068155288572e+01};
  constexpr double c[] = {-7.784894002430293e-03, -3.223964580411365e-01, -2.400758277161838e+00,
                          -2.549732539343734e+00, 4.374664141464968e+00,  2.938163982698783e+00};
  constexpr double d[] = {7.784695709041462e-03, 3.224671290700398e-01, 2.445134137142996e+00, 3.754408661907416e+00};
  constexpr double p_low = 0.02425;
  double x = 0;
  if (p < p_low) {
    const double q = std::sqrt(-2 * std::log(p));
    x = (((((c[0] * q + c[1]) * q + c[2]) * q + c[3]) * q + c[4]) * q + c[5]) /
        ((((d[0] * q + d[1]) * q + d[2]) * q + d[3]) * q + 1);
  } else if (p <= 1 - p_low) {
    const double q = p - 0.5;
    const double r = q * q;
    x = (((((a[0] * r + a[1]) * r + a[2]) * r + a[3]) * r + a[4]) * r + a[5]) * q /
        (((((b[0] * r + b[1]) * r + b[2]) * r + b[3]) * r + b[4]) * r + 1);
  } else {
    const double q = std::sqrt(-2 * std::log1p(-p));
    x = -(((((c[0] * q + c[1]) * q + c[2]) * q + c[3]) * q + c[4]) * q + c[5]) /
        ((((d[0] * q + d[1]) * q + d[2]) * q + d[3]) * q + 1);
  }
  // Halley refinement (Acklam's note): e = Phi(x) - p, u = e / phi(x). Above the median,
  // Phi(x) - p is taken as (1 - p) - Phi(-x) (1 - p is exact there), which keeps the upper tail
  // as accurate as the lower one.
  const double e = p < 0.5 ? normal_cdf(x) - p : (1 - p) - normal_cdf(-x);
  const double u = e * std::sqrt(2 * std::numbers::pi) * std::exp(0.5 * x * x);
  return x - u / (1 + 0.5 * x * u);
}

}  // namespace frontpack::detail
