#include "certify/report.hpp"

#include <CGAL/AABB_segment_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Simple_cartesian.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "periodic/overlap_pass.hpp"

namespace frontpack::detail {

namespace {

// A periodic cell's outside disks: how far the centre lies outside the cell (a periodic side is no
// boundary, so a centre outside the cell reaches r + that distance out), and for a shear cell how
// far the disk reaches past a wall.
void measure_outside_cell(const Domain& domain, std::span<const Disk> disks, CertifyReport& report) {
  const Box cell = domain.bbox();
  const bool walls = domain.periodicity() == Periodicity::x;
  for (const std::size_t i : report.outside) {
    const Disk& d = disks[i];
    double by = std::numeric_limits<double>::infinity();
    if (std::isfinite(d.centre.x) && std::isfinite(d.centre.y) && std::isfinite(d.radius) && d.radius >= 0) {
      const double dx = std::max({cell.xmin - d.centre.x, d.centre.x - cell.xmax, 0.0});
      const double dy = std::max({cell.ymin - d.centre.y, d.centre.y - cell.ymax, 0.0});
      const double out = std::hypot(dx, dy);
      by = out > 0 || !walls ? d.radius + out : d.radius - std::min(d.centre.y - cell.ymin, cell.ymax - d.centre.y);
    }
    if (!report.farthest_outside || by > report.farthest_outside_by) {
      report.farthest_outside = i;
      report.farthest_outside_by = by;
    }
  }
}

}  // namespace

// The "how bad" figures of a report, in floating point from the exact decisions. The distance
// from a centre to the boundary comes from an AABB tree of the domain's edges (CGAL 5.5's tree is
// 3D: the edges lie in the plane z = 0), built only when some disk is outside. Not the float
// distance index of domain/edge_distance.hpp: that grid answers "which edges lie within d of p"
// for a d known in advance, and a nearest-edge query from a centre far outside or deep in a large
// hole would visit every cell between; the tree's query is logarithmic wherever the point is, and
// `frontpack check` takes anyone's disks. No decision depends on this figure.
void measure_worst(const Domain& domain, std::span<const Disk> disks, CertifyReport& report) {
  for (const auto& [i, j] : report.overlapping) {
    const Disk& a = disks[i];
    const Disk& b = disks[j];
    const double depth = domain.periodicity() != Periodicity::none
                             ? periodic_overlap_depth(domain, a, b, i == j)
                             : a.radius + b.radius - std::hypot(a.centre.x - b.centre.x, a.centre.y - b.centre.y);
    if (!report.deepest_overlap || depth > report.deepest_overlap_depth) {
      report.deepest_overlap = std::make_pair(i, j);
      report.deepest_overlap_depth = depth;
    }
  }
  if (report.outside.empty()) {
    return;
  }
  if (domain.periodicity() != Periodicity::none) {
    measure_outside_cell(domain, disks, report);
    return;
  }
  using K = CGAL::Simple_cartesian<double>;
  using Segments = std::vector<K::Segment_3>;
  using Tree = CGAL::AABB_tree<CGAL::AABB_traits<K, CGAL::AABB_segment_primitive<K, Segments::const_iterator>>>;
  Segments edges;
  const auto add_ring = [&edges](const Ring& ring) {
    for (std::size_t k = 0; k < ring.size(); ++k) {
      const Point& p = ring[k];
      const Point& q = ring[(k + 1) % ring.size()];
      edges.emplace_back(K::Point_3(p.x, p.y, 0), K::Point_3(q.x, q.y, 0));
    }
  };
  for (const Polygon& polygon : domain.polygons()) {
    add_ring(polygon.outer);
    for (const Ring& hole : polygon.holes) {
      add_ring(hole);
    }
  }
  Tree tree(edges.cbegin(), edges.cend());
  tree.accelerate_distance_queries();
  for (const std::size_t i : report.outside) {
    const Disk& d = disks[i];
    double by = std::numeric_limits<double>::infinity();
    if (std::isfinite(d.centre.x) && std::isfinite(d.centre.y) && std::isfinite(d.radius) && d.radius >= 0) {
      const double distance = std::sqrt(tree.squared_distance(K::Point_3(d.centre.x, d.centre.y, 0)));
      by = domain.locate(d.centre) == Location::inside ? d.radius - distance : d.radius + distance;
    }
    if (!report.farthest_outside || by > report.farthest_outside_by) {
      report.farthest_outside = i;
      report.farthest_outside_by = by;
    }
  }
}

}  // namespace frontpack::detail
