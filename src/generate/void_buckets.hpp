// The voids the fronts leave behind, bucketed by the largest radius each can take (log-spaced
// radius classes between rmin and rmax), so that each new radius is tried in the tightest void
// that may hold it. Header-only and CGAL-free: every radius drawn is classed here.
#pragma once

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

namespace frontpack::detail {

/// Radius classes for the void buckets: N classes log-spaced between rmin and rmax; class k >= 1
/// holds the radii from floor_[k] up, class 0 the rest (below floor_[1], and NaN); with
/// rmin = rmax everything is class 0. The generators ask for the class of every radius drawn and
/// every void kept, so of() takes no logarithm and no search: the bits of a positive double, as
/// an integer, grow with it, and their top bits (the exponent and the first mantissa bits) index
/// a table of the class at the bottom of each such bucket of radii; the buckets are made narrower
/// than a class where the table's kTable entries allow it, so one comparison finishes the lookup
/// (a loop climbs further where they do not). A binary search with log2(N) dependent steps took
/// about 40 cycles.
template <int N>
class RadiusClasses {
  static_assert(N >= 2 && N <= 256);  // classes fit the table's bytes
  static constexpr std::size_t kTable = 1024;

 public:
  RadiusClasses() {
    floor_.fill(std::numeric_limits<double>::infinity());
    floor_[N] = std::numeric_limits<double>::quiet_NaN();  // never reached: r >= NaN is false
  }
  RadiusClasses(double rmin, double rmax) : RadiusClasses() {
    const double log_rmin = std::log(rmin);
    const double span = std::log(rmax) - log_rmin;
    floor_[0] = -std::numeric_limits<double>::infinity();
    if (!(span > 0)) {
      return;
    }
    // Above rmin (a range a few ulps wide rounds the low floors down to it) and increasing.
    const double above_rmin = std::nextafter(rmin, std::numeric_limits<double>::infinity());
    for (std::size_t k = 1; k < N; ++k) {
      floor_[k] = std::max({std::exp(log_rmin + span * static_cast<double>(k) / N), above_rmin, floor_[k - 1]});
    }
    // The finest buckets whose keys from rmin to rmax fit the table (rmin > 0 and finite here).
    const auto bits_min = std::bit_cast<std::uint64_t>(rmin);
    const auto bits_max = std::bit_cast<std::uint64_t>(rmax);
    shift_ = 0;
    while (shift_ < 63 && (bits_max >> shift_) - (bits_min >> shift_) >= kTable) {
      ++shift_;
    }
    key0_ = bits_min >> shift_;
    rmin_ = rmin;
    for (std::size_t i = 0; i < kTable; ++i) {
      const std::uint64_t bottom = (key0_ + i) << shift_;
      // Keys past rmax's get its class's table entry (of() clamps to the last one it needs).
      table_[i] = static_cast<std::uint8_t>(bottom <= bits_max ? search(std::max(rmin, std::bit_cast<double>(bottom)))
                                                               : table_[i - 1]);
    }
  }

  [[nodiscard]] int of(double r) const noexcept {
    if (!(r > rmin_)) {
      return 0;  // also NaN and, with rmin = rmax (rmin_ infinite), everything
    }
    const std::uint64_t i = (std::bit_cast<std::uint64_t>(r) >> shift_) - key0_;
    int k = table_[std::min<std::uint64_t>(i, kTable - 1)];
    k += r >= floor_[static_cast<std::size_t>(k) + 1] ? 1 : 0;
    while (r >= floor_[static_cast<std::size_t>(k) + 1]) {  // buckets wider than a class
      ++k;
    }
    return k;
  }

 private:
  // The class by bisection over the floors, for the table.
  [[nodiscard]] int search(double r) const noexcept {
    std::size_t k = 0;
    for (std::size_t step = std::bit_ceil(static_cast<std::size_t>(N)) / 2; step > 0; step /= 2) {
      k += k + step < N && r >= floor_[k + step] ? step : 0;
    }
    return static_cast<int>(k);
  }

  std::array<double, static_cast<std::size_t>(N) + 1> floor_;  // floor_[N]: NaN, a sentinel
  std::array<std::uint8_t, kTable> table_{};
  double rmin_ = std::numeric_limits<double>::infinity();
  std::uint64_t key0_ = 0;
  unsigned shift_ = 0;
};

/// The voids themselves, one bucket a radius class (RadiusClasses<N>), each a stack (the most
/// recent void first: its neighbourhood is the likeliest still in the cache), with a bit a class
/// saying whether its bucket holds any, so that the tightest class above a radius's is found
/// with a count of trailing zeros a 64 classes. Class 0 holds nothing: its radii are too small
/// for any disk drawn. Item is what a front keeps of a void (two or three element ids).
template <class Item, int N>
class VoidBuckets {
  static_assert(N >= 2 && N <= 256);
  static constexpr std::size_t kWords = (static_cast<std::size_t>(N) + 63) / 64;

 public:
  [[nodiscard]] bool empty() const noexcept {
    return std::all_of(mask_.begin(), mask_.end(), [](std::uint64_t w) { return w == 0; });
  }

  /// Keeps `v` in class k (0 < k < N).
  void push(int k, const Item& v) {
    const auto i = static_cast<std::size_t>(k);
    buckets_[i].push_back(v);
    mask_[i / 64] |= std::uint64_t{1} << (i % 64);
  }

  /// The lowest class above cls whose bucket holds a void, or -1.
  [[nodiscard]] int first_above(int cls) const noexcept {
    const auto from = static_cast<std::size_t>(cls + 1);
    for (std::size_t w = from / 64; w < kWords; ++w) {
      std::uint64_t bits = mask_[w];
      if (w == from / 64) {
        bits &= ~std::uint64_t{0} << (from % 64);
      }
      if (bits != 0) {
        return static_cast<int>(64 * w) + std::countr_zero(bits);
      }
    }
    return -1;
  }

  /// Takes the most recent void of class k, whose bucket holds one (first_above()).
  Item pop(int k) {
    const auto i = static_cast<std::size_t>(k);
    std::vector<Item>& bucket = buckets_[i];
    const Item v = bucket.back();
    bucket.pop_back();
    if (bucket.empty()) {
      mask_[i / 64] &= ~(std::uint64_t{1} << (i % 64));
    }
    return v;
  }

  /// Frees the buckets' memory (before the output grows).
  void release() {
    for (auto& bucket : buckets_) {
      std::vector<Item>().swap(bucket);
    }
  }

 private:
  std::array<std::vector<Item>, static_cast<std::size_t>(N)> buckets_;
  std::array<std::uint64_t, kWords> mask_{};  // bit k: buckets_[k] holds a void
};

}  // namespace frontpack::detail
