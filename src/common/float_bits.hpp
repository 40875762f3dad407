// Neighbouring doubles without a libm call (std::nextafter is not inlined and showed in
// profiles of the certifier). Same results as std::nextafter towards -inf / +inf.
#pragma once

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

namespace frontpack::detail {

/// The largest double below v (v finite or infinite; NaN stays NaN; -inf stays -inf).
inline double next_down(double v) noexcept {
  if (std::isnan(v) || v == -std::numeric_limits<double>::infinity()) {
    return v;
  }
  if (v == 0) {
    return -std::numeric_limits<double>::denorm_min();
  }
  auto bits = std::bit_cast<std::uint64_t>(v);
  bits = v > 0 ? bits - 1 : bits + 1;
  return std::bit_cast<double>(bits);
}

/// The smallest double above v.
inline double next_up(double v) noexcept {
  return -next_down(-v);
}

}  // namespace frontpack::detail
