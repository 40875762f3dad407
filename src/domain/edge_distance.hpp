// The float distance index over a domain's edges, for "how far is the nearest wall from p" and
// "which edges come within d of p" in floating point (the statistics' band, clearance and wall
// contacts; the jam's insertion and walls). Not for decisions: the domain's exact queries go
// through domain/edge_grid.hpp.
//
// The distance queries search a bounding-volume hierarchy of the edges (halved at the median of
// the edges' midpoints, up to 4 edges a leaf), nearer node first, dropping a node no nearer than
// the best edge found. A node is bounded by its box and by a capsule: the chord between its two
// extreme endpoints and the largest distance of an endpoint from it (every point of its edges is
// that close to the chord, the distance to a segment being convex). On a curve of radius R the
// capsule of a node of length S is S^2 / 8R thick where its box is about S: a query at depth D
// under a finely drawn curve then visits a few nodes a level, about log E nodes in all (with boxes
// alone, the sqrt(D / S) leaves within S of the nearest), whatever the ratio of D to the edges'
// length. (A grid of cells sized for the reach scanned every edge of a cell: the statistics on a
// 30,000-vertex circle took E x reach / length.) The answer is that of a scan of
// every edge, bit for bit: each edge's distance is computed by one formula and a box is dropped
// only when its distance, less a rounding margin, is no smaller than the best.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "common/bucket_grid.hpp"
#include "frontpack/domain.hpp"
#include "frontpack/geometry.hpp"

namespace frontpack::detail {

class EdgeDistanceIndex {
 public:
  /// Indexes the domain's walls for distance(), closer_than() and within(). The walls are every
  /// edge of a polygonal domain's rings; in a periodic cell only the real walls
  /// (domain/periodic_cell.hpp): none for Periodicity::xy, the bottom and top lines for
  /// Periodicity::x, each extended by a period beyond either side so that the distance of any
  /// point within a period of the cell (an image) is its distance to the line. A periodic side is
  /// no wall: the plane continues across it. O(E log E) time, O(E) memory.
  explicit EdgeDistanceIndex(const Domain& domain);

  /// The same, and also a grid of cells of side h (at least the side of about 4 million cells
  /// over the domain's bounding box) for near().
  EdgeDistanceIndex(const Domain& domain, double h);

  /// Whether there is any wall (false for a cell periodic in x and y).
  [[nodiscard]] bool has_walls() const noexcept { return !a_.empty(); }

  /// Calls f(closest point, distance) for each edge (possibly repeated) listed in the grid's cells
  /// within d of p; every edge at distance <= d from p is among them. The jam's forces sum over
  /// these calls in this order. Without the grid (the constructor without h): within().
  template <class F>
  void near(Point p, double d, F&& f) const {
    if (grid_.empty()) {
      within(p, d, f);
      return;
    }
    grid_.visit_box(frame_, Box{p.x - d, p.y - d, p.x + d, p.y + d}, [&](std::uint32_t e) {
      const Point q = closest(e, p);
      f(q, std::hypot(q.x - p.x, q.y - p.y));
    });
  }

  /// min(cap, the distance from p to the nearest edge): exactly the minimum of cap and every
  /// edge's distance. Without walls: cap.
  [[nodiscard]] double distance(Point p, double cap) const;

  /// Whether the boundary comes closer than d to p (some edge's distance is below d).
  [[nodiscard]] bool closer_than(Point p, double d) const { return distance(p, d) < d; }

  /// Calls f(closest point, distance) once for each edge within d of p (and maybe an edge
  /// farther by a rounding margin, for the caller to judge), in the order of the edges.
  template <class F>
  void within(Point p, double d, F&& f) const {
    std::vector<std::uint32_t> found;
    collect(p, d, found);
    std::sort(found.begin(), found.end());
    for (const std::uint32_t e : found) {
      const Point q = closest(e, p);
      f(q, std::hypot(q.x - p.x, q.y - p.y));
    }
  }

  /// The edges whose distance the queries have computed so far: their cost, for the tests.
  [[nodiscard]] std::size_t examined() const noexcept { return examined_; }

 private:
  void add_ring(const Ring& ring) {
    for (std::size_t k = 0; k < ring.size(); ++k) {
      a_.push_back(ring[k]);
      b_.push_back(ring[(k + 1) % ring.size()]);
    }
  }
  // A node of the hierarchy: its edges are order_[begin, end), every point of them in the box and
  // within rho of the segment c0 c1; an inner node's children are the next node and node `right`.
  struct Node {
    Box box;
    Point c0;
    Point c1;
    double rho;
    std::uint32_t begin;
    std::uint32_t end;
    std::uint32_t right;  // 0 for a leaf
  };
  static constexpr std::uint32_t kLeafEdges = 4;

  void add_walls(const Domain& domain);
  void build_tree();
  std::uint32_t build_node(std::uint32_t begin, std::uint32_t end, std::vector<Point>& mid);
  void build_grid(const Domain& domain, double h);
  // Calls emit(c) for each grid cell edge e passes through: rasterized along the edge, column by
  // column, never over its bounding box (a diagonal edge's box is O(length^2) cells).
  template <class Emit>
  void edge_cells(std::size_t e, Emit&& emit) const {
    const Point a = a_[e];
    const Point c = b_[e];
    const double xlo = std::min(a.x, c.x);
    const double xhi = std::max(a.x, c.x);
    for (std::size_t i = frame_.column(xlo); i <= frame_.column(xhi); ++i) {
      // The edge's y range over this column's x range (conservative by a relative 1e-9).
      const double cx0 = std::max(xlo, frame_.x0 + static_cast<double>(i) * h_);
      const double cx1 = std::min(xhi, frame_.x0 + static_cast<double>(i + 1) * h_);
      double ylo = std::min(a.y, c.y);
      double yhi = std::max(a.y, c.y);
      if (c.x != a.x) {
        const double ya = a.y + (c.y - a.y) * ((cx0 - a.x) / (c.x - a.x));
        const double yb = a.y + (c.y - a.y) * ((cx1 - a.x) / (c.x - a.x));
        ylo = std::max(ylo, std::min(ya, yb) - 1e-9 * h_);
        yhi = std::min(yhi, std::max(ya, yb) + 1e-9 * h_);
      }
      frame_.visit_block(i, i, frame_.row(ylo), frame_.row(yhi), emit);
    }
  }
  // Appends the edges within d of p (and maybe a few farther by the rounding margin).
  void collect(Point p, double d, std::vector<std::uint32_t>& out) const;
  // A lower bound of the distance from p to any point of the node's edges, less the rounding
  // margin of a computed edge distance.
  [[nodiscard]] double lower_bound(const Node& n, Point p) const noexcept {
    const Box& b = n.box;
    const double dx = std::max({b.xmin - p.x, p.x - b.xmax, 0.0});
    const double dy = std::max({b.ymin - p.y, p.y - b.ymax, 0.0});
    const Point q = closest_on(n.c0, n.c1, p);
    const double capsule = std::hypot(q.x - p.x, q.y - p.y) - n.rho;
    return std::max(std::hypot(dx, dy), capsule) - (margin_ + 0x1p-46 * (std::abs(p.x) + std::abs(p.y)));
  }
  // The point of the segment a b closest to p.
  [[nodiscard]] static Point closest_on(Point a, Point b, Point p) noexcept {
    const double dx = b.x - a.x;
    const double dy = b.y - a.y;
    const double len2 = dx * dx + dy * dy;
    double t = len2 > 0 ? ((p.x - a.x) * dx + (p.y - a.y) * dy) / len2 : 0;
    t = std::clamp(t, 0.0, 1.0);
    return Point{a.x + t * dx, a.y + t * dy};
  }
  [[nodiscard]] Point closest(std::uint32_t e, Point p) const {
    ++examined_;
    return closest_on(a_[e], b_[e], p);
  }

  std::vector<Point> a_;
  std::vector<Point> b_;
  // The hierarchy: nodes_[0] the root, order_ the edges leaf by leaf; margin_ covers the rounding
  // of a closest point (a few ulps of the largest coordinate).
  std::vector<Node> nodes_;
  std::vector<std::uint32_t> order_;
  double margin_ = 0;
  // The grid for near(): cells of side h_, each listing the edges that pass through it; empty
  // without it.
  double h_ = 1;
  GridFrame frame_;
  BucketGrid<std::uint32_t, std::size_t> grid_;
  mutable std::size_t examined_ = 0;
};

}  // namespace frontpack::detail
