// frontpack <-> CGAL interoperability (opt-in: this header includes CGAL; the rest of the public
// API does not).
//
// Domains store doubles. A CGAL polygon over any kernel is converted coordinate by coordinate with
// CGAL::to_double (exact when the coordinate is a double, as with Epick or exact kernels fed with
// doubles; otherwise within about an ulp) and the converted geometry is then validated like any
// other input, so every guarantee holds for the domain frontpack actually uses.
#pragma once

#include <CGAL/Polygon_with_holes_2.h>

#include <vector>

#include "frontpack/domain.hpp"

namespace frontpack {

namespace detail {
template <class CgalPolygon>
Ring ring_from_cgal(const CgalPolygon& polygon) {
  Ring ring;
  ring.reserve(polygon.size());
  for (auto it = polygon.vertices_begin(); it != polygon.vertices_end(); ++it) {
    ring.push_back(Point{CGAL::to_double(it->x()), CGAL::to_double(it->y())});
  }
  return ring;
}
}  // namespace detail

/// A domain from CGAL polygons with holes (a multipolygon). Throws InvalidDomainError.
template <class Kernel, class Container>
[[nodiscard]] Domain from_cgal(const std::vector<CGAL::Polygon_with_holes_2<Kernel, Container>>& polygons) {
  std::vector<Polygon> out;
  out.reserve(polygons.size());
  for (const auto& pwh : polygons) {
    Polygon p;
    p.outer = detail::ring_from_cgal(pwh.outer_boundary());
    for (auto h = pwh.holes_begin(); h != pwh.holes_end(); ++h) {
      p.holes.push_back(detail::ring_from_cgal(*h));
    }
    out.push_back(std::move(p));
  }
  return Domain::from_polygons(std::move(out));
}

/// A domain from one CGAL polygon with holes. Throws InvalidDomainError.
template <class Kernel, class Container>
[[nodiscard]] Domain from_cgal(const CGAL::Polygon_with_holes_2<Kernel, Container>& polygon) {
  return from_cgal(std::vector<CGAL::Polygon_with_holes_2<Kernel, Container>>{polygon});
}

/// The domain's normalised polygons as CGAL polygons with holes over `Kernel` (exact: every
/// double is representable in any CGAL kernel's number type).
template <class Kernel>
[[nodiscard]] std::vector<CGAL::Polygon_with_holes_2<Kernel>> to_cgal(const Domain& domain) {
  using P2 = CGAL::Polygon_2<Kernel>;
  const auto convert = [](const Ring& ring) {
    P2 polygon;
    for (const Point& p : ring) {
      polygon.push_back(typename Kernel::Point_2(p.x, p.y));
    }
    return polygon;
  };
  std::vector<CGAL::Polygon_with_holes_2<Kernel>> out;
  for (const Polygon& p : domain.polygons()) {
    CGAL::Polygon_with_holes_2<Kernel> pwh(convert(p.outer));
    for (const Ring& hole : p.holes) {
      pwh.add_hole(convert(hole));
    }
    out.push_back(std::move(pwh));
  }
  return out;
}

}  // namespace frontpack
