#include "domain/contour_nesting.hpp"

#include <CGAL/Mpzf.h>

#include <cmath>
#include <cstddef>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "common/budget.hpp"
#include "common/format.hpp"
#include "domain/safe_arcs.hpp"
#include "frontpack/errors.hpp"

namespace frontpack::detail {

namespace {

// The message of an InvalidDomainError without its "invalid domain: " prefix.
std::string invalid_detail(const InvalidDomainError& e) {
  const std::string what = e.what();
  const std::string prefix = "invalid domain: ";
  return what.compare(0, prefix.size(), prefix) == 0 ? what.substr(prefix.size()) : what;
}

std::string edge_name(const Contour& c, const ContourEdge& e) {
  const std::string& name = c.names.at(e.name);
  return name.find("POLYLINE") != std::string::npos ? name + ", edge " + std::to_string(e.index) : name;
}

// Exact orientation of a ring: the sign of twice its signed area, summed exactly.
int ring_sign(const Ring& ring) {
  CGAL::Mpzf sum(0);
  for (std::size_t i = 0; i < ring.size(); ++i) {
    const Point a = ring[i];
    const Point b = ring[(i + 1) % ring.size()];
    sum = sum + CGAL::Mpzf(a.x) * CGAL::Mpzf(b.y) - CGAL::Mpzf(b.x) * CGAL::Mpzf(a.y);
  }
  return sum > CGAL::Mpzf(0) ? 1 : (sum < CGAL::Mpzf(0) ? -1 : 0);
}

// Measured: a curve segment costs about 280 bytes through reading a DXF into a Domain (3.3 million
// took 880 MB peak in `frontpack info`): its vertex in the contour's ring with chords, in that
// ring's own Domain (validation, edge index), in the ring on the domain's side, in the polygon,
// and in the whole Domain.
constexpr double kBytesPerCurveSegment = 280;

// The edges `c` becomes once its curves are polylines (curve_segments for each curve).
double contour_segments(const Contour& c, const DomainReadOptions& options) {
  if (c.full_circle) {
    return curve_segments(c.circle, true, curve_deviation(options, c.circle.radius), c.describe());
  }
  double n = 0;
  for (const ContourEdge& e : c.edges) {
    n += e.curved ? curve_segments(e.arc, false, curve_deviation(options, e.arc.radius), edge_name(c, e)) : 1.0;
  }
  return n;
}

struct Built {
  Ring ring;
  std::vector<CurveReport> curves;
};

// The contour as a ring; `inside_of(sweep)` says whether the domain is inside the circle of an arc
// of that signed sweep (the full circle's sweep is +2 pi).
template <typename Side>
Built build_ring(const Contour& c, const DomainReadOptions& options, Side inside_of) {
  Built out;
  const auto report = [&](const std::string& entity, const Arc& arc, bool inside, const ArcPolyline& p) {
    out.curves.push_back({.entity = entity,
                          .centre = arc.centre,
                          .radius = p.radius,
                          .sweep = std::abs(arc.sweep),
                          .domain_inside = inside,
                          .deviation = p.deviation,
                          .segments = p.segments,
                          .nudged = p.nudged});
  };
  if (c.full_circle) {
    const bool inside = inside_of(c.circle.sweep);
    const std::string entity = c.describe();
    ArcPolyline p = circle_polygon(c.circle, inside, curve_deviation(options, c.circle.radius), entity);
    report(entity, c.circle, inside, p);
    out.ring = std::move(p.vertices);
    return out;
  }
  for (std::size_t i = 0; i < c.edges.size(); ++i) {
    const ContourEdge& e = c.edges[i];
    out.ring.push_back(e.from);
    if (e.curved) {
      const Point to = c.edges[(i + 1) % c.edges.size()].from;
      const bool inside = inside_of(e.arc.sweep);
      const std::string entity = edge_name(c, e);
      ArcPolyline p = arc_polyline(e.arc, e.from, to, inside, curve_deviation(options, e.arc.radius), entity);
      report(entity, e.arc, inside, p);
      out.ring.insert(out.ring.end(), p.vertices.begin(), p.vertices.end());
    }
  }
  return out;
}

}  // namespace

double curve_deviation(const DomainReadOptions& options, double radius) {
  return options.max_deviation > 0 ? options.max_deviation : options.relative_deviation * radius;
}

Domain polygons_to_domain(std::vector<Polygon> polygons, const std::vector<std::vector<std::string>>& ring_names,
                          const std::string& source) {
  try {
    return Domain::from_polygons(std::move(polygons));
  } catch (const InvalidDomainError& e) {
    std::string names;
    const auto name_of = [&](const InvalidDomainError::Site& s) {
      return s.part < ring_names.size() && s.ring < ring_names[s.part].size() ? ring_names[s.part][s.ring]
                                                                              : std::string();
    };
    names = name_of(e.site());
    if (e.other_site() && name_of(*e.other_site()) != names && !name_of(*e.other_site()).empty()) {
      names += " and " + name_of(*e.other_site());
    }
    throw InvalidDomainError(e.kind(),
                             "'" + source + "'" + (names.empty() ? "" : ", " + names) + ": " + invalid_detail(e),
                             e.site(), e.other_site(), e.where());
  }
}

namespace {

// Every curve's segment count is known before any is split: their sum is held to the budget
// first, so that a tiny deviation is refused with its figure instead of filling the memory.
void check_segments(const std::vector<Contour>& contours, const DomainReadOptions& options) {
  double segments = 0;
  for (const Contour& c : contours) {
    segments += contour_segments(c, options);
  }
  check_count(options.budget, segments, kBytesPerCurveSegment, "curve segments",
              "use a larger max_deviation (--max-deviation)");
}

// Each contour alone, with chords: validated (a contour that crosses itself is named here), its
// exact orientation, and a point of it to locate in the others.
struct Alone {
  std::vector<Domain> domains;
  std::vector<int> orientation;
  std::vector<Point> probe;
};

Alone each_alone(const std::vector<Contour>& contours, const DomainReadOptions& options, const std::string& source) {
  const std::size_t n = contours.size();
  Alone alone{{}, std::vector<int>(n, 0), std::vector<Point>(n)};
  alone.domains.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    const Built chords = build_ring(contours[i], options, [](double) { return true; });
    alone.orientation[i] = ring_sign(chords.ring);
    alone.probe[i] = chords.ring.empty() ? Point{} : chords.ring.front();
    try {
      alone.domains.push_back(Domain::from_rings(chords.ring));
    } catch (const InvalidDomainError& e) {
      throw InvalidDomainError(e.kind(), "'" + source + "', " + contours[i].describe() + ": " + invalid_detail(e),
                               e.site(), e.other_site(), e.where());
    }
  }
  return alone;
}

// Depth: how many contours hold this one's point, and which. Touching or crossing contours have a
// point of one on the other, or are reported by the validation of the whole domain later.
struct Nesting {
  std::vector<std::size_t> depth;
  std::vector<std::vector<std::size_t>> holders;
};

Nesting nesting_of(const std::vector<Contour>& contours, const Alone& alone, const std::string& source) {
  const std::size_t n = contours.size();
  std::vector<Box> boxes;
  boxes.reserve(n);
  for (const Domain& d : alone.domains) {
    boxes.push_back(d.bbox());
  }
  Nesting nest{std::vector<std::size_t>(n, 0), std::vector<std::vector<std::size_t>>(n)};
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = 0; j < n; ++j) {
      const Box b = boxes[j];
      const Point q = alone.probe[i];
      if (i == j || q.x < b.xmin || q.x > b.xmax || q.y < b.ymin || q.y > b.ymax) {
        continue;  // a point outside a contour's box is outside the contour
      }
      const Location where = alone.domains[j].locate(q);
      if (where == Location::boundary) {
        throw InvalidDomainError(InvalidDomainError::Kind::rings_cross,
                                 "'" + source + "', " + contours[i].describe() + " and " + contours[j].describe() +
                                     ": the contours touch or cross at " + format_point(q),
                                 {}, std::nullopt, q);
      }
      if (where == Location::inside) {
        ++nest.depth[i];
        nest.holders[i].push_back(j);
      }
    }
  }
  return nest;
}

// Outer contours (even depth) start polygons, in contour order; a hole joins the polygon of the
// contour one level up that holds it. Each ring is built with its arcs bulging to the side that
// keeps the curve's centre where the contour's role puts it.
Domain assemble(const std::vector<Contour>& contours, const DomainReadOptions& options, const std::string& source,
                const Alone& alone, const Nesting& nest, std::vector<CurveReport>& curves) {
  const std::size_t n = contours.size();
  std::vector<std::optional<std::size_t>> part_of(n);
  std::vector<Polygon> polygons;
  std::vector<std::vector<std::string>> names;
  std::vector<Built> built(n);
  for (std::size_t i = 0; i < n; ++i) {
    const bool outer = nest.depth[i] % 2 == 0;
    const int turn = alone.orientation[i];
    built[i] = build_ring(contours[i], options, [outer, turn](double sweep) {
      const bool centre_inside_contour = (sweep > 0 ? 1 : -1) == turn;
      return centre_inside_contour == outer;
    });
    if (outer) {
      part_of[i] = polygons.size();
      polygons.push_back({});
      names.emplace_back(1, contours[i].describe());
    }
  }
  for (std::size_t i = 0; i < n; ++i) {
    if (nest.depth[i] % 2 == 0) {
      polygons[*part_of[i]].outer = built[i].ring;
      continue;
    }
    std::optional<std::size_t> parent;
    for (const std::size_t j : nest.holders[i]) {
      if (nest.depth[j] + 1 == nest.depth[i]) {
        parent = j;
      }
    }
    if (!parent || !part_of[*parent]) {
      throw InvalidDomainError(
          InvalidDomainError::Kind::rings_cross,
          "'" + source + "', " + contours[i].describe() + ": the contours around it cross each other", {}, std::nullopt,
          alone.probe[i]);
    }
    polygons[*part_of[*parent]].holes.push_back(built[i].ring);
    names[*part_of[*parent]].push_back(contours[i].describe());
  }
  for (const Built& b : built) {
    curves.insert(curves.end(), b.curves.begin(), b.curves.end());
  }
  return polygons_to_domain(std::move(polygons), names, source);
}

}  // namespace

Domain nest_contours(const std::vector<Contour>& contours, const DomainReadOptions& options, const std::string& source,
                     std::vector<CurveReport>& curves) {
  if (contours.empty()) {
    throw DomainFileError(DomainFileError::Kind::empty,
                          "no closed contour: expected closed LWPOLYLINE or POLYLINE, CIRCLE, or LINE and ARC "
                          "entities that join into closed contours",
                          source);
  }
  check_segments(contours, options);
  const Alone alone = each_alone(contours, options, source);
  const Nesting nest = nesting_of(contours, alone, source);
  return assemble(contours, options, source, alone, nest, curves);
}

}  // namespace frontpack::detail
