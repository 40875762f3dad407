// The clearance of a packing, f(p) = min(s(p), min_i |p - c_i| - r_i), with s the signed distance
// to the boundary (positive inside the domain): the radius of the largest disk centred at p that
// lies in the domain and overlaps no disk (negative where none does). f is 1-Lipschitz, so its
// value at the centre of a square plus the square's half-diagonal bounds it over the square; the
// largest empty circle (empty_circle.cpp) and the hole counts (holes.cpp) are quadtrees over the
// cells of one uniform grid, refined where these bounds leave the answer open.
//
// Floating point (measurements): distances are computed in double, a few ulps from the exact
// ones; whether a point is inside the domain is decided exactly (Domain::locate).
//
// A periodic cell: the disks are DiskImages::all() (stats/periodic_images.hpp), the boundary its
// walls alone (domain/edge_distance.hpp), and every point is located as its image in the cell. The
// grid covers the cell and, when the period is not a multiple of the grid's side, part of a cell
// more beyond its high sides, where f repeats its values near the low sides. At a point of the
// grid, f computed from the images is the true f wherever it is at most the images' reach minus
// rmax and the grid's side (the nearest disk of the plane is then among them: the point is within
// a side of the cell), and never below it elsewhere.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "common/bucket_grid.hpp"
#include "domain/edge_distance.hpp"
#include "frontpack/domain.hpp"
#include "frontpack/geometry.hpp"
#include "periodic/disk_images.hpp"

namespace frontpack::detail {

/// A square: centre (x, y), half side a.
struct Square {
  double x = 0;
  double y = 0;
  double a = 0;
  [[nodiscard]] double half_diagonal() const noexcept { return a * 1.4142135623730951; }
};

/// Where a whole square lies: unknown while the boundary may cross it.
enum class Side : std::uint8_t { unknown, inside, outside };

/// What bound() learns about f on a square.
struct SquareBounds {
  bool pruned = false;  ///< upper < threshold: nothing else was computed
  double upper = 0;     ///< f <= upper on the whole square
  double value = 0;     ///< f(centre), exact when `certain`, else an upper estimate <= threshold
  bool certain = false;
  Side side = Side::unknown;  ///< the side of the whole square, when the boundary does not cross it
};

class Clearance {
 public:
  /// A grid of cells of side about two mean radii of the disks (images.all() without the images;
  /// coarser for sparse packings) over the domain's bounding box, each disk and image listed in
  /// every cell its bounding box meets.
  Clearance(const Domain& domain, const DiskImages& images, const EdgeDistanceIndex& edges);

  [[nodiscard]] std::size_t nx() const noexcept { return frame_.nx; }
  [[nodiscard]] std::size_t ny() const noexcept { return frame_.ny; }
  [[nodiscard]] double side() const noexcept { return side_; }
  /// The lower left corner of the grid.
  [[nodiscard]] Point origin() const noexcept { return {frame_.x0, frame_.y0}; }
  [[nodiscard]] const Periods& periods() const noexcept { return periods_; }
  /// The grid column and row of a coordinate (clamped to the grid).
  [[nodiscard]] std::size_t column(double x) const noexcept { return frame_.column(x); }
  [[nodiscard]] std::size_t row(double y) const noexcept { return frame_.row(y); }
  /// The grid cell (i, j) as a square.
  [[nodiscard]] Square cell(std::size_t i, std::size_t j) const noexcept;

  /// The disks listed in the 3 x 3 cells around (i, j), each once. For every point of cell
  /// (i, j) the disks left out are at least 0.99 side() away (their |p - c| - r).
  void block(std::size_t i, std::size_t j, std::vector<std::uint32_t>& out) const;

  /// min(cap, min_i |p - c_i| - r_i) over all disks (rings of cells around p's cell).
  [[nodiscard]] double disk_distance(Point p, double cap) const;

  /// Bounds of f on q, from `list`: the block() of the grid cell that holds q, or a subset that
  /// keeps every disk able to be the nearest at some point of q (the `keep` of q's parent).
  /// Stops early (pruned) when the upper bound is below `threshold`; the centre's value is made
  /// certain (exact point location) when it exceeds `threshold`. `keep`, when given, receives
  /// the disks of `list` that can be the nearest somewhere in q. `known`: q's side, if known.
  SquareBounds bound(const Square& q, std::span<const std::uint32_t> list, Side known, double threshold,
                     std::vector<std::uint32_t>* keep) const;

 private:
  const Domain& domain_;
  Periods periods_;
  std::span<const Disk> disks_;
  const EdgeDistanceIndex& edges_;
  double side_ = 1;
  GridFrame frame_;                                 // cells of side side_ over the domain's box
  BucketGrid<std::uint32_t, std::size_t> members_;  // each disk (or image) in every cell its box meets
  mutable std::vector<std::uint32_t> stamp_;        // block(): the last cell each disk was added for
  mutable std::uint32_t stamp_now_ = 0;
};

}  // namespace frontpack::detail
