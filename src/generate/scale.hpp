// The generators' units of length: a power-of-two scale (exact) that keeps squares of lengths
// finite and normal at every scale the library accepts.
#pragma once

#include <algorithm>
#include <cmath>

namespace frontpack::detail {

/// A power of two that brings lengths of the order of `length` (a run's largest radius) to about 1.
/// Multiplying by it rounds nothing, so a computation done at that scale and scaled back gives the
/// same bits, but its squares and fourth powers neither overflow nor underflow at any scale the
/// library accepts (lengths of 1e80 or 1e-80).
struct LengthScale {
  double k = 1;      // lengths are multiplied by this
  double inv_k = 1;  // and the results by this
  LengthScale() = default;
  explicit LengthScale(double length) {
    if (std::isfinite(length) && length > 0) {
      const int e = std::clamp(std::ilogb(length), -1000, 1000);
      k = std::ldexp(1.0, -e);
      inv_k = std::ldexp(1.0, e);
    }
  }
};

/// The generators' unit of length. A run multiplies every length it is given (coordinates relative
/// to its box's corner, radii, the clearance) by k, a power of two (exact), and its disks by inv_k
/// on the way out. k is 1 for rmax in [2^-300, 2^300] (about 5e-91 to 2e90), which covers every
/// domain of ordinary size: their packings are the ones computed without it, bit for bit. Outside,
/// k = 2^-ilogb(rmax) brings rmax to [1, 2) (k at most 2^1000: a subnormal rmax stays below that),
/// so that the squares in the overlap tests and the clearance's band around them stay normal
/// numbers and finite: at 1e-200 they underflowed to 0, and with radii of 1e200 to 1e300 every
/// pair of disks, their squared distances infinite, tested clear; either way the floating-point
/// filter decided nothing and a run did not end. A domain that small packs as it does at 1.
struct WorkScale {
  double k = 1;
  double inv_k = 1;
  WorkScale() = default;
  explicit WorkScale(double rmax) {
    if ((rmax > 0 && rmax < 0x1p-300) || (rmax > 0x1p300 && std::isfinite(rmax))) {
      const LengthScale s(rmax);
      k = s.k;
      inv_k = s.inv_k;
    }
  }
};

}  // namespace frontpack::detail
