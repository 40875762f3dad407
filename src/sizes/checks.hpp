// Argument checks and small helpers shared by the radius distributions (distributions.cpp,
// tabulated.cpp): every bad argument is an OptionError naming the distribution and the value.
#pragma once

#include <cmath>
#include <memory>
#include <string>
#include <utility>

#include "common/format.hpp"
#include "frontpack/errors.hpp"
#include "frontpack/sizes.hpp"
#include "sizes/normal.hpp"

namespace frontpack::detail {

inline std::string interval(double lo, double hi) {
  std::string out("[");  // (not "[" + string: GCC 12 warns falsely about that, -Wrestrict)
  out += format_double(lo);
  out += ", ";
  out += format_double(hi);
  out += "]";
  return out;
}

inline void check_radius(double r, const std::string& what) {
  if (!std::isfinite(r) || !(r > 0)) {
    throw OptionError("radius: " + what + " must be a finite number > 0, got " + format_double(r));
  }
}

// Smallest probability a truncation window must keep. The window's probabilities are computed
// in the tail where they are small (TruncatedStandardNormal), so they keep their relative
// accuracy down to underflow; this only refuses windows whose probability underflows.
constexpr double kMinMass = 1e-300;

// Phi(beta) - Phi(alpha) for alpha <= beta, computed in the tail where it is accurate.
inline double normal_mass(double alpha, double beta) {
  if (alpha > 0) {
    return detail::normal_cdf(-alpha) - detail::normal_cdf(-beta);
  }
  return detail::normal_cdf(beta) - detail::normal_cdf(alpha);
}

inline double clamp(double r, double lo, double hi) {
  return r < lo ? lo : (r > hi ? hi : r);
}

inline void check_finite_positive_bounds(const char* name, double lo, double hi) {
  check_radius(lo, std::string(name) + ": the lower bound");
  check_radius(hi, std::string(name) + ": the upper bound");
  if (!(lo < hi)) {
    throw OptionError(std::string("radius: ") + name + ": the lower bound (" + format_double(lo) +
                      ") must be less than the upper bound (" + format_double(hi) + ")");
  }
}

inline void check_mass(const char* name, double mass, double lo, double hi) {
  if (!(mass >= kMinMass)) {
    throw OptionError(std::string("radius: ") + name + ": the truncation bounds " + interval(lo, hi) +
                      " keep a probability of " + format_double(mass) + " (less than 1e-300) of the distribution");
  }
}

inline const char* size_name(SizeKind kind) {
  return kind == SizeKind::radius ? "radius" : "diameter";
}

// Checks a size and returns it as a radius.
inline double to_radius(double size, SizeKind kind, const std::string& where) {
  if (!std::isfinite(size) || !(size > 0)) {
    throw OptionError("radius: " + where + ": the " + size_name(kind) + " must be a finite number > 0, got " +
                      format_double(size));
  }
  return kind == SizeKind::diameter ? size / 2 : size;  // exact: a power-of-two scaling
}

inline void check_fraction(double f, const std::string& where, const char* what) {
  if (!std::isfinite(f) || f < 0 || f > 1) {
    throw OptionError("radius: " + where + ": the " + what + " must be a number in [0, 1], got " + format_double(f));
  }
}

template <class D>
Radii make(std::shared_ptr<const D> d) {
  return Radii::custom(std::move(d));
}

}  // namespace frontpack::detail
