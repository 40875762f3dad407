// The elements of the boundary front: the walls (the polygon's edges, the open form's walls of
// Sec. 3 generalised), the reflex vertices (nodes of radius 0) and the placed disks, one id each
// (walls.hpp); the gaps the front pairs them in; and where a new disk touches two of them. Header-only
// and CGAL-free: every try at a gap asks.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "common/huge_pages.hpp"
#include "generate/boundary/walls.hpp"
#include "generate/run_control.hpp"
#include "generate/scale.hpp"
#include "generate/settings.hpp"
#include "generate/tangency.hpp"
#include "periodic/wrap.hpp"

namespace frontpack::detail {

/// A disk or a reflex vertex.
struct BoundaryNode {
  double x, y, r;
  std::int32_t cell_next;  // the next node in the same grid cell (obstacles.hpp)
  std::int32_t after;      // the second element of the last front gap with this disk first
};

/// Two elements a disk is to touch, on the left of a -> b: a gap of the front, or a void.
struct Gap {
  std::int32_t a, b;
  // A void's third element, the one that bounds it (keep_void()): a disk that a and b touch
  // no larger than the pocket between the three clears it. kNoElement on the front, and for a
  // void kept without one.
  std::int32_t bound = kNoElement;
};

class Elements {
 public:
  explicit Elements(const RunFrame& frame) noexcept : clearance_(frame.clearance), scale_(frame.scale) {}

  /// Room for n nodes.
  void reserve(std::size_t n) {
    nodes_.reserve(n);
    before_.reserve(n);
  }

  /// The walls and the reflex vertices (corners[i] at corner_at[i]); before any disk.
  void set_boundary(std::vector<Wall> walls, std::vector<Corner> corners, const std::vector<Point>& corner_at) {
    walls_ = std::move(walls);
    corners_ = std::move(corners);
    corner_count_ = static_cast<std::int32_t>(corners_.size());
    for (const Point& p : corner_at) {
      if (wrap_.any()) {
        real_.push_back(static_cast<std::int32_t>(nodes_.size()));
      }
      nodes_.push_back(BoundaryNode{p.x, p.y, 0, kNoElement, kNoElement});
      before_.push_back(kNoElement);
    }
  }

  [[nodiscard]] static bool is_wall(std::int32_t e) noexcept { return e < 0; }
  // Against a copy of corners_.size() (the vector's size is a subtraction and a shift; with it,
  // these tests were 7% of the front's instructions on a 67k-disk square, under callgrind).
  [[nodiscard]] bool is_disk(std::int32_t e) const noexcept { return e >= corner_count_; }
  [[nodiscard]] bool is_corner(std::int32_t e) const noexcept {
    return static_cast<std::uint32_t>(e) < static_cast<std::uint32_t>(corner_count_);
  }
  /// A wall or a reflex vertex.
  [[nodiscard]] bool on_wall(std::int32_t e) const noexcept { return e < corner_count_; }
  [[nodiscard]] std::int32_t corner_count() const noexcept { return corner_count_; }

  [[nodiscard]] const std::vector<Wall>& walls() const noexcept { return walls_; }
  [[nodiscard]] const Wall& wall(std::int32_t e) const noexcept { return walls_[wall_index(e)]; }
  [[nodiscard]] const BoundaryNode& node(std::int32_t e) const noexcept { return nodes_[static_cast<std::size_t>(e)]; }
  [[nodiscard]] const BoundaryNode* nodes() const noexcept { return nodes_.data(); }
  /// The nodes: reflex vertices, then disks.
  [[nodiscard]] std::size_t size() const noexcept { return nodes_.size(); }
  [[nodiscard]] const LengthScale& scale() const noexcept { return scale_; }

  /// A new disk, cell_next the next node in its grid cell; its id.
  std::int32_t add_disk(double x, double y, double r, std::int32_t cell_next) {
    const auto id = static_cast<std::int32_t>(nodes_.size());
    nodes_.push_back(BoundaryNode{x, y, r, cell_next, kNoElement});
    before_.push_back(kNoElement);
    if (wrap_.any()) {
      real_.push_back(id);
    }
    return id;
  }

  // ------------------------------------------------------------------------------------------
  // A periodic cell (periodic/wrap.hpp; the cell is [0, lx) x [0, ly), local). A disk's centre is
  // kept in the cell; a disk near a periodic side has images, nodes in the grid's cells only, never
  // in a gap: what a scan finds may be an image, and real() names its disk. Every position is
  // computed from nodes as seen from one of them (near(): the minimum image), which a cell at least
  // 10 rmax wide makes the one meant, since the elements a disk touches lie within 2 rmax of it.

  /// Makes the run periodic (before any node).
  void set_periodic(const PeriodicWrap& wrap) noexcept { wrap_ = wrap; }
  [[nodiscard]] const PeriodicWrap& wrap() const noexcept { return wrap_; }

  /// Node e as seen from (x, y): itself, or in a periodic cell its minimum image.
  [[nodiscard]] BoundaryNode near(std::int32_t e, double x, double y) const noexcept {
    BoundaryNode o = node(e);
    if (wrap_.any()) {
      o.x = x + wrap_.dx(o.x - x);
      o.y = y + wrap_.dy(o.y - y);
    }
    return o;
  }
  /// Node e as seen from node `from`.
  [[nodiscard]] BoundaryNode near(std::int32_t e, const BoundaryNode& from) const noexcept {
    return near(e, from.x, from.y);
  }

  /// The disk that node e is an image of (e itself for any other element).
  [[nodiscard]] std::int32_t real(std::int32_t e) const noexcept {
    return e >= 0 && wrap_.any() ? real_[static_cast<std::size_t>(e)] : e;
  }

  /// The images of disk n within `reach` of the cell, each entered in the grid by
  /// enter(id, x, y), which returns the node that headed its cell.
  template <class Enter>
  void add_images(std::int32_t n, double reach, Enter&& enter) {
    const BoundaryNode o = node(n);
    std::array<std::array<double, 2>, 3> shifts{};
    const std::size_t k = wrap_.image_shifts(o.x, o.y, reach, shifts);
    for (std::size_t i = 0; i < k; ++i) {
      const double x = o.x + shifts[i][0];
      const double y = o.y + shifts[i][1];
      const auto id = static_cast<std::int32_t>(nodes_.size());
      nodes_.push_back(BoundaryNode{x, y, o.r, enter(id, x, y), kNoElement});
      before_.push_back(kNoElement);
      real_.push_back(n);
      ++images_;
    }
  }
  /// How many images there are.
  [[nodiscard]] std::size_t images() const noexcept { return images_; }

  /// The front's links per disk: the first element of the last front gap with disk d second
  /// (before()), and the second element of the last with d first (after()).
  [[nodiscard]] std::int32_t before(std::int32_t d) const noexcept { return before_[static_cast<std::size_t>(d)]; }
  [[nodiscard]] std::int32_t after(std::int32_t d) const noexcept { return nodes_[static_cast<std::size_t>(d)].after; }
  /// Records gap a -> b as the last one with its first disk first and its second disk second.
  void link(std::int32_t a, std::int32_t b) noexcept {
    if (is_disk(a)) {
      nodes_[static_cast<std::size_t>(a)].after = b;
    }
    if (is_disk(b)) {
      before_[static_cast<std::size_t>(b)] = a;
    }
  }

  /// Sec. 2.2: the position (px, py) of a disk of radius r touching elements a and b (at the
  /// clearance), on the left of a -> b. False if there is none.
  bool tangent(std::int32_t a, std::int32_t b, double r, double& px, double& py) const noexcept {
    const double g = r + clearance_;
    if (!is_wall(a) && !is_wall(b)) {
      const BoundaryNode& an = node(a);
      const BoundaryNode bn = near(b, an);
      return tangent_to_two(an.x, an.y, an.r + g, bn.x, bn.y, bn.r + g, /*left=*/true, scale_, px, py);
    }
    if (is_wall(a) && is_wall(b)) {
      return tangent_to_two_walls(wall(a), wall(b), g, px, py);
    }
    // A wall and a node: before the node along the wall if the wall comes first, after it
    // otherwise. A reflex vertex at the wall's end lies on its line.
    const bool wall_first = is_wall(a);
    const Wall& wl = wall(wall_first ? a : b);
    const std::int32_t d = wall_first ? b : a;
    const BoundaryNode& dn = node(d);
    return tangent_to_disk_and_wall(dn.x, dn.y, dn.r, wl, wl.tx, wl.ty, g, !wall_first, ends(wl, d), px, py);
  }

  /// Whether a candidate at (px, py) really touches parent e where it should: its foot on a wall
  /// lies on the edge, and it is not in the outside wedge of a reflex vertex (there it would be
  /// outside the domain, touching the corner from without).
  [[nodiscard]] bool supported_by(std::int32_t e, double px, double py) const noexcept {
    if (is_wall(e)) {
      const Wall& wl = wall(e);
      const double u = (px - wl.ax) * wl.tx + (py - wl.ay) * wl.ty;
      return u >= -clearance_ && u <= wl.len + clearance_;
    }
    if (is_corner(e)) {
      const Corner& c = corners_[static_cast<std::size_t>(e)];
      const BoundaryNode& v = node(e);
      const double dx = px - v.x;
      const double dy = py - v.y;
      const bool right_of_in = c.ux1 * dy - c.uy1 * dx < 0;
      const bool right_of_out = c.ux2 * dy - c.uy2 * dx < 0;
      return !(right_of_in && right_of_out);
    }
    return true;
  }

  /// Whether node e is a reflex vertex at an end of wall wl (node coordinates and wall ends come
  /// from the same ring points, so equality is exact).
  [[nodiscard]] bool ends(const Wall& wl, std::int32_t e) const noexcept {
    if (!is_corner(e)) {
      return false;
    }
    const BoundaryNode& v = node(e);
    return (v.x == wl.ax && v.y == wl.ay) || (v.x == wl.bx && v.y == wl.by);
  }

  /// Frees the front's links (the run is over).
  void release_links() { release(before_); }

  /// Appends the disks, scaled back to the domain's coordinates, to `out`, and frees the nodes
  /// (the images are dropped first; a periodic cell's centres are kept in `cell`, keep_in_cell()).
  void move_out(Point origin, double inv_k, std::vector<Disk>& out, const Box& cell) {
    const std::size_t first_out = out.size();
    if (images_ != 0) {
      std::size_t kept = 0;
      for (std::size_t i = 0; i < nodes_.size(); ++i) {
        if (i < corners_.size() || real_[i] == static_cast<std::int32_t>(i)) {
          nodes_[kept++] = nodes_[i];
        }
      }
      nodes_.resize(kept);
      release(real_);
    }
    detail::move_out(nodes_, corners_.size(), origin, inv_k, out);
    if (wrap_.any()) {
      keep_in_cell(wrap_, std::span<Disk>(out).subspan(first_out), cell);
    }
  }

 private:
  double clearance_;
  LengthScale scale_;
  std::vector<Wall> walls_;
  std::vector<Corner> corners_;    // node i < corners_.size() is reflex vertex i (radius 0)
  std::int32_t corner_count_ = 0;  // corners_.size()
  HugeVector<BoundaryNode> nodes_;
  HugeVector<std::int32_t> before_;  // per disk: the first element of the last front gap with it second
  PeriodicWrap wrap_;                // local; none outside a periodic cell
  std::vector<std::int32_t> real_;   // periodic: per node, the disk it is (an image's, its disk's id)
  std::size_t images_ = 0;
};

}  // namespace frontpack::detail
