#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <optional>
#include <vector>

#include "check.hpp"
#include "frontpack/domain.hpp"
#include "frontpack/errors.hpp"
#include "frontpack/fill.hpp"
#include "fuzz_targets.hpp"

namespace frontpack::fuzz {

namespace {

// Reads the input from the front; past its end, zeros (so every input decodes to something).
class Bytes {
 public:
  Bytes(const std::uint8_t* data, std::size_t size) : data_(data), size_(size) {}
  std::uint8_t byte() { return pos_ < size_ ? data_[pos_++] : 0; }
  std::uint16_t u16() { return static_cast<std::uint16_t>(byte() | (byte() << 8)); }
  std::uint64_t u64() {
    std::uint64_t v = 0;
    for (int i = 0; i < 8; ++i) {
      v = (v << 8) | byte();
    }
    return v;
  }
  /// In [0, 1].
  double unit() { return u16() / 65535.0; }
  [[nodiscard]] bool empty() const { return pos_ >= size_; }

 private:
  const std::uint8_t* data_;
  std::size_t size_;
  std::size_t pos_ = 0;
};

// A ring around (cx, cy): a star-shaped polygon with `n` vertices at angles in order and radii
// from the bytes, so that most rings are simple; some bytes make spikes, slivers and wiggles.
Ring star(Bytes& in, double cx, double cy, double size, std::size_t n) {
  Ring ring;
  for (std::size_t k = 0; k < n; ++k) {
    const double angle = 2 * 3.141592653589793 * (static_cast<double>(k) + 0.9 * in.unit()) / static_cast<double>(n);
    const std::uint8_t mode = in.byte();
    double rho = size * (0.05 + in.unit());
    if (mode == 255) {
      rho *= 1e6;  // a spike
    } else if (mode == 254) {
      rho *= 1e-9;  // a pinch towards the centre
    }
    Point p{cx + rho * std::cos(angle), cy + rho * std::sin(angle)};
    if (mode == 253 && !ring.empty()) {
      p = ring.back();                     // a repeated vertex
      p.x = std::nextafter(p.x, p.x + 1);  // one ulp off: a wiggle
    }
    ring.push_back(p);
  }
  return ring;
}

bool same_packing(const Packing& a, const Packing& b) {
  return a.disks.size() == b.disks.size() &&
         (a.disks.empty() || std::memcmp(a.disks.data(), b.disks.data(), a.disks.size() * sizeof(Disk)) == 0);
}

}  // namespace

void fill(const std::uint8_t* data, std::size_t size) {
  Bytes in(data, size);
  // Scale 2^-30 .. 2^30 (about 1e-9 .. 1e9) and offset up to 2^30 times the scale or 1e9.
  const double scale = std::ldexp(1.0, static_cast<int>(in.byte() % 61) - 30);
  const std::uint8_t where = in.byte();
  const double offset = where < 200 ? scale * (where - 100) : 1e9 * (where - 227);
  std::vector<Polygon> polygons;
  const std::size_t parts = 1 + in.byte() % 2;
  for (std::size_t p = 0; p < parts; ++p) {
    Polygon poly;
    const double cx = offset + 3 * scale * static_cast<double>(p);
    poly.outer = star(in, cx, offset, scale, 3 + in.byte() % 10);
    const std::size_t holes = in.byte() % 3;
    for (std::size_t h = 0; h < holes; ++h) {
      poly.holes.push_back(star(in, cx + scale * (in.unit() - 0.5) * 0.4, offset + scale * (in.unit() - 0.5) * 0.4,
                                0.1 * scale, 3 + in.byte() % 5));
    }
    polygons.push_back(std::move(poly));
  }
  std::optional<Domain> domain;
  try {
    domain = Domain::from_polygons(std::move(polygons));
  } catch (const Error&) {
    return;
  }
  FillOptions options;
  options.method = (in.byte() & 1) != 0 ? Method::open : Method::closed;
  options.seed = in.u64();
  const std::uint8_t window = in.byte();
  options.window = window < 200 ? 5 : window % 8;  // mostly the paper's 5; sometimes 0 (whole front)..7
  options.max_disks = 20'000;                      // bounded work per input
  try {
    // rmax from the domain's size down to 2^-10 of it; rmax / rmin up to 1024.
    const Box b = domain->bbox();
    const double extent = std::max(b.width(), b.height());
    const double rmax = extent * std::ldexp(1.0 + in.unit(), -static_cast<int>(in.byte() % 11));
    const double rmin = rmax * std::ldexp(1.0, -static_cast<int>(in.byte() % 11));
    options.radii = (in.byte() & 1) != 0 ? Radii::constant(rmax) : Radii::uniform(rmin, rmax);
  } catch (const Error&) {
    return;
  }
  if (std::getenv("FRONTPACK_FUZZ_VERBOSE") != nullptr) {  // to reproduce a finding by hand
    const RadiusDistribution& r = options.radii.distribution();
    std::fprintf(stderr, "domain %s\nmethod %s seed %llu window %zu radii [%.17g, %.17g]\n", domain->to_wkt().c_str(),
                 to_string(options.method), static_cast<unsigned long long>(options.seed), options.window, r.min(),
                 r.max());
  }
  Packing packing;
  try {
    packing = frontpack::fill(*domain, options);
  } catch (const Error&) {
    return;  // refused (LimitError, OptionError): a clear error
  }
  const Certificate& c = packing.certificate;
  check(c.exact, "every decision exact");
  check(c.dropped == 0, "the generator never emits an overlap");
  check(c.generated >= packing.disks.size() && c.generated - c.culled - c.dropped == packing.disks.size(),
        "the certificate's counts add up");
  const CertifyReport again = certify(*domain, packing.disks);
  check(again.outside.empty(), "every output disk is inside the domain");
  check(again.overlapping.empty(), "no two output disks overlap");
  if (in.byte() % 8 == 0) {  // now and then: the same input gives the same bits
    check(same_packing(frontpack::fill(*domain, options), packing), "same seed, same packing");
  }
}

}  // namespace frontpack::fuzz
