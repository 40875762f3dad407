// frontpack's random source: xoshiro256** seeded by splitmix64. Written out here (a few lines)
// rather than taken from <random> so that a seed gives the same stream on every standard
// library: std::mt19937_64 would too, but the distributions built on it would not.
#pragma once

#include <cstdint>

namespace frontpack::detail {

/// splitmix64 (Steele, Lea & Flood 2014) at `state`: the output of the generator whose state
/// was `state` before its step, a 64-bit hash of `state` with every bit mixed. The seed mixer of
/// Rng, and the hash of the stratified sampling in stats.
[[nodiscard]] constexpr std::uint64_t splitmix64(std::uint64_t state) noexcept {
  std::uint64_t z = state + 0x9e3779b97f4a7c15ULL;
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

class Rng {
 public:
  explicit Rng(std::uint64_t seed) noexcept {
    for (std::uint64_t& word : s_) {
      word = splitmix64(seed);
      seed += 0x9e3779b97f4a7c15ULL;
    }
  }

  std::uint64_t next() noexcept {
    const std::uint64_t result = rotl(s_[1] * 5, 7) * 9;
    const std::uint64_t t = s_[1] << 17;
    s_[2] ^= s_[0];
    s_[3] ^= s_[1];
    s_[1] ^= s_[2];
    s_[0] ^= s_[3];
    s_[2] ^= t;
    s_[3] = rotl(s_[3], 45);
    return result;
  }

  /// Uniform in [0, 1), a multiple of 2^-53: exact, platform independent.
  double uniform() noexcept { return static_cast<double>(next() >> 11) * 0x1p-53; }

 private:
  static std::uint64_t rotl(std::uint64_t x, int k) noexcept { return (x << k) | (x >> (64 - k)); }
  std::uint64_t s_[4]{};
};

}  // namespace frontpack::detail
