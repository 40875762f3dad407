// The Apollonius pockets of the boundary front's voids: the largest circle that touches three
// elements (disks, reflex vertices or walls) from outside, which bounds the disks a void can still
// take (Sec. 2.2's holes, bucketed by what they hold). Two pockets at once in the lanes of a
// vector, from the same templated source as the scalar ones, so with the same bits; then the
// pocket of three elements given by their ids (elements.hpp), which picks the solver for the walls
// among them. Header-only and CGAL-free: computed for every failed try at a gap.
#pragma once

#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <type_traits>
#include <utility>

#include "generate/boundary/elements.hpp"
#include "generate/boundary/walls.hpp"
#include "generate/scale.hpp"

namespace frontpack::detail {

// Lanes. pocket() computes one pocket in a double; a disk placed in a void needs two, which
// pocket_pair() computes in the two lanes of a vector (GCC's and Clang's vector extensions, whose
// + - * / and square root are the correctly rounded scalar operations lane by lane) from the same
// source, so with the same bits. Helpers that take either:
using V2 = double __attribute__((vector_size(16)));
using M2 = decltype(V2{} < V2{});  // a comparison of V2s: -1 true, 0 false (Clang and GCC name it differently)
template <class T>
T lanes(double a) noexcept {
  if constexpr (std::is_same_v<T, double>) {
    return a;
  } else {
    return T{a, a};
  }
}
inline double select(bool m, double a, double b) noexcept {
  return m ? a : b;
}
inline V2 select(M2 m, V2 a, V2 b) noexcept {
  return std::bit_cast<V2>((std::bit_cast<M2>(a) & m) | (std::bit_cast<M2>(b) & ~m));
}
inline bool lnot(bool m) noexcept {
  return !m;
}
inline M2 lnot(M2 m) noexcept {
  return ~m;
}
inline double square_root(double a) noexcept {
  return std::sqrt(a);
}
inline V2 square_root(V2 a) noexcept {
#if defined(__SSE2__)
  return __builtin_ia32_sqrtpd(a);
#else
  return V2{std::sqrt(a[0]), std::sqrt(a[1])};
#endif
}

// The smallest rho > 0 with |u + rho v| = ri + rho that `accept` takes, or -1; lane by lane in
// a V2 (pocket_of_nodes()). The quadratic qa rho^2 + qb rho + qc = 0 is solved without
// cancellation: with q = -(qb + sign(qb) sqrt(disc)) / 2 the roots are q / qa and qc / q. The
// textbook (-qb +- sqrt(disc)) / (2 qa) subtracts two nearly equal numbers when qa is near 0,
// which is where two equal disks resting on a wall's line put it (|v| = 1 but for rounding): the
// small root, their cusp, lost every digit and read as no pocket, so the cusp was kept as a void
// for every radius. qa = 0 (a linear equation) needs no case of its own: q / qa is infinite and
// refused, and qc / q is the linear root -qc / qb.
template <class T, class Accept>
inline T smallest_root(T ux, T uy, T vx, T vy, T ri, Accept accept) noexcept {
  const T qa = vx * vx + vy * vy - 1.0;
  const T qb = 2.0 * (ux * vx + uy * vy - ri);
  const T qc = ux * ux + uy * uy - ri * ri;
  constexpr double inf = std::numeric_limits<double>::infinity();
  // Whether rho is a root to take (positive, finite, accepted), without branches. A negative
  // discriminant (no root) gives NaN roots, which it refuses.
  auto ok = [&](T rho) { return (rho > 0.0) & (rho < inf) & accept(rho); };
  const T sq = square_root(qb * qb - 4.0 * qa * qc);
  const T q = -0.5 * (qb + select(qb < 0.0, -sq, sq));
  const T first = q / qa;
  const T second = qc / q;
  const auto ok_first = ok(first);
  const auto ok_second = ok(second);
  const T best = select(ok_first, first, lanes<T>(-1));
  return select(ok_second & (lnot(ok_first) | (second < first)), second, best);
}

// pocket() of three nodes (disks or reflex vertices) a, b, d, given by their centres and radii:
// in a double (T = double), or two triples in the lanes of a V2. A lane whose system is
// degenerate is -1 in a double and NaN in a V2 (a lane cannot branch): rare, and pocket_pair()
// computes it alone.
template <class T>
[[nodiscard]] inline T pocket_of_nodes(T ax, T ay, T ra, T bx, T by, T rb, T dx, T dy, T rd,
                                       const LengthScale& unit) noexcept {
  // Relative to a's centre: |p|^2 = (ra + rho)^2 and, subtracting, c_i . p = alpha_i + beta_i rho.
  // At the scale of rmax (`unit`): the degeneracy test below compares fourth powers of lengths.
  const double k = unit.k;
  bx = (bx - ax) * k;
  by = (by - ay) * k;
  dx = (dx - ax) * k;
  dy = (dy - ay) * k;
  ra = ra * k;
  rb = rb * k;
  rd = rd * k;
  const T alpha_b = (bx * bx + by * by - rb * rb + ra * ra) / 2.0;
  const T alpha_d = (dx * dx + dy * dy - rd * rd + ra * ra) / 2.0;
  const T beta_b = ra - rb;
  const T beta_d = ra - rd;
  const T det = bx * dy - by * dx;
  const T scale = (bx * bx + by * by) * (dx * dx + dy * dy);
  const auto regular = det * det > 1e-12 * scale;
  if constexpr (std::is_same_v<T, double>) {
    if (!regular) {
      return -1;
    }
  }
  const T inv = 1.0 / det;
  const T ux = (alpha_b * dy - alpha_d * by) * inv;
  const T uy = (bx * alpha_d - dx * alpha_b) * inv;
  const T vx = (beta_b * dy - beta_d * by) * inv;
  const T vy = (bx * beta_d - dx * beta_b) * inv;
  // On the left of a -> b: the pocket, not the circle on the far side.
  const T rho = smallest_root(ux, uy, vx, vy, ra, [&](T t) { return bx * (uy + t * vy) - by * (ux + t * vx) > 0.0; });
  const T scaled = select(rho < 0.0, rho, rho * unit.inv_k);
  if constexpr (std::is_same_v<T, double>) {
    return scaled;
  } else {
    return select(regular, scaled, lanes<T>(std::numeric_limits<double>::quiet_NaN()));
  }
}

// pocket() of a wall and two nodes i and j, i a reflex vertex at the wall's end (a gap at the
// corner, or the corner in its way): a circle touching the wall's line and passing through a point
// on it touches it there. Its centre is i + rho n, and it touches j from outside:
// |i + rho n - j| = rj + rho. (The general solution, pocket_at_line(), meets this as a double
// root, which rounding turns into none.)
template <class Node>
inline double pocket_at_wall_end(const Wall& wl, const Node& ni, const Node& nj) noexcept {
  const double cx = nj.x - ni.x;
  const double cy = nj.y - ni.y;
  const double den = 2 * (wl.nx * cx + wl.ny * cy + nj.r);
  const double rho = (cx * cx + cy * cy - nj.r * nj.r) / den;
  return rho > 0 && std::isfinite(rho) ? rho : -1;
}

// pocket() of a wall's line and two nodes i and j: the circle of radius rho at distance rho from
// the line (inside) touching both from outside; the smallest such rho, or -1.
template <class Node>
inline double pocket_at_line(const Wall& wl, const Node& ni, const Node& nj) noexcept {
  // Relative to i's centre: |p|^2 = (ri + rho)^2; c . p = alpha + beta rho (c = cj - ci);
  // n . p = (w - n . ci) + rho.
  const double cx = nj.x - ni.x;
  const double cy = nj.y - ni.y;
  const double ri = ni.r;
  const double alpha = (cx * cx + cy * cy - nj.r * nj.r + ri * ri) / 2;
  const double beta = ri - nj.r;
  const double off = wl.w - (wl.nx * ni.x + wl.ny * ni.y);
  const double det = cx * wl.ny - cy * wl.nx;
  if (!(det * det > 1e-12 * (cx * cx + cy * cy))) {
    return -1;
  }
  const double inv = 1 / det;
  const double ux = (alpha * wl.ny - off * cy) * inv;
  const double uy = (cx * off - wl.nx * alpha) * inv;
  const double vx = (beta * wl.ny - cy) * inv;
  const double vy = (cx - wl.nx * beta) * inv;
  return smallest_root(ux, uy, vx, vy, ri, [](double) { return true; });
}

// pocket() of two walls' lines and a node: the circle of radius rho at distance rho from both
// lines (inside) touching the node from outside; the smallest such rho, or -1 (see
// pocket_at_walls()).
template <class Node>
inline double pocket_at_two_walls(const Wall& p, const Wall& q, const Node& ni) noexcept {
  // n1 . c = w1 + rho, n2 . c = w2 + rho: c = X + rho V.
  const double det = p.nx * q.ny - p.ny * q.nx;
  if (!(std::abs(det) > 1e-9)) {
    return -1;  // parallel
  }
  const double xx = (p.w * q.ny - q.w * p.ny) / det;
  const double xy = (p.nx * q.w - q.nx * p.w) / det;
  const double vx = (q.ny - p.ny) / det;
  const double vy = (p.nx - q.nx) / det;
  // A node covering the lines' crossing is met by the growing circle only on its way out: the
  // root would be the least radius clear of it, not the most.
  const double ux = xx - ni.x;
  const double uy = xy - ni.y;
  if (!(ux * ux + uy * uy > ni.r * ni.r)) {
    return -1;
  }
  const double rho = smallest_root(ux, uy, vx, vy, ni.r, [](double) { return true; });
  if (rho < 0) {
    return -1;
  }
  const double cx = xx + rho * vx;
  const double cy = xy + rho * vy;
  for (const Wall* wl : {&p, &q}) {
    const double u = (cx - wl->ax) * wl->tx + (cy - wl->ay) * wl->ty;
    if (!(u >= 0 && u <= wl->len)) {
      return -1;
    }
  }
  return rho;
}

// ------------------------------------------------------------------------------------------
// The pockets of elements, by their ids (elements.hpp).

// pocket() with one wall among the three: the circle of radius rho at distance rho from the
// wall's line (inside) touching the two nodes from outside; the smallest such rho.
[[nodiscard]] inline double pocket_at_wall(const Elements& el, std::int32_t a, std::int32_t b,
                                           std::int32_t d) noexcept {
  std::int32_t w = a;
  std::int32_t i = b;
  std::int32_t j = d;
  if (Elements::is_wall(b)) {
    w = b;
    i = a;
  } else if (Elements::is_wall(d)) {
    w = d;
    i = a;
    j = b;
  }
  const Wall& wl = el.wall(w);
  if (el.ends(wl, j)) {
    std::swap(i, j);
  }
  const BoundaryNode& ni = el.node(i);
  const BoundaryNode nj = el.near(j, ni);
  if (el.ends(wl, i)) {
    return el.ends(wl, j) ? -1 : pocket_at_wall_end(wl, ni, nj);
  }
  return pocket_at_line(wl, ni, nj);
}

// pocket() with two walls among the three (a crevice of a rough boundary, or a corner with a disk
// in the way): the circle of radius rho at distance rho from both walls' lines (inside) touching
// the node from outside; the smallest such rho. Its centre moves along a line as rho grows. The
// walls are segments: where the circle's foot on a wall's line falls off the segment, a vertex
// and not the line bounds the pocket, and none is computed (-1).
[[nodiscard]] inline double pocket_at_walls(const Elements& el, std::int32_t a, std::int32_t b,
                                            std::int32_t d) noexcept {
  std::int32_t w1 = a;
  std::int32_t w2 = b;
  std::int32_t i = d;
  if (!Elements::is_wall(a)) {
    w1 = d;
    i = a;
  } else if (!Elements::is_wall(b)) {
    w2 = d;
    i = b;
  }
  return pocket_at_two_walls(el.wall(w1), el.wall(w2), el.node(i));
}

// The void a failed gap leaves: the radius of the circle touching elements a, b and d from
// outside, on the left of a -> b (Apollonius' problem; a, b, d disks or reflex vertices), or -1
// if there is none or it is not computed (a wall among them, centres collinear). A disk touching
// a and b no larger than that clears d: it is the most the gap can take with d in the way.
[[nodiscard]] inline double pocket(const Elements& el, std::int32_t a, std::int32_t b, std::int32_t d) noexcept {
  if (d == kNoElement) {
    return -1;
  }
  const int walls = (Elements::is_wall(a) ? 1 : 0) + (Elements::is_wall(b) ? 1 : 0) + (Elements::is_wall(d) ? 1 : 0);
  if (walls == 1) {
    return pocket_at_wall(el, a, b, d);
  }
  if (walls == 2) {
    return pocket_at_walls(el, a, b, d);
  }
  if (walls != 0) {
    return -1;
  }
  const BoundaryNode& na = el.node(a);
  const BoundaryNode nb = el.near(b, na);
  const BoundaryNode nd = el.near(d, na);
  return pocket_of_nodes<double>(na.x, na.y, na.r, nb.x, nb.y, nb.r, nd.x, nd.y, nd.r, el.scale());
}

// pocket(x, n, d) and pocket(n, y, d) for disks x, n, y and a node d that is no wall: the two
// pockets a disk n placed in void (x, y) bounded by d leaves. In the lanes of a vector, in two
// thirds of the instructions of two calls and with their two long chains of dependent
// operations as one; the same bits (a lane that the vector leaves undecided, NaN, is computed
// alone).
[[nodiscard]] inline std::array<double, 2> pocket_pair(const Elements& el, std::int32_t x, std::int32_t n,
                                                       std::int32_t y, std::int32_t d) noexcept {
  const BoundaryNode& a = el.node(x);
  const BoundaryNode m = el.near(n, a);
  const BoundaryNode b = el.near(y, a);
  const BoundaryNode o = el.near(d, a);
  const V2 rho = pocket_of_nodes<V2>(V2{a.x, m.x}, V2{a.y, m.y}, V2{a.r, m.r}, V2{m.x, b.x}, V2{m.y, b.y}, V2{m.r, b.r},
                                     lanes<V2>(o.x), lanes<V2>(o.y), lanes<V2>(o.r), el.scale());
  std::array<double, 2> caps{rho[0], rho[1]};
  if (x == d) {
    caps[0] = -1;
  } else if (std::isnan(caps[0])) [[unlikely]] {
    caps[0] = pocket(el, x, n, d);
  }
  if (y == d) {
    caps[1] = -1;
  } else if (std::isnan(caps[1])) [[unlikely]] {
    caps[1] = pocket(el, n, y, d);
  }
  return caps;
}

}  // namespace frontpack::detail
