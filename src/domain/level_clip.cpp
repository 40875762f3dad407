// The part of a domain below a level, exactly (level_clip.hpp): CGAL's Boolean operations on exact
// rationals, then each vertex rounded to a double that the domain holds.
#include "domain/level_clip.hpp"

#include <CGAL/Boolean_set_operations_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Polygon_2.h>
#include <CGAL/Polygon_with_holes_2.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>
#include <string>
#include <type_traits>
#include <vector>

#include "common/format.hpp"

namespace frontpack::detail {

namespace {

using K = CGAL::Exact_predicates_exact_constructions_kernel;
using CPolygon = CGAL::Polygon_2<K>;
using CPwh = CGAL::Polygon_with_holes_2<K>;

CPolygon to_cgal(const Ring& ring) {
  CPolygon p;
  for (const Point& v : ring) {
    p.push_back(K::Point_2(v.x, v.y));
  }
  return p;
}

// A double strictly beyond v, away from 0 by at least 1: a side of the clipping box that lies
// off the domain.
double beyond(double v, double dir) {
  return v + std::copysign(std::max(std::abs(v), 1.0), dir);
}

// A vertex of the clip, as doubles: a vertex of the domain as it is; a new one (on the level) with
// its x rounded and moved along the level until the domain holds it.
Point rounded(const Domain& domain, const K::Point_2& v, double height) {
  const auto ex = CGAL::exact(v.x());  // copies: v.x() is a temporary
  const auto ey = CGAL::exact(v.y());
  const double x = CGAL::to_double(ex);
  const double y = CGAL::to_double(ey);
  using Exact = std::decay_t<decltype(ex)>;
  if (Exact(x) == ex && Exact(y) == ey) {
    return {x, y};
  }
  // Not representable: a crossing with the level, whose y is the level exactly.
  const Point p{x, height};
  if (domain.locate(p) != Location::outside) {
    return p;
  }
  double up = x;
  double down = x;
  for (int k = 0; k < 64; ++k) {
    up = std::nextafter(up, std::numeric_limits<double>::infinity());
    down = std::nextafter(down, -std::numeric_limits<double>::infinity());
    if (domain.locate({up, height}) != Location::outside) {
      return {up, height};
    }
    if (domain.locate({down, height}) != Location::outside) {
      return {down, height};
    }
  }
  return p;  // validation or the certificate against the domain settles it
}

Ring to_ring(const Domain& domain, const CPolygon& p, double height) {
  Ring ring;
  ring.reserve(p.size());
  for (const K::Point_2& v : p.vertices()) {
    const Point q = rounded(domain, v, height);
    if (ring.empty() || !(ring.back() == q)) {
      ring.push_back(q);
    }
  }
  while (ring.size() > 1 && ring.front() == ring.back()) {
    ring.pop_back();
  }
  return ring;
}

}  // namespace

Domain clip_below(const Domain& domain, double height) {
  const Box b = domain.bbox();
  if (!std::isfinite(height) || height <= b.ymin) {
    throw OptionError("height " + format_double(height) +
                      ": the level must lie above the domain's lowest point, y = " + format_double(b.ymin) +
                      " (the domain spans y = " + format_double(b.ymin) + " to " + format_double(b.ymax) + ")");
  }
  if (height >= b.ymax) {
    return domain;
  }
  CPolygon below;
  const double x0 = beyond(b.xmin, -1);
  const double x1 = beyond(b.xmax, 1);
  const double y0 = beyond(b.ymin, -1);
  below.push_back(K::Point_2(x0, y0));
  below.push_back(K::Point_2(x1, y0));
  below.push_back(K::Point_2(x1, height));
  below.push_back(K::Point_2(x0, height));
  std::vector<Polygon> parts;
  for (const Polygon& polygon : domain.polygons()) {
    std::vector<CPolygon> holes;
    for (const Ring& h : polygon.holes) {
      holes.push_back(to_cgal(h));
      if (holes.back().orientation() != CGAL::CLOCKWISE) {
        holes.back().reverse_orientation();
      }
    }
    CPolygon outer = to_cgal(polygon.outer);
    if (outer.orientation() != CGAL::COUNTERCLOCKWISE) {
      outer.reverse_orientation();
    }
    const CPwh pwh(outer, holes.begin(), holes.end());
    std::vector<CPwh> clipped;
    CGAL::intersection(pwh, below, std::back_inserter(clipped));
    for (const CPwh& c : clipped) {
      Polygon part;
      part.outer = to_ring(domain, c.outer_boundary(), height);
      for (auto h = c.holes_begin(); h != c.holes_end(); ++h) {
        part.holes.push_back(to_ring(domain, *h, height));
      }
      parts.push_back(std::move(part));
    }
  }
  if (parts.empty()) {
    throw OptionError("height " + format_double(height) + ": no part of the domain lies below the level");
  }
  return Domain::from_polygons(std::move(parts));
}

}  // namespace frontpack::detail
