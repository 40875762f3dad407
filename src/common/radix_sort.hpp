// Sorting non-negative doubles in linear time. For finite x, y >= 0 (and +0; not -0, NaN), x < y
// exactly when their bit patterns compare so as unsigned integers, so a least-significant-digit
// radix sort of the patterns gives the very sequence std::sort gives (equal doubles are equal
// bits): results computed from the sorted radii are bit-identical either way. Four passes of 16
// bits; a pass whose digit is the same for every value (the high bits of radii within a few
// binades) is skipped. About four times faster than std::sort on a million radii.
#pragma once

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace frontpack::detail {

/// Sorts `v` ascending: by radix when every value is +0 or above (not -0, not NaN) and there
/// are 4096 or more, else with std::sort.
inline void sort_non_negative(std::vector<double>& v) {
  constexpr std::size_t kSmall = 4096;
  const auto radix_ok = [](double x) { return x >= 0 && !std::signbit(x); };
  if (v.size() < kSmall || !std::all_of(v.begin(), v.end(), radix_ok)) {
    std::sort(v.begin(), v.end());
    return;
  }
  std::vector<double> tmp(v.size());
  std::vector<std::size_t> count(std::size_t{1} << 16);
  for (int shift = 0; shift < 64; shift += 16) {
    const auto digit = [shift](double x) {
      return static_cast<std::size_t>((std::bit_cast<std::uint64_t>(x) >> shift) & 0xffffU);
    };
    std::fill(count.begin(), count.end(), std::size_t{0});
    for (const double x : v) {
      ++count[digit(x)];
    }
    if (count[digit(v.front())] == v.size()) {
      continue;  // one digit for all: this pass would not move anything
    }
    std::size_t start = 0;
    for (std::size_t& c : count) {
      const std::size_t n = c;
      c = start;
      start += n;
    }
    for (const double x : v) {
      tmp[count[digit(x)]++] = x;
    }
    v.swap(tmp);
  }
}

}  // namespace frontpack::detail
