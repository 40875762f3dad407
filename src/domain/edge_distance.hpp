// The float distance index over a domain's edges: a uniform grid listing each edge in the cells it
// crosses, for "which edges come within d of p" queries in floating point (the statistics' band,
// wall contacts). Not for decisions: the domain's exact queries go through domain/edge_grid.hpp,
// whose cells are bounded by explicit doubles and sized for point location.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "common/grid_cells.hpp"
#include "frontpack/domain.hpp"
#include "frontpack/geometry.hpp"

namespace frontpack::detail {

class EdgeDistanceIndex {
 public:
  /// Indexes the domain's walls in cells of side h (at least the side of about 4 million cells
  /// over the domain's bounding box). The walls are every edge of a polygonal domain's rings; in a
  /// periodic cell only the real walls (domain/periodic_cell.hpp): none for Periodicity::xy, the
  /// bottom and top lines for Periodicity::x, each extended by a period beyond either side so that
  /// the distance of any point within a period of the cell (an image) is its distance to the line.
  /// A periodic side is no wall: the plane continues across it.
  EdgeDistanceIndex(const Domain& domain, double h);

  /// Whether there is any wall (false for a cell periodic in x and y).
  [[nodiscard]] bool has_walls() const noexcept { return !a_.empty(); }

  /// Calls f(closest point, distance) for each edge (possibly repeated) listed in the cells
  /// within d of p; every edge at distance <= d from p is among them.
  template <class F>
  void near(Point p, double d, F&& f) const {
    const std::size_t i0 = column(p.x - d);
    const std::size_t i1 = column(p.x + d);
    const std::size_t j0 = row(p.y - d);
    const std::size_t j1 = row(p.y + d);
    for (std::size_t j = j0; j <= j1; ++j) {
      for (std::size_t i = i0; i <= i1; ++i) {
        const std::size_t c = j * nx_ + i;
        for (std::size_t k = start_[c]; k < start_[c + 1]; ++k) {
          const Point q = closest(edges_[k], p);
          f(q, std::hypot(q.x - p.x, q.y - p.y));
        }
      }
    }
  }

  /// min(cap, the distance from p to the nearest edge), for cap > 0: the cells are visited in
  /// rings around p's cell, from the first ring that lists an edge (a distance transform of the
  /// grid says which), until the rings left are farther than the nearest edge found. Without
  /// walls: cap.
  [[nodiscard]] double distance(Point p, double cap) const;

  /// Whether the boundary comes closer than d to p.
  [[nodiscard]] bool closer_than(Point p, double d) const {
    bool found = false;
    near(p, d, [&found, d](Point, double dist) { found = found || dist < d; });
    return found;
  }

 private:
  void add_ring(const Ring& ring) {
    for (std::size_t k = 0; k < ring.size(); ++k) {
      a_.push_back(ring[k]);
      b_.push_back(ring[(k + 1) % ring.size()]);
    }
  }
  void add_walls(const Domain& domain);
  [[nodiscard]] std::size_t column(double x) const { return cell_index(x, x0_, inv_h_, nx_); }
  [[nodiscard]] std::size_t row(double y) const { return cell_index(y, y0_, inv_h_, ny_); }
  [[nodiscard]] Point closest(std::uint32_t e, Point p) const {
    const Point a = a_[e];
    const Point b = b_[e];
    const double dx = b.x - a.x;
    const double dy = b.y - a.y;
    const double len2 = dx * dx + dy * dy;
    double t = len2 > 0 ? ((p.x - a.x) * dx + (p.y - a.y) * dy) / len2 : 0;
    t = std::clamp(t, 0.0, 1.0);
    return Point{a.x + t * dx, a.y + t * dy};
  }

  std::vector<Point> a_;
  std::vector<Point> b_;
  double h_ = 1;
  double inv_h_ = 1;
  double x0_ = 0;
  double y0_ = 0;
  std::size_t nx_ = 1;
  std::size_t ny_ = 1;
  std::vector<std::size_t> start_;
  std::vector<std::uint32_t> edges_;
  // Per cell, the Chebyshev distance in cells to the nearest cell that lists an edge (at most
  // 255): every point of the cell is at least (value - 1) h from every edge.
  std::vector<std::uint8_t> empty_rings_;
};

}  // namespace frontpack::detail
