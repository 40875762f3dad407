// A uniform grid over the edges of a set of rings: the domain's spatial index.
//
// Exactness. Cell boundaries are explicit doubles X[0] < X[1] < ... < X[nx] (likewise Y), and
// cell (i, j) is the half-open real rectangle [X[i], X[i+1]) x [Y[j], Y[j+1]). Every edge is
// listed in every cell its real point set meets (conservatively: possibly a few more), so a
// cell whose list is empty provably contains no boundary point, and its whole area is inside or
// outside the domain. Queries locate a double exactly in a cell by comparisons, then decide with
// exact predicates (exact/predicates.hpp) only against the edges listed in the cells they touch.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "frontpack/domain.hpp"
#include "frontpack/geometry.hpp"

namespace frontpack::detail {

class EdgeGrid {
 public:
  /// Indexes the edges v[k] -> v[next[k]] for every k. `bounds` must contain every vertex.
  /// About `target_cells` cells are used (fewer if the coordinates' precision does not allow).
  void build(std::span<const Point> vertices, std::span<const std::uint32_t> next, Box bounds,
             std::size_t target_cells);

  /// Classifies the empty cells as inside or outside by crossing parity. Requires the rings to
  /// form a valid domain (closed, non-crossing).
  void classify_cells();

  /// Exact location of p with respect to the region bounded by the indexed rings.
  [[nodiscard]] Location locate(Point p) const;

  /// Exact: the closed disk lies in the closed region (see Domain::contains).
  [[nodiscard]] bool contains(const Disk& disk) const;

  /// Appends to `out` the edges crossed by the ray from p towards +x, by the half-open rule
  /// (an edge counts if exactly one endpoint lies strictly above p.y). Edges through p are
  /// skipped: the caller must not rely on them. Each edge appears at most once.
  void edges_crossing_ray(Point p, std::vector<std::uint32_t>& out) const;

  /// The work edges_crossing_ray(p) would do: the cells right of p in its row and the edges they
  /// list. O(1).
  [[nodiscard]] std::size_t ray_cost(Point p) const noexcept;

 private:
  static constexpr std::uint8_t kOutside = 0;
  static constexpr std::uint8_t kMixed = 1;
  static constexpr std::uint8_t kInside = 2;

  [[nodiscard]] std::size_t column(double x) const noexcept;
  [[nodiscard]] std::size_t row(double y) const noexcept;
  [[nodiscard]] std::size_t cell(std::size_t i, std::size_t j) const noexcept { return j * nx_ + i; }
  [[nodiscard]] std::span<const std::uint32_t> edges_of(std::size_t c) const noexcept {
    return {cell_edges_.data() + cell_start_[c], cell_start_[c + 1] - cell_start_[c]};
  }
  template <class F>
  void rasterize(std::uint32_t edge, F&& emit) const;
  // Appends to `out` the edges listed in cells [i, k) of row j, each once.
  void append_row_edges(std::size_t i, std::size_t k, std::size_t j, std::vector<std::uint32_t>& out) const;
  // Whether edge e crosses the horizontal line through p (half-open rule: exactly one endpoint
  // strictly above it) to the right of p; lo and hi receive its endpoints, lower first. Exact.
  bool crosses_right_of(std::uint32_t e, Point p, Point& lo, Point& hi) const;
  // Parity of the crossings of the horizontal segment p -> (X[k], p.y) with the edges listed in
  // cells [i, k) of row j. scratch is reused storage.
  [[nodiscard]] bool odd_crossings(Point p, std::size_t i, std::size_t k, std::size_t j,
                                   std::vector<std::uint32_t>& scratch) const;
  // The same upwards: parity of the crossings of the vertical segment p -> (p.x, Y[m]) with the
  // edges listed in cells [j, m) of column i (half-open rule in x: exactly one endpoint strictly
  // right of the line).
  [[nodiscard]] bool odd_crossings_up(Point p, std::size_t i, std::size_t j, std::size_t m,
                                      std::vector<std::uint32_t>& scratch) const;
  [[nodiscard]] Location locate_in(Point p, std::size_t i, std::size_t j) const;

  std::span<const Point> v_;
  std::span<const std::uint32_t> next_;
  std::size_t nx_ = 0;
  std::size_t ny_ = 0;
  std::vector<double> xs_;  // nx + 1 column boundaries
  std::vector<double> ys_;  // ny + 1 row boundaries
  double inv_w_ = 0.0;
  double inv_h_ = 0.0;
  std::vector<std::uint32_t> cell_start_;  // CSR: nx * ny + 1
  std::vector<std::uint32_t> cell_edges_;
  std::vector<std::uint8_t> state_;  // kOutside / kMixed / kInside
};

}  // namespace frontpack::detail
