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
// Each nudge moves a coordinate by one ulp; a vertex rounded to the wrong side is off by about one
// ulp of its coordinates, so a few steps suffice. The bound only guards the loop.
constexpr int kMaxNudges = 4096;

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

double step_toward(double x, double target) {
  return x == target ? x : std::nextafter(x, target);
}

Point toward_centre(Point p, Point c) {
  return {step_toward(p.x, c.x), step_toward(p.y, c.y)};
}

Point away_from_centre(Point p, Point c) {
  constexpr double inf = std::numeric_limits<double>::infinity();
  return {p.x == c.x ? p.x : std::nextafter(p.x, p.x > c.x ? inf : -inf),
          p.y == c.y ? p.y : std::nextafter(p.y, p.y > c.y ? inf : -inf)};
}

Point on_circle(Point c, double rho, double angle) {
  return {c.x + rho * std::cos(angle), c.y + rho * std::sin(angle)};
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
      if (++steps > kMaxNudges) {
        throw std::logic_error("frontpack: could not round a chord vertex into its circle");
      }
      p = toward_centre(p, c);
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
  std::vector<char> moved(n, 0);
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
      v[k] = away_from_centre(v[k], c);
      moved[k] = 1;
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
  nudged += static_cast<std::size_t>(std::count(moved.begin(), moved.end(), 1));
}

double chord_deviation(double r, double step) {
  const double s = std::sin(step / 4);
  return 2 * r * s * s;
}

double tangent_deviation(double r, double step) {
  return r / std::cos(step / 2) - r;
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

ArcPolyline arc_polyline(const Arc& arc, Point a, Point b, bool inside, double deviation, const std::string& entity) {
  check_arc(arc, deviation, entity);
  ArcPolyline out;
  const std::size_t n = arc_segments(arc.radius, arc.sweep, inside, deviation, entity);
  const double step = arc.sweep / static_cast<double>(n);
  if (inside) {
    out.segments = n;
    out.deviation = chord_deviation(arc.radius, std::abs(step));
    for (std::size_t k = 1; k < n; ++k) {
      out.vertices.push_back(on_circle(arc.centre, arc.radius, arc.start + static_cast<double>(k) * step));
    }
    nudge_inward(out.vertices, arc.centre, arc.radius, out.nudged);
  } else {
    // Tangent at the start, tangents at start + k * step, tangent at the end: n + 1 segments,
    // vertices where consecutive tangents meet.
    out.segments = n + 1;
    out.deviation = tangent_deviation(arc.radius, std::abs(step));
    const double rho = arc.radius / std::cos(step / 2);
    for (std::size_t k = 0; k < n; ++k) {
      out.vertices.push_back(on_circle(arc.centre, rho, arc.start + (static_cast<double>(k) + 0.5) * step));
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
