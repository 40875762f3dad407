// RadiusBins: the one binning of radii, for SizeStats::histogram and the tool's picture panel.
#include <cmath>

#include "frontpack/stats.hpp"

namespace frontpack {

RadiusBins::RadiusBins(double lo, double hi, std::size_t count, BinSpacing spacing) : spacing_(spacing), lo_(lo) {
  // hi / lo overflows for radii spanning more than the range of doubles (1e-10 to 1e308): then
  // the log edges are taken from log(lo) (the same edges up to rounding).
  const bool wide = spacing == BinSpacing::log && !std::isfinite(hi / lo);
  span_ = spacing == BinSpacing::linear ? hi - lo : wide ? std::log(hi) - std::log(lo) : std::log(hi / lo);
  const auto edge = [&](std::size_t b) {
    if (spacing == BinSpacing::linear) {
      return lo + span_ * static_cast<double>(b) / static_cast<double>(count);
    }
    const double f = span_ * static_cast<double>(b) / static_cast<double>(count);
    return wide ? std::exp(std::log(lo) + f) : lo * std::exp(f);
  };
  edges_.reserve(count + 1);
  for (std::size_t b = 0; b <= count; ++b) {
    edges_.push_back(b == 0 ? lo : b == count ? hi : edge(b));
  }
}

std::size_t RadiusBins::bin_of(double x) const noexcept {
  const std::size_t bins = count();
  if (bins == 1) {
    return 0;
  }
  const double guess = spacing_ == BinSpacing::linear ? (x - lo_) / span_ : std::log(x / lo_) / span_;
  const double t = std::floor(guess * static_cast<double>(bins));
  // (NaN-safe: the conversion of a NaN is undefined.)
  std::size_t b = t > 0 ? (t < static_cast<double>(bins - 1) ? static_cast<std::size_t>(t) : bins - 1) : 0;
  while (b > 0 && x < edges_[b]) {
    --b;
  }
  while (b + 1 < bins && x >= edges_[b + 1]) {
    ++b;
  }
  return b;
}

}  // namespace frontpack
