#include "domain/safe_arcs.hpp"

#include <CGAL/Mpzf.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <stdexcept>

#include "common/format.hpp"
#include "frontpack/domain_file.hpp"
#include "frontpack/errors.hpp"

namespace frontpack::detail {

namespace {

using Exact = CGAL::Mpzf;  // exact sums and products of doubles (no division needed below)

constexpr double kMaxStep = std::numbers::pi / 2;
// A rounded vertex is off its side by about an ulp of the circle's centre and radius, which may be
// many ulps of the vertex itself (a nearly flat arc far from its centre): the n-th move of a
// vertex is 2^n ulps, so any offset is made good in a few dozen moves. The bound guards the loop.
constexpr int kMaxNudges = 200;

Exact squared_distance(Point p, Point c) {
  const Exact dx = Exact(p.x) - Exact(c.x);
  const Exact dy = Exact(p.y) - Exact(c.y);
  return dx * dx + dy * dy;
}

bool in_closed_disk(Point p, Point c, double r) {
  return squared_distance(p, c) <= Exact(r) * Exact(r);
}

// Exact: the squared distance from c to the segment [a, b] is at least `bound2`.
bool segment_keeps_off(Point a, Point b, Point c, const Exact& bound2) {
  const Exact abx = Exact(b.x) - Exact(a.x);
  const Exact aby = Exact(b.y) - Exact(a.y);
  const Exact acx = Exact(c.x) - Exact(a.x);
  const Exact acy = Exact(c.y) - Exact(a.y);
  const Exact t = acx * abx + acy * aby;
  const Exact ab2 = abx * abx + aby * aby;
  if (t <= Exact(0) || ab2 == Exact(0)) {
    return acx * acx + acy * acy >= bound2;
  }
  if (t >= ab2) {
    return squared_distance(b, c) >= bound2;
  }
  const Exact cross = abx * acy - aby * acx;
  return cross * cross >= bound2 * ab2;  // distance to the line, squared, times |ab|^2
}

// x moved by 2^k ulps toward +inf (dir > 0) or -inf (dir < 0).
double moved(double x, double dir, int k) {
  const double ulp = std::nextafter(std::abs(x), std::numeric_limits<double>::infinity()) - std::abs(x);
  return x + std::copysign(std::ldexp(ulp, k), dir);
}

Point toward_centre(Point p, Point c, int k) {
  return {p.x == c.x ? p.x : moved(p.x, c.x - p.x, k), p.y == c.y ? p.y : moved(p.y, c.y - p.y, k)};
}

Point away_from_centre(Point p, Point c, int k) {
  return {p.x == c.x ? p.x : moved(p.x, p.x - c.x, k), p.y == c.y ? p.y : moved(p.y, p.y - c.y, k)};
}

Point on_circle(Point c, double rho, double angle) {
  return {c.x + rho * std::cos(angle), c.y + rho * std::sin(angle)};
}

// The point of the circle (c, r) at angle start + t, plus `out` along the radius there, computed
// from the arc's start point a = c + r u(start): a + 2 r sin(t/2) u'(start + t/2) + out u(start +
// t), where u' is u turned a quarter. No term is of the size of r when t is small, so a nearly flat
// arc (a radius far larger than its chord) keeps its vertices as accurate as its chord.
Point from_start(Point a, double r, double start, double t, double out) {
  const double chord = 2 * r * std::sin(t / 2);
  const double mid = start + t / 2;
  const double end = start + t;
  return {a.x - chord * std::sin(mid) + out * std::cos(end), a.y + chord * std::cos(mid) + out * std::sin(end)};
}

// The readers refuse bad circles with the file's context (DomainFileError::Kind::bad_curve); this
// guards the precondition.
void check_arc(const Arc& arc, double deviation, const std::string& entity) {
  if (!std::isfinite(arc.radius) || arc.radius <= 0 || !std::isfinite(arc.centre.x) || !std::isfinite(arc.centre.y) ||
      !std::isfinite(arc.start) || !std::isfinite(arc.sweep)) {
    throw std::invalid_argument("frontpack: bad arc for " + entity);
  }
  if (!std::isfinite(deviation) || deviation <= 0) {
    throw OptionError("curve deviation " + format_double(deviation) + " for " + entity +
                      ": expected a finite number > 0");
  }
}

void nudge_inward(std::vector<Point>& v, Point c, double r, std::size_t& nudged) {
  for (Point& p : v) {
    int steps = 0;
    while (!in_closed_disk(p, c, r)) {
      if (steps > kMaxNudges) {
        throw std::logic_error("frontpack: could not round a chord vertex into its circle");
      }
      p = toward_centre(p, c, steps++);
    }
    nudged += steps > 0 ? 1 : 0;
  }
}

// The tangent polyline's vertices `v` (constructed), between the given endpoints `a` and `b` when
// they exist, else closed: every segment kept off the open disk, the end segments no nearer than
// their endpoint.
void nudge_outward(std::vector<Point>& v, std::optional<Point> a, std::optional<Point> b, Point c, double r,
                   std::size_t& nudged) {
  const Exact r2 = Exact(r) * Exact(r);
  const std::size_t n = v.size();
  std::vector<int> moves(n, 0);
  const auto bound_at = [&](Point p) {
    const Exact d2 = squared_distance(p, c);
    return d2 < r2 ? d2 : r2;
  };
  for (int pass = 0;; ++pass) {
    if (pass > kMaxNudges) {
      throw std::logic_error("frontpack: could not round a tangent polyline off its circle");
    }
    bool all_ok = true;
    const auto fix = [&](std::size_t k) {
      v[k] = away_from_centre(v[k], c, moves[k]++);
      all_ok = false;
    };
    if (a && n > 0 && !segment_keeps_off(*a, v[0], c, bound_at(*a))) {
      fix(0);
    }
    const std::size_t inner = a ? n - 1 : n;  // closed: n segments, v[n-1] -> v[0]
    for (std::size_t k = 0; k < inner && n > 1; ++k) {
      const std::size_t k1 = (k + 1) % n;
      if (!segment_keeps_off(v[k], v[k1], c, r2)) {
        fix(k);
        fix(k1);
      }
    }
    if (b && n > 0 && !segment_keeps_off(v[n - 1], *b, c, bound_at(*b))) {
      fix(n - 1);
    }
    if (all_ok) {
      break;
    }
  }
  nudged += static_cast<std::size_t>(std::count_if(moves.begin(), moves.end(), [](int m) { return m > 0; }));
}

double chord_deviation(double r, double step) {
  const double s = std::sin(step / 4);
  return 2 * r * s * s;
}

double tangent_deviation(double r, double step) {
  return r / std::cos(step / 2) - r;
}

// The radius, widened (domain inside) or narrowed (outside) just enough that both given endpoints
// are exactly on the domain's side of the circle, when that takes at most kEndpointSlack of it:
// endpoints are on the circle up to rounding (a bulge's circle is computed from them, an ARC's
// endpoints from it). A larger gap (a LINE end joined within the join tolerance) keeps the radius.
constexpr double kEndpointSlack = 1e-12;

double endpoint_radius(const Arc& arc, Point a, Point b, bool inside) {
  const Exact da = squared_distance(a, arc.centre);
  const Exact db = squared_distance(b, arc.centre);
  const Exact& far = da > db ? da : db;
  const Exact& near = da < db ? da : db;
  const auto ok = [&](double r) { return inside ? far <= Exact(r) * Exact(r) : near >= Exact(r) * Exact(r); };
  if (ok(arc.radius)) {
    return arc.radius;
  }
  const double ra = std::hypot(a.x - arc.centre.x, a.y - arc.centre.y);
  const double rb = std::hypot(b.x - arc.centre.x, b.y - arc.centre.y);
  double r = inside ? std::max(ra, rb) : std::min(ra, rb);
  const double dir = inside ? std::numeric_limits<double>::infinity() : 0.0;
  for (int i = 0; i < 8 && !ok(r); ++i) {
    r = std::nextafter(r, dir);
  }
  return ok(r) && std::abs(r - arc.radius) <= kEndpointSlack * arc.radius ? r : arc.radius;
}

}  // namespace

std::size_t arc_segments(double radius, double sweep, bool inside, double deviation, const std::string& entity) {
  // Chords: r (1 - cos(t / 2)) = 2 r sin^2(t / 4) <= d. Tangents: r / cos(t / 2) - r <= d, i.e.
  // tan(t / 2) <= sqrt(d (2 r + d)) / r. Both forms stay accurate for d much smaller than r.
  double step = kMaxStep;
  if (inside) {
    const double s = std::sqrt(deviation / (2 * radius));
    step = s < 1 ? std::min(kMaxStep, 4 * std::asin(s)) : kMaxStep;
  } else {
    step = std::min(kMaxStep, 2 * std::atan(std::sqrt(deviation * (2 * radius + deviation)) / radius));
  }
  const double n = std::ceil(std::abs(sweep) / step);
  if (!(n <= static_cast<double>(max_segments_per_curve))) {
    throw OptionError("curve deviation " + format_double(deviation) + " is too small for " + entity + " (radius " +
                      format_double(radius) + "): it would take " +
                      (std::isfinite(n) ? format_double(n) : std::string("too many")) + " segments, more than " +
                      std::to_string(max_segments_per_curve) + "; give a larger deviation");
  }
  return std::max<std::size_t>(1, static_cast<std::size_t>(n));
}

double curve_segments(const Arc& arc, bool full_circle, double deviation, const std::string& entity) {
  check_arc(arc, deviation, entity);
  const double sweep = full_circle ? 2 * std::numbers::pi : arc.sweep;
  const std::size_t chords = arc_segments(arc.radius, sweep, true, deviation, entity);
  // An arc's tangent polyline has a segment more than its steps (arc_polyline); a circle's does not.
  const std::size_t tangents = arc_segments(arc.radius, sweep, false, deviation, entity) + (full_circle ? 0 : 1);
  return static_cast<double>(std::max({chords, tangents, std::size_t{full_circle ? 4U : 1U}}));
}

ArcPolyline arc_polyline(const Arc& given, Point a, Point b, bool inside, double deviation, const std::string& entity) {
  check_arc(given, deviation, entity);
  ArcPolyline out;
  Arc arc = given;
  arc.radius = endpoint_radius(given, a, b, inside);
  out.radius = arc.radius;
  const std::size_t n = arc_segments(arc.radius, arc.sweep, inside, deviation, entity);
  const double step = arc.sweep / static_cast<double>(n);
  if (inside) {
    out.segments = n;
    out.deviation = chord_deviation(arc.radius, std::abs(step));
    for (std::size_t k = 1; k < n; ++k) {
      out.vertices.push_back(from_start(a, arc.radius, arc.start, static_cast<double>(k) * step, 0.0));
    }
    nudge_inward(out.vertices, arc.centre, arc.radius, out.nudged);
  } else {
    // Tangent at the start, tangents at start + k * step, tangent at the end: n + 1 segments,
    // vertices where consecutive tangents meet.
    out.segments = n + 1;
    out.deviation = tangent_deviation(arc.radius, std::abs(step));
    const double s4 = std::sin(step / 4);
    const double out_by = 2 * arc.radius * s4 * s4 / std::cos(step / 2);  // r / cos(step/2) - r, stably
    for (std::size_t k = 0; k < n; ++k) {
      out.vertices.push_back(from_start(a, arc.radius, arc.start, (static_cast<double>(k) + 0.5) * step, out_by));
    }
    nudge_outward(out.vertices, a, b, arc.centre, arc.radius, out.nudged);
  }
  return out;
}

ArcPolyline circle_polygon(const Arc& circle, bool inside, double deviation, const std::string& entity) {
  check_arc(circle, deviation, entity);
  ArcPolyline out;
  const double sweep = 2 * std::numbers::pi;
  const std::size_t n = std::max<std::size_t>(4, arc_segments(circle.radius, sweep, inside, deviation, entity));
  const double step = sweep / static_cast<double>(n);
  out.segments = n;
  out.radius = circle.radius;
  if (inside) {
    out.deviation = chord_deviation(circle.radius, step);
    for (std::size_t k = 0; k < n; ++k) {
      out.vertices.push_back(on_circle(circle.centre, circle.radius, static_cast<double>(k) * step));
    }
    nudge_inward(out.vertices, circle.centre, circle.radius, out.nudged);
  } else {
    out.deviation = tangent_deviation(circle.radius, step);
    const double rho = circle.radius / std::cos(step / 2);
    for (std::size_t k = 0; k < n; ++k) {
      out.vertices.push_back(on_circle(circle.centre, rho, (static_cast<double>(k) + 0.5) * step));
    }
    nudge_outward(out.vertices, std::nullopt, std::nullopt, circle.centre, circle.radius, out.nudged);
  }
  return out;
}

Arc arc_from_bulge(Point a, Point b, double bulge) {
  const double dx = b.x - a.x;
  const double dy = b.y - a.y;
  const double k = (1 - bulge * bulge) / (4 * bulge);
  Arc arc;
  arc.centre = {0.5 * (a.x + b.x) - k * dy, 0.5 * (a.y + b.y) + k * dx};
  arc.radius = std::hypot(dx, dy) * (1 + bulge * bulge) / (4 * std::abs(bulge));
  arc.start = std::atan2(a.y - arc.centre.y, a.x - arc.centre.x);
  arc.sweep = 4 * std::atan(bulge);
  return arc;
}

}  // namespace frontpack::detail
