#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <optional>
#include <vector>

#include "check.hpp"
#include "frontpack/deck.hpp"
#include "frontpack/domain.hpp"
#include "frontpack/errors.hpp"
#include "frontpack/fill.hpp"
#include "fuzz_targets.hpp"

// The input layout. Every input decodes to something (past its end the bytes read as zeros).
//
//   scale, offset, parts          3 bytes
//   the star rings of each part   see star(); 1-2 parts, 0-2 holes each
//   method                        1 byte m: m % 12 in 6..9: boundary; otherwise bit 0: open (1) / closed (0)
//   seed, window                  8 + 1 bytes
//   radii                         2 + 1 + 1 + 1 bytes: rmax / extent, its power of 2, rmax / rmin, constant?
//   repeat                        1 byte: % 8 == 0: fill twice and compare; bit 3 set: fill_voids = false
//   extension (optional)          whatever follows: a first byte % 8 < 6 picks a shaped domain (shaped())
//                                 that replaces the star rings; 6 keeps them (nothing more is read); 7
//                                 keeps them and reads one more byte p: p % 4 == 1 fills the rings' box
//                                 as a periodic cell in x and y instead, p % 4 == 2 as a shear cell
//                                 (periodic in x, walls at the bottom and top), p % 4 == 3 fills
//                                 the rings with the jam stage (FillOptions::jam), at most 2,000 disks
//                                 and about 16,000 relaxation steps (run_fill()); p % 4 == 0 with
//                                 bytes after it: the budget knobs (Knobs), a small max_disks and
//                                 memory_limit for the fill, then wall disks of a chosen radius
//                                 (down to far below the coordinates' precision) within that budget
//
// Why this encoding: the inputs made before the boundary method and fill_voids (the 32 corpus
// seeds and the 2 regressions committed before) must keep their meaning, and that layout read
// only bit 0 of the method byte, only bits 0-2 of the repeat byte and nothing after the repeat
// byte. So:
// - boundary takes 4 of the 12 residues of m (a third of all method bytes, of both parities); the
//   other 8 keep bit 0's meaning. The committed method bytes are 0 (most inputs end before it),
//   245, 118 and 131 (seeds 12, 20, 31) and 206 and 255 (the two regressions): 0, 5, 10, 11, 2 and
//   3 mod 12, none of them boundary. ("(m >> 1) % 3 == k" would have turned the zeros, or those
//   three seeds, or both regressions into boundary runs, whichever k.)
// - fill_voids = false needs bit 3 of the repeat byte, clear in every committed input (they ran
//   with the default, true).
// - the extension is read only where the old layout read nothing; the one committed input with
//   bytes there (seed_20, 13 bytes) has 54 = 6 mod 8 first, which keeps its star rings.
// Each committed input therefore decodes to the very domain and options it did before, with every
// compiler: the reads are now sequenced in the order Clang (libFuzzer's compiler, which made the
// inputs) happened to evaluate the old code's unsequenced ones (a hole's centre and vertex count,
// rmax's mantissa and exponent); GCC evaluated them the other way round, so the unit tests' replay
// (GCC builds) decoded 9 of the 34 committed inputs, both regressions among them, into other domains.

namespace frontpack::fuzz {

namespace {

// Reads the input from the front; past its end, zeros (so every input decodes to something).
class Bytes {
 public:
  Bytes(const std::uint8_t* data, std::size_t size) : data_(data), size_(size) {}
  std::uint8_t byte() {
    const std::uint8_t b = pos_ < size_ ? data_[pos_] : 0;
    ++pos_;
    return b;
  }
  std::uint16_t u16() {
    const std::uint8_t lo = byte();  // sequenced: the first byte is the low one, with every compiler
    const std::uint8_t hi = byte();
    return static_cast<std::uint16_t>(lo | (hi << 8));
  }
  std::uint64_t u64() {
    std::uint64_t v = 0;
    for (int i = 0; i < 8; ++i) {
      v = (v << 8) | byte();
    }
    return v;
  }
  /// In [0, 1].
  double unit() { return u16() / 65535.0; }
  /// 2^-(byte % n): a ratio from 1 down to 2^-(n - 1).
  double tiny(int n) { return std::ldexp(1.0, -(in_range(n))); }
  /// byte % n.
  int in_range(int n) { return static_cast<int>(byte() % static_cast<unsigned>(n)); }
  [[nodiscard]] bool empty() const { return pos_ >= size_; }
  /// How many bytes have been read (past the end too): where the next field starts.
  [[nodiscard]] std::size_t pos() const { return pos_; }

 private:
  const std::uint8_t* data_;
  std::size_t size_;
  std::size_t pos_ = 0;
};

// splitmix64: the many vertices of a jagged ring from a few input bytes.
class Mix {
 public:
  explicit Mix(std::uint64_t seed) : s_(seed) {}
  std::uint64_t next() {
    std::uint64_t z = (s_ += 0x9e3779b97f4a7c15ULL);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
  }
  /// In [0, 1).
  double unit() { return static_cast<double>(next() >> 11) * 0x1p-53; }

 private:
  std::uint64_t s_;
};

constexpr double kPi = 3.141592653589793;

// A ring around (cx, cy): a star-shaped polygon with `n` vertices at angles in order and radii
// from the bytes, so that most rings are simple; some bytes make spikes, slivers and wiggles.
Ring star(Bytes& in, double cx, double cy, double size, std::size_t n) {
  Ring ring;
  for (std::size_t k = 0; k < n; ++k) {
    const double angle = 2 * kPi * (static_cast<double>(k) + 0.9 * in.unit()) / static_cast<double>(n);
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

// ---------------------------------------------------------------------------------------------
// Shaped domains (the extension): rings aimed at the boundary method, which takes the edges as
// walls and the reflex vertices as obstacles, so edge lengths, turning angles and the distances
// between rings matter to it where the box-and-cull forms only ever see the domain through the
// exact containment test. Built in unit coordinates (about [0, 1] or [-1, 1]), then rotated,
// scaled and moved by shaped().

Point along(Point a, Point b, double t) {
  return {a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)};
}

// The left normal of a -> b times `d` (inward for an anticlockwise ring), added to p.
Point off(Point p, Point a, Point b, double d) {
  const double len = std::hypot(b.x - a.x, b.y - a.y);
  return {p.x - d * (b.y - a.y) / len, p.y + d * (b.x - a.x) / len};
}

// A regular m-gon of circumradius 1 about the origin, anticlockwise.
Ring regular(std::size_t m, double phase) {
  Ring ring;
  for (std::size_t k = 0; k < m; ++k) {
    const double angle = phase + 2 * kPi * static_cast<double>(k) / static_cast<double>(m);
    ring.push_back({std::cos(angle), std::sin(angle)});
  }
  return ring;
}

// Many vertices (16 .. 4096): a star-shaped ring whose radii jitter by 1 .. 2^-47 (from a jagged
// saw down to a circle whose neighbouring edges are nearly collinear), with deep teeth now and
// then, angles evenly spaced or jittered (very short edges next to long ones); maybe a jagged
// hole inside it.
std::vector<Polygon> jagged(Bytes& in) {
  const std::size_t n = 16 + in.u16() % 4081U;
  const double amp = 0.95 * in.tiny(48);
  const std::uint8_t teeth = in.byte();  // chance of a deep tooth per vertex, in 1/256
  const double depth = 0.02 + 0.9 * in.unit();
  const double jitter = (in.byte() & 1) != 0 ? 0.999 : 0.0;
  const std::uint8_t hole = in.byte();
  Mix mix(in.u64());
  auto ring = [&](std::size_t count, double size) {
    Ring r;
    for (std::size_t k = 0; k < count; ++k) {
      const double angle = 2 * kPi * (static_cast<double>(k) + jitter * mix.unit()) / static_cast<double>(count);
      double rho = 1 - amp * mix.unit();
      if (mix.next() % 256 < teeth) {
        rho *= depth;
      }
      r.push_back({size * rho * std::cos(angle), size * rho * std::sin(angle)});
    }
    return r;
  };
  Polygon poly;
  poly.outer = ring(n, 1.0);
  if (hole % 3 != 0) {
    // Inside the smallest radius of the outer ring: the hole's farthest vertex at 0.1 .. 0.999 of it.
    double inner = 1;
    for (const Point& p : poly.outer) {
      inner = std::min(inner, std::hypot(p.x, p.y));
    }
    const double reach = 1 - 0.9 * std::ldexp(1.0, -static_cast<int>(hole % 11));
    poly.holes.push_back(ring(std::max<std::size_t>(3, n / (1U + hole % 7U)), reach * inner * std::cos(kPi / 3)));
  }
  return {poly};
}

// A star of 3 .. 10 vertices whose edges are each left alone or given a very short edge at one
// end (straight on, or bent in or out: a sharp turn over a tiny length), or split into a run of
// nearly collinear vertices, each off the line by 2^-10 .. 2^-59 of the edge either way or not at
// all (slightly convex, slightly reflex and exactly straight corners).
std::vector<Polygon> edges(Bytes& in) {
  const std::size_t m = 3 + static_cast<std::size_t>(in.in_range(8));
  Ring base;
  for (std::size_t k = 0; k < m; ++k) {
    const double angle = 2 * kPi * (static_cast<double>(k) + 0.5 * in.unit()) / static_cast<double>(m);
    const double rho = 0.5 + 0.5 * in.unit();
    base.push_back({rho * std::cos(angle), rho * std::sin(angle)});
  }
  Ring ring;
  for (std::size_t k = 0; k < m; ++k) {
    const Point a = base[k];
    const Point b = base[(k + 1) % m];
    const std::uint8_t f = in.byte();
    ring.push_back(a);
    const double len = std::hypot(b.x - a.x, b.y - a.y);
    switch (f % 4) {
      case 1:
      case 2: {  // a short edge at a (1) or at b (2), then (before) the long rest of the edge
        const double t = std::ldexp(1.0, -(8 + in.in_range(45)));
        static constexpr double bends[] = {0, 0x1p-30, 0x1p-12, 1, -1, 0.25, -0x1p-30, -0x1p-12};
        const double bend = bends[(f >> 2) % 8] * t * len;
        ring.push_back(off(f % 4 == 1 ? along(a, b, t) : along(b, a, t), a, b, bend));
        break;
      }
      case 3: {  // nearly collinear vertices along the edge
        const std::size_t s = 1 + static_cast<std::size_t>(in.in_range(31));
        const int e = 10 + in.in_range(50);
        const std::uint8_t signs = in.byte();
        for (std::size_t i = 1; i <= s; ++i) {
          const unsigned bit = static_cast<unsigned>(i % 8);
          const double d = (f & 0x80) != 0 && i % 3 == 0 ? 0 : ((signs >> bit) & 1) != 0 ? 1 : -1;
          ring.push_back(
              off(along(a, b, static_cast<double>(i) / static_cast<double>(s + 1)), a, b, d * std::ldexp(len, -e)));
        }
        break;
      }
      default: break;
    }
  }
  return {Polygon{ring, {}}};
}

// A regular 3- to 8-gon whose edges may carry a thin spike outwards (its tip a very sharp convex
// corner, its foot two reflex ones) and/or a thin notch in towards the centre (its tip a reflex
// corner of almost 360 degrees), each 2^0 .. 2^-44 of the edge wide at its foot.
std::vector<Polygon> spikes(Bytes& in) {
  const std::size_t m = 3 + static_cast<std::size_t>(in.in_range(6));
  const Ring base = regular(m, 2 * kPi * in.unit());
  const double apothem = std::cos(kPi / static_cast<double>(m));
  Ring ring;
  for (std::size_t k = 0; k < m; ++k) {
    const Point a = base[k];
    const Point b = base[(k + 1) % m];
    const std::uint8_t f = in.byte();
    const double width = 0.12 * in.tiny(45);  // half the foot, as a fraction of the edge
    const double length = in.unit();
    ring.push_back(a);
    if ((f & 1) != 0) {  // outwards, its foot at 0.25 .. 0.75 of the edge (0.25 if there is a notch too)
      const double at = (f & 2) != 0 ? 0.25 : 0.25 + 0.5 * in.unit();
      ring.push_back(along(a, b, at - width));
      ring.push_back(off(along(a, b, at), a, b, -(0.01 + 3 * length)));
      ring.push_back(along(a, b, at + width));
    }
    if ((f & 2) != 0) {  // inwards, along the line to the centre
      ring.push_back(along(a, b, 0.5 - width));
      ring.push_back(off(along(a, b, 0.5), a, b, apothem * (0.01 + 0.85 * length)));
      ring.push_back(along(a, b, 0.5 + width));
    }
  }
  return {Polygon{ring, {}}};
}

// A rectangle (or an L: a reflex corner) with 1 .. 3 holes close to its walls, to its reflex
// corner or to each other, 2^-1 .. 2^-52 away: a wall and a hole facing each other across a
// channel (a square hole) or a pinch (a diamond's vertex towards the wall).
std::vector<Polygon> holes_near(Bytes& in) {
  const double h = 0.25 + 1.75 * in.unit();
  const bool l_shape = (in.byte() & 1) != 0;
  Polygon poly;
  if (l_shape) {  // the upper right quarter cut away: a reflex corner at (0.5, h / 2)
    poly.outer = {{0, 0}, {1, 0}, {1, h / 2}, {0.5, h / 2}, {0.5, h}, {0, h}};
  } else {
    poly.outer = {{0, 0}, {1, 0}, {1, h}, {0, h}};
  }
  const std::size_t count = 1 + static_cast<std::size_t>(in.in_range(3));
  const double size = (0.02 + 0.9 * in.unit()) * std::min(0.2, h / 8);  // half the hole's width
  std::vector<Point> centres;  // of the holes kept; each hole's box is its centre +- size
  for (std::size_t i = 0; i < count; ++i) {
    const std::uint8_t f = in.byte();
    const double gap = 0.5 * in.tiny(52);
    const bool diamond = (f & 4) != 0;
    Point c{0.1 + 0.3 * in.unit(), h / 4};  // the hole's centre; moved next to its target below
    bool at_corner = false;
    switch (f % 4) {
      case 0: c.y = gap + size; break;  // above the bottom wall
      case 1: c.x = gap + size; break;  // right of the left wall
      case 2:  // a vertex of it next to the reflex corner, at (0.5 - gap, h / 2 + gap); or by the right wall
        if (l_shape) {
          c = {0.5 - gap - size, h / 2 + gap + (diamond ? 0 : size)};
          at_corner = true;
        } else {
          c.x = 1 - gap - size;
        }
        break;
      default:  // right of the previous hole
        if (!centres.empty()) {
          c = {centres.back().x + 2 * size + gap, centres.back().y};
        }
        break;
    }
    // Keep it only if it lies inside the outer ring and apart from the other holes (boxes).
    bool ok = c.x - size > 0 && c.x + size < 1 && c.y - size > 0 && c.y + size < h &&
              (at_corner || !l_shape || c.x + size < 0.5 || c.y + size < h / 2);
    for (const Point& o : centres) {
      ok = ok && (std::abs(c.x - o.x) > 2 * size || std::abs(c.y - o.y) > 2 * size);
    }
    if (!ok) {
      continue;
    }
    centres.push_back(c);
    if (diamond) {
      poly.holes.push_back({{c.x, c.y - size}, {c.x + size, c.y}, {c.x, c.y + size}, {c.x - size, c.y}});
    } else {
      poly.holes.push_back(
          {{c.x - size, c.y - size}, {c.x + size, c.y - size}, {c.x + size, c.y + size}, {c.x - size, c.y + size}});
    }
  }
  return {poly};
}

// Slivers 2^-1 .. 2^-44 wide (narrower than 2 rmin for most radii): a needle triangle, a thin
// strip, two squares joined by a thin channel, a square with a thin strip beside it (a second
// part, just apart) or a thin slit of a hole in a square.
std::vector<Polygon> slivers(Bytes& in) {
  const std::uint8_t f = in.byte();
  const double w = 0.5 * in.tiny(44);
  const double t = in.unit();
  switch (f % 5) {
    case 0: return {Polygon{{{0, 0}, {1, 0}, {t, w}}, {}}};
    case 1: return {Polygon{{{0, 0}, {1, 0}, {1, w}, {0, w}}, {}}};
    case 2: {
      const double c = 0.02 + t;  // the channel's length
      const double y0 = (1 - w) * in.unit();
      return {Polygon{{{0, 0},
                       {1, 0},
                       {1, y0},
                       {1 + c, y0},
                       {1 + c, 0},
                       {2 + c, 0},
                       {2 + c, 1},
                       {1 + c, 1},
                       {1 + c, y0 + w},
                       {1, y0 + w},
                       {1, 1},
                       {0, 1}},
                      {}}};
    }
    case 3: {
      const double gap = 0.5 * in.tiny(52);
      return {Polygon{{{0, 0}, {1, 0}, {1, 1}, {0, 1}}, {}},
              Polygon{{{0, 1 + gap}, {t + 0.01, 1 + gap}, {t + 0.01, 1 + gap + w}, {0, 1 + gap + w}}, {}}};
    }
    default: {
      const double y0 = 0.25 + 0.5 * in.unit();
      return {Polygon{{{0, 0}, {1, 0}, {1, 1}, {0, 1}}, {{{0.1, y0}, {0.1, y0 + w}, {0.9, y0 + w}, {0.9, y0}}}}};
    }
  }
}

// A comb: 1 .. 200 teeth of random heights on a base 2^0 .. 2^-29 thick; the teeth and the gaps
// between them from a few percent of the pitch up to almost all of it (slivers of the domain, and
// slots narrower than the disks), many short edges next to long ones, a reflex corner at every
// root.
std::vector<Polygon> comb(Bytes& in) {
  const std::size_t teeth = 1 + static_cast<std::size_t>(in.in_range(200));
  const double pitch = 1.0 / static_cast<double>(teeth);
  const double tooth = pitch * (0.01 + 0.98 * in.unit());
  const double base = in.tiny(30);
  const double height = 0.05 + 2 * in.unit();
  const double vary = in.unit();
  Mix mix(in.u64());
  Ring ring{{0, 0}, {1, 0}, {1, base}};
  for (std::size_t i = teeth; i-- > 0;) {
    const double x0 = static_cast<double>(i) * pitch + (pitch - tooth) / 2;
    const double top = base + height * (1 - vary * mix.unit());
    ring.insert(ring.end(), {{x0 + tooth, base}, {x0 + tooth, top}, {x0, top}, {x0, base}});
  }
  ring.push_back({0, base});
  return {Polygon{ring, {}}};
}

// The extension: a shaped domain, rotated (or not), at the given scale, moved to the given offset
// plus (sometimes) 1e6 (absolute, or times the scale: coordinates far larger than the shape), and
// with `parts` = 2 a copy beside it, 2^0 .. 2^-50 of its width apart.
std::vector<Polygon> shaped(Bytes& in, int kind, double scale, double offset, std::size_t parts) {
  const std::uint8_t turn = in.byte();
  static constexpr double shifts[] = {0, 0, 0, 0, 1e6, -1e6, 1e6, -3.3e6};
  const std::uint8_t shift = in.byte();
  const double move = offset + (shift % 8 < 6 ? shifts[shift % 8] : shifts[shift % 8] * scale);
  const double apart = in.tiny(51);
  std::vector<Polygon> polygons;
  switch (kind) {
    case 0: polygons = jagged(in); break;
    case 1: polygons = edges(in); break;
    case 2: polygons = spikes(in); break;
    case 3: polygons = holes_near(in); break;
    case 4: polygons = slivers(in); break;
    default: polygons = comb(in); break;
  }
  if (parts == 2) {
    double xmin = INFINITY;
    double xmax = -INFINITY;
    for (const Polygon& poly : polygons) {
      for (const Point& p : poly.outer) {
        xmin = std::min(xmin, p.x);
        xmax = std::max(xmax, p.x);
      }
    }
    const double dx = (xmax - xmin) * (1 + apart);
    const std::size_t count = polygons.size();
    for (std::size_t i = 0; i < count; ++i) {
      Polygon copy = polygons[i];
      for (Point& p : copy.outer) {
        p.x += dx;
      }
      for (Ring& hole : copy.holes) {
        for (Point& p : hole) {
          p.x += dx;
        }
      }
      polygons.push_back(std::move(copy));
    }
  }
  // Exact axis-aligned coordinates (turn < 128) or rotated by a multiple of 2 pi / 128.
  const double angle = turn < 128 ? 0 : 2 * kPi * (turn - 128) / 128.0;
  const double c = turn < 128 ? 1 : std::cos(angle);
  const double s = turn < 128 ? 0 : std::sin(angle);
  auto place = [&](Ring& ring) {
    for (Point& p : ring) {
      p = {move + scale * (c * p.x - s * p.y), move + scale * (s * p.x + c * p.y)};
    }
  };
  for (Polygon& poly : polygons) {
    place(poly.outer);
    for (Ring& hole : poly.holes) {
      place(hole);
    }
  }
  return polygons;
}

bool verbose() {
  return std::getenv("FRONTPACK_FUZZ_VERBOSE") != nullptr;
}

// A clean refusal (an invalid domain, a request over the limits); said only when reproducing by hand.
void refused(const Error& e) {
  if (verbose()) {
    std::fprintf(stderr, "refused: %s\n", e.what());
  }
}

// The budget knobs (kind 7, p % 4 == 0): what the fill and the wall disks may make, and the wall
// radius as a power of 2 times rmin, from 2^7 down to 2^-120 (the precision floor at unit
// coordinates is about 2^-29): each derived count must be refused up front or made within the
// budget, never found as an allocation failure or a long run.
struct Knobs {
  Budget budget;
  double wall_scale = 1;  // wall radius / rmin
};

Knobs read_knobs(Bytes& in) {
  Knobs k;
  k.budget.max_count = std::size_t{1} << in.in_range(16);                     // 1 .. 32,768
  const int memory = in.in_range(16);                                         // 0: three quarters of the machine's
  k.budget.memory_limit = memory == 0 ? 0 : std::size_t{1} << (12 + memory);  // 8 KB .. 128 MB
  const double mantissa = in.unit();                                          // read in this order with every compiler
  k.wall_scale = std::ldexp(1.0 + mantissa, 7 - in.in_range(128));
  return k;
}

// Wall disks within `knobs`: refused (LimitError, OptionError), or at most max_count of them, every
// one outside the domain.
void check_walls(const Domain& domain, double rmin, const Knobs& knobs) {
  std::vector<Disk> walls;
  try {
    walls = wall_disks(domain, rmin * knobs.wall_scale, rmin, knobs.budget);
  } catch (const Error& e) {
    refused(e);
    return;
  }
  if (verbose()) {
    std::fprintf(stderr, "wall disks: %zu\n", walls.size());
  }
  check(walls.size() <= knobs.budget.max_count, "no more wall disks than max_count");
  for (const Disk& w : walls) {
    check(domain.locate(w.centre) == Location::outside, "every wall disk's centre outside the domain");
  }
}

bool same_packing(const Packing& a, const Packing& b) {
  return a.disks.size() == b.disks.size() &&
         (a.disks.empty() || std::memcmp(a.disks.data(), b.disks.data(), a.disks.size() * sizeof(Disk)) == 0);
}

// The jam stage goes on while its rounds insert disks, and a crystal of constant radii takes one
// disk a round for a hundred rounds (76,895 relaxation steps for 900 disks: near the fuzzer's
// timeout under the sanitizers). Its progress reports come every 64 steps and after each round;
// past kJamReports the callback ends the stage, which undoes the round under way: the bound also
// runs that path, and it is the same for a seed, so a repeated fill gives the same bits.
constexpr std::size_t kJamReports = 256;

Packing run_fill(const Domain& domain, const FillOptions& options) {
  Generator generator(domain, options);
  std::size_t jam_reports = 0;
  generator.on_progress(
      [&jam_reports](const Progress& p) { return p.phase != Phase::jam || ++jam_reports <= kJamReports; });
  return generator.run();
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
      // Read in this order (x, y, vertex count) with every compiler, as Clang, which made the
      // committed inputs, evaluates the arguments of a call.
      const double hx = cx + scale * (in.unit() - 0.5) * 0.4;
      const double hy = offset + scale * (in.unit() - 0.5) * 0.4;
      const std::size_t n = 3 + in.byte() % 5;
      poly.holes.push_back(star(in, hx, hy, 0.1 * scale, n));
    }
    polygons.push_back(std::move(poly));
  }
  // The options' bytes, all read before the extension (rmax: mantissa, then exponent, as Clang read them).
  const std::size_t method_at = in.pos();
  const std::uint8_t method = in.byte();
  const std::uint64_t seed = in.u64();
  const std::uint8_t window = in.byte();
  const double rmax_mantissa = in.unit();
  const int rmax_exponent = static_cast<int>(in.byte() % 11);
  const int ratio_exponent = static_cast<int>(in.byte() % 11);
  const bool constant = (in.byte() & 1) != 0;
  const std::uint8_t repeat = in.byte();
  Periodicity periodicity = Periodicity::none;
  bool jam = false;
  std::optional<Knobs> knobs;
  const std::size_t extension_at = in.pos();
  if (!in.empty()) {
    const int kind = in.in_range(8);  // 6, 7: keep the star rings
    if (kind < 6) {
      polygons = shaped(in, kind, scale, offset, parts);
    } else if (kind == 7) {
      const int p = in.in_range(4);
      periodicity = p == 1 ? Periodicity::xy : p == 2 ? Periodicity::x : Periodicity::none;
      jam = p == 3;
      if (p == 0 && !in.empty()) {
        knobs = read_knobs(in);
      }
    }
  }

  std::optional<Domain> domain;
  try {
    domain = Domain::from_polygons(std::move(polygons));
    if (periodicity != Periodicity::none) {
      domain = Domain::periodic(domain->bbox(), periodicity);
    }
  } catch (const Error& e) {
    refused(e);
    return;
  }
  FillOptions options;
  options.method = method % 12 >= 6 && method % 12 <= 9 ? Method::boundary
                   : (method & 1) != 0                  ? Method::open
                                                        : Method::closed;
  options.seed = seed;
  options.window = window < 200 ? 5 : window % 8;  // mostly the paper's 5; sometimes 0 (whole front)..7
  options.fill_voids = (repeat & 0x08) == 0 || options.method == Method::boundary;  // boundary: always
  options.max_disks = jam ? 2'000 : 20'000;  // bounded work per input (a jam round relaxes every disk)
  if (knobs) {
    options.max_disks = std::min(options.max_disks, knobs->budget.max_count);
    options.memory_limit = knobs->budget.memory_limit;
  }
  options.jam = jam;
  try {
    // rmax from the domain's size down to 2^-10 of it; rmax / rmin up to 1024.
    const Box b = domain->bbox();
    const double extent = std::max(b.width(), b.height());
    double rmax = extent * std::ldexp(1.0 + rmax_mantissa, -rmax_exponent);
    if (periodicity != Periodicity::none) {
      // At most a tenth of the periods, which fill() requires (and a disk no larger than the cell).
      rmax = std::min({rmax, b.width() / 10, periodicity == Periodicity::xy ? b.height() / 10 : b.height() / 2});
    }
    const double rmin = rmax * std::ldexp(1.0, -ratio_exponent);
    options.radii = constant ? Radii::constant(rmax) : Radii::uniform(rmin, rmax);
  } catch (const Error& e) {
    refused(e);
    return;
  }
  if (verbose() && knobs) {
    std::fprintf(stderr, "knobs: max_count %zu memory_limit %zu wall radius %.17g rmin\n", knobs->budget.max_count,
                 knobs->budget.memory_limit, knobs->wall_scale);
  }
  if (verbose()) {  // to reproduce a finding by hand
    const RadiusDistribution& r = options.radii.distribution();
    std::fprintf(stderr,
                 "domain %s (%s)\nmethod %s seed %llu window %zu fill_voids %d max_disks %zu jam %d radii %s [%.17g, "
                 "%.17g]\n"
                 "bytes: method at %zu, extension at %zu\n",
                 domain->to_wkt().c_str(), to_string(domain->periodicity()), to_string(options.method),
                 static_cast<unsigned long long>(options.seed), options.window, options.fill_voids ? 1 : 0,
                 options.max_disks, options.jam ? 1 : 0, constant ? "constant" : "uniform", r.min(), r.max(), method_at,
                 extension_at);
  }
  Packing packing;
  try {
    packing = run_fill(*domain, options);
  } catch (const Error& e) {
    refused(e);
    return;  // refused (LimitError, OptionError): a clear error
  }
  const Certificate& c = packing.certificate;
  check(c.exact, "every decision exact");
  check(c.dropped == 0, "the generator never emits an overlap");
  if (options.method == Method::boundary) {
    check(c.culled == 0, "the boundary method never culls (every disk inside by construction)");
  }
  check(c.generated >= packing.disks.size() && c.generated - c.culled - c.dropped == packing.disks.size(),
        "the certificate's counts add up");
  const CertifyReport again = certify(*domain, packing.disks);
  check(again.outside.empty(), "every output disk is inside the domain");
  check(again.overlapping.empty(), "no two output disks overlap");
  if (repeat % 8 == 0) {  // now and then: the same input gives the same bits
    check(same_packing(run_fill(*domain, options), packing), "same seed, same packing");
  }
  if (knobs) {
    check(packing.disks.size() <= knobs->budget.max_count, "no more disks than max_count");
    check_walls(*domain, options.radii.min(), *knobs);
  }
}

}  // namespace frontpack::fuzz
