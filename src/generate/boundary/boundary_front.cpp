// The boundary-conforming advancing front (generate/boundary/boundary_front.hpp): the open form's walls (Sec. 3)
// generalised to every edge of every ring, with reflex vertices as zero-radius obstacles; the
// front, kept as unlinked gaps, starts at the corners of every ring and advances inwards; cases
// (b)-(d) of Sec. 2.2 are decided by geometry (a move to touch the element in the way); the voids
// the front leaves (Sec. 2.2's holes) take later, smaller disks, bucketed by the Apollonius
// pocket each can hold. Element ids: a node (disk or reflex vertex) is >= 0, wall e is -(e + 1).
// The method, what it guarantees and where it deviates from the paper, and why:
// docs/boundary-method.md. Its density: docs/density.md; its cost: docs/performance.md.
#include "generate/boundary/boundary_front.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <numeric>
#include <string>
#include <tuple>
#include <type_traits>
#include <utility>

#include "generate/cell_grid.hpp"
#include "common/huge_pages.hpp"
#include "common/packing_density.hpp"
#include "exact/overlap.hpp"

namespace frontpack::detail {

namespace {

constexpr std::int32_t kNone = std::numeric_limits<std::int32_t>::min();
// Void buckets: log-spaced radius classes between rmin and rmax. Finer classes match each radius
// to a void barely larger than it (at rmax / rmin = 10, 24 classes gave the comb an interior of
// 0.836, 128 give 0.842); the cost per disk grows by about a tenth.
constexpr int kClasses = 128;
constexpr std::size_t kMaskWords = (kClasses + 63) / 64;  // words of a void mask (a bit per class)
// Alternatives tried per gap (cases (b)-(d): the candidate moved to touch the element in its way
// and one of its parents). None for a front gap or a void in the interior: there a move places
// few of the disks it tries, and the radii it would have placed find the voids instead (moves
// cost the interior 0.01 of packing fraction on every shape: 0.842-0.852 with one move per front
// gap, 0.849-0.864 without). One, though, where the element in the way is a wall or
// a reflex vertex (kWallCut): the moved disk then touches the boundary, and a smooth curve's band
// stays as dense as its interior (without it a 100,000-vertex circle's band packed 0.66 against
// 0.84 inside). Gaps on a wall or a reflex vertex get three, and so do voids there: with one per
// void the band of a rough boundary (big_polygon) packed 0.023 below its interior, with three
// 0.015.
constexpr int kMoves = 0;
constexpr int kWallCut = 1;
constexpr int kWallMoves = 3;
constexpr int kVoidMoves = 3;
constexpr std::size_t kBlock = 16;  // cells per side of a block in the walled_ bitmap
constexpr std::size_t kBlockCells = kBlock * kBlock;
constexpr std::uint32_t kWallList = 16;  // a cell with more walls than this asks the wall tree
constexpr std::size_t kLeafWalls = 4;    // walls per leaf of the wall tree
// kSlideTurn, 0.35 rad (20 degrees): a vertex where the boundary turns by less is no corner: the
// front does not start there, and the wall layer slides across it (slide()). Used through its
// cosine only, correctly rounded here (no C library call).
constexpr double kCosSlideTurn = 0.9393727128473789;  // cos(0.35)

// Lanes. pocket() computes one pocket in a double; a disk placed in a void needs two, which
// pocket_pair() computes in the two lanes of a vector (GCC's and Clang's vector extensions, whose
// + - * / and square root are the correctly rounded scalar operations lane by lane) from the same
// source, so with the same bits. Helpers that take either:
using V2 = double __attribute__((vector_size(16)));
using M2 = decltype(V2{} < V2{});  // a comparison of V2s: -1 true, 0 false (Clang and GCC name it differently)
template <class T>
T lanes(double a) noexcept {
  if constexpr (std::is_same_v<T, double>) {
    return a;
  } else {
    return T{a, a};
  }
}
inline double select(bool m, double a, double b) noexcept {
  return m ? a : b;
}
inline V2 select(M2 m, V2 a, V2 b) noexcept {
  return std::bit_cast<V2>((std::bit_cast<M2>(a) & m) | (std::bit_cast<M2>(b) & ~m));
}
inline bool lnot(bool m) noexcept {
  return !m;
}
inline M2 lnot(M2 m) noexcept {
  return ~m;
}
inline double square_root(double a) noexcept {
  return std::sqrt(a);
}
inline V2 square_root(V2 a) noexcept {
#if defined(__SSE2__)
  return __builtin_ia32_sqrtpd(a);
#else
  return V2{std::sqrt(a[0]), std::sqrt(a[1])};
#endif
}

class BoundaryFront {
  struct Node {
    double x, y, r;
    std::int32_t cell_next;
    std::int32_t after;  // the second element of the last front gap with this disk first (overtaker())
  };
  struct Wall {
    double ax, ay, bx, by;  // a -> b, the domain on the left
    double tx, ty;          // unit direction
    double nx, ny;          // unit inward normal
    double len, w;          // length; n . a
  };
  struct Corner {  // a reflex vertex: the directions of its edges in and out
    double ux1, uy1, ux2, uy2;
  };
  struct Gap {
    std::int32_t a, b;
    // A void's third element, the one that bounds it (keep_void()): a disk that a and b touch
    // no larger than the pocket between the three clears it. kNone on the front, and for a void
    // kept without one.
    std::int32_t bound = kNone;
  };

 public:
  BoundaryFront(const BoundaryRequest& req, Rng& rng, std::vector<Disk>& out, FillStats& stats)
      : req_(req), rng_(rng), out_(out), stats_(stats), control_(req.max_disks, req.tick), out_before_(out.size()) {
    Box box;
    for (const Point& p : req.polygon->outer) {
      box.extend(p);
    }
    // Local coordinates, in the unit of WorkScale (1 but for rmax outside [2^-300, 2^300]).
    unit_ = WorkScale(req.radii->max());
    origin_ = Point{box.xmin, box.ymin};
    width_ = (box.xmax - box.xmin) * unit_.k;
    height_ = (box.ymax - box.ymin) * unit_.k;
    rmin_ = req.radii->min() * unit_.k;
    rmax_ = req.radii->max() * unit_.k;
    clearance_ = req.clearance * unit_.k;
    scale_ = LengthScale(rmax_);
    margin_ = clearance_ / 2;
    band_ = clearance_ / 4;
    box_ = Box{-clearance_, -clearance_, width_ + clearance_, height_ + clearance_};
    classes_ = RadiusClasses<kClasses>(rmin_, rmax_);

    estimate_ = estimate_disks(box, *req.radii);
    // (Every disk lies in the polygon: at most its box's area, bound_disks(), 1.18 estimates.)
    const auto reserve = count_of(estimate_ * 1.3 + 64, 1e9);
    nodes_.reserve(reserve);
    before_.reserve(reserve);
    setup_walls();
    setup_grid();
    build_wall_tree();
    for (const Wall& w : walls_) {
      polygon_area_ += (w.ax * w.by - w.bx * w.ay) / 2;  // holes (clockwise) subtract
    }
  }

  FrontResult run() {
    FrontResult result;
    double r = draw();
    int cls = class_of(r);  // r's void class (r stays until it is placed)
    for (;;) {
      if (control_.stop(placed(), area_ * unit_.inv_k * unit_.inv_k, result)) {
        break;
      }
      Gap g{kNone, kNone};
      // Voids first, those on a rough wall before the others, the tightest class whose radii all
      // exceed r, the most recent void in it.
      int k = any_rough_ ? first_void_above(1, cls) : -1;
      std::size_t side = 1;
      if (k < 0) {
        k = first_void_above(0, cls);
        side = 0;
      }
      if (k >= 0) {
        std::vector<Gap>& bucket = voids_[side][static_cast<std::size_t>(k)];
        g = bucket.back();
        bucket.pop_back();
        if (bucket.empty()) {
          mask_[side][static_cast<std::size_t>(k) / 64] &= ~(std::uint64_t{1} << (static_cast<unsigned>(k) % 64));
        }
      } else if (wall_head_ < wall_fifo_.size()) {
        g = wall_fifo_[wall_head_++];  // the first layer along every wall comes first
      } else if (!fifo_empty()) {
        g = fifo_[head_++];
        if (head_ > 4096 && head_ * 2 > fifo_.size()) {  // drop the consumed half (amortised O(1))
          fifo_.erase(fifo_.begin(), fifo_.begin() + static_cast<std::ptrdiff_t>(head_));
          head_ = 0;
        }
        if (const std::int32_t o = overtaker(g); o != kNone) {
          if (req_.fill_voids) {
            push_void(g, kClasses - 1, o);
          }
          continue;
        }
      } else {
        // The front is done and no void can take r. If the walls could not start a front (a
        // boundary rougher than the smallest disk: nothing fits in its corners) and the polygon
        // is far from full, a seed pair of disks starts one inside, growing outwards. Otherwise
        // the run ends here. (Skipping r and drawing smaller radii for the voids left would fill
        // them, but only by distorting the size distribution towards small radii.)
        if (seed(r)) {
          area_ += r * r;
          r = draw();
          cls = class_of(r);
          continue;
        }
        break;
      }
      if (try_gap(g, r, k >= 0)) {
        area_ += r * r;
        r = draw();
        cls = class_of(r);
      } else if (req_.fill_voids && cls > 0 && !hopeless_) {
        // r did not fit: the gap may still take a smaller disk, at most as large as the pocket
        // between its elements and the disk in the way.
        push_void(g, cls, blocker_);
      }
    }
    // The front, the voids and the grid are done with: free them before the output grows (peak
    // memory: the nodes and the output are then all that is left).
    release(fifo_);
    release(wall_fifo_);
    for (auto& side : voids_) {
      for (auto& bucket : side) {
        release(bucket);
      }
    }
    release(before_);
    release(head_cell_);
    release(block_first_);
    release(cell_walls_);
    release(wall_ids_);
    release(walled_);
    move_out(nodes_, corners_.size(), origin_, unit_.inv_k, out_);
    result.fixed_bytes = fixed_bytes_;
    return result;
  }

 private:
  [[nodiscard]] std::size_t placed() const noexcept {
    return nodes_.size() - static_cast<std::size_t>(corner_count_) + out_before_;
  }
  // Whether front gap g has been overtaken: a later gap paired its first disk with another second
  // element, or its second disk with another first one. Mostly a disk placed since then touching
  // one of them on g's free side has covered the gap (in the paper's list, g's segment was cut),
  // so its first position is taken; the gap is kept as a void instead, for the smaller radii that
  // may still fit. (Two thirds of the front's gaps used to fail all their moves; without the
  // overtaken ones the 1M-disk square needs 12% fewer overlap scans, and the density moves less
  // than from seed to seed.) The later pairing can also come from a void filled behind g (a fifth
  // of the cases with radii 0.002-0.02); testing its side as well changed neither the cost (-0.8%)
  // nor the densities beyond their noise, so it is not tested.
  //
  // Returns the element that overtook g (its first disk's new partner, else its second's), or
  // kNone if g is still on the front. (Neither link is ever kNone once g was queued: pushing g
  // set both.)
  [[nodiscard]] std::int32_t overtaker(Gap g) const noexcept {
    if (is_disk(g.a) && nodes_[static_cast<std::size_t>(g.a)].after != g.b) {
      return nodes_[static_cast<std::size_t>(g.a)].after;
    }
    if (is_disk(g.b) && before_[static_cast<std::size_t>(g.b)] != g.a) {
      return before_[static_cast<std::size_t>(g.b)];
    }
    return kNone;
  }
  [[nodiscard]] bool fifo_empty() const noexcept { return head_ == fifo_.size() && wall_head_ == wall_fifo_.size(); }
  [[nodiscard]] bool on_wall(std::int32_t e) const noexcept { return e < corner_count_; }  // a wall or a corner
  // Records gap g as the last one with its first disk first and its second disk second
  // (overtaker()).
  void link(Gap g) noexcept {
    if (is_disk(g.a)) {
      nodes_[static_cast<std::size_t>(g.a)].after = g.b;
    }
    if (is_disk(g.b)) {
      before_[static_cast<std::size_t>(g.b)] = g.a;
    }
  }
  void push_gap(Gap g) {
    link(g);
    if (on_wall(g.a) || on_wall(g.b)) {
      wall_fifo_.push_back(g);
    } else {
      fifo_.push_back(g);
    }
  }
  [[nodiscard]] static bool is_wall(std::int32_t e) noexcept { return e < 0; }
  [[nodiscard]] static std::size_t wall_index(std::int32_t e) noexcept { return static_cast<std::size_t>(-(e + 1)); }
  // Against a copy of corners_.size() (the vector's size is a subtraction and a shift; with it,
  // these tests were 7% of the front's instructions on a 67k-disk square, under callgrind).
  [[nodiscard]] bool is_disk(std::int32_t e) const noexcept { return e >= corner_count_; }
  [[nodiscard]] bool is_corner(std::int32_t e) const noexcept {
    return static_cast<std::uint32_t>(e) < static_cast<std::uint32_t>(corner_count_);
  }
  [[nodiscard]] int class_of(double r) const noexcept { return classes_.of(r); }
  double draw() { return req_.radii->quantile(rng_.uniform()) * unit_.k; }

  // ------------------------------------------------------------------------------------------
  // Walls, reflex vertices and the initial gaps.

  // |(dx, dy)| from + - * / and a square root alone, all correctly rounded on every platform:
  // std::hypot's last bit differs between C libraries, and every tangent to the wall, so every
  // packing, would differ with it. At a power-of-two scale (exact), so that the squares neither
  // overflow nor underflow.
  static double length(double dx, double dy) noexcept {
    const double m = std::max(std::abs(dx), std::abs(dy));
    if (!(m > 0) || !std::isfinite(m)) {
      return m;  // 0 where two vertices round to one local point (the wall then tests as nothing)
    }
    const int e = std::ilogb(m);
    const double x = std::ldexp(dx, -e);
    const double y = std::ldexp(dy, -e);
    return std::ldexp(std::sqrt(x * x + y * y), e);
  }

  void setup_walls() {
    auto add_ring = [&](const Ring& ring) {
      const std::size_t n = ring.size();
      const auto first = static_cast<std::int32_t>(walls_.size());
      for (std::size_t i = 0; i < n; ++i) {
        const Point a = local(ring[i]);
        const Point b = local(ring[(i + 1) % n]);
        const double dx = b.x - a.x;
        const double dy = b.y - a.y;
        const double len = length(dx, dy);
        Wall w{a.x, a.y, b.x, b.y, dx / len, dy / len, -dy / len, dx / len, len, 0};
        w.w = w.nx * a.x + w.ny * a.y;
        walls_.push_back(w);
      }
      // Corner at vertex i + 1, between wall i (in) and wall i + 1 (out). The front starts at
      // every corner sharper than kSlideTurn; along gentler ones the wall layer slides from one
      // wall to the next (slide()), so a finely divided curve is not started at each of its
      // vertices (the ring's sharpest vertex starts it if none is sharp).
      ring_first_.push_back(static_cast<std::size_t>(first));
      rough_.resize(walls_.size(), 0);
      std::size_t sharpest = 0;
      double sharpest_turn = -1;
      bool started = false;
      auto start_at = [&](std::size_t i, bool convex, std::int32_t v) {
        const std::int32_t in = -(first + static_cast<std::int32_t>(i) + 1);
        const std::int32_t out = -(first + static_cast<std::int32_t>((i + 1) % n) + 1);
        if (convex) {
          push_gap(Gap{in, out});
        } else {
          push_gap(Gap{in, v});
          push_gap(Gap{v, out});
        }
        started = true;
      };
      std::vector<std::int32_t> vertex(n, kNone);  // the reflex vertex's node, per vertex
      for (std::size_t i = 0; i < n; ++i) {
        const Wall& wi = walls_[static_cast<std::size_t>(first) + i];
        const Wall& wo = walls_[static_cast<std::size_t>(first) + (i + 1) % n];
        const double cross = wi.tx * wo.ty - wi.ty * wo.tx;  // > 0: left turn, a convex corner
        const double dot = wi.tx * wo.tx + wi.ty * wo.ty;    // the cosine of the turn
        // A key that grows with the turn over [0, pi] (its sine, then 2 minus it), from * and -
        // alone: with std::atan2, whose last bit differs between C libraries, the vertex that
        // starts a ring without a corner could too.
        const double turn = dot > 0 ? std::abs(cross) : 2 - std::abs(cross);
        const bool sharp = dot <= kCosSlideTurn;  // turns by kSlideTurn or more
        const bool convex = cross > 1e-12;
        if (!convex) {
          vertex[i] = static_cast<std::int32_t>(corners_.size());
          corners_.push_back(Corner{wi.tx, wi.ty, wo.tx, wo.ty});
          corner_count_ = static_cast<std::int32_t>(corners_.size());
          corner_at_.push_back(Point{wi.bx, wi.by});
        }
        if (sharp && wi.len < 2 * rmax_) {
          rough_[static_cast<std::size_t>(first) + i] = 1;
        }
        if (sharp && wo.len < 2 * rmax_) {
          rough_[static_cast<std::size_t>(first) + (i + 1) % n] = 1;
        }
        if (turn > sharpest_turn) {
          sharpest_turn = turn;
          sharpest = i;
        }
        if (sharp) {
          start_at(i, convex, vertex[i]);
        }
      }
      if (!started && n > 0) {
        const Wall& wi = walls_[static_cast<std::size_t>(first) + sharpest];
        const Wall& wo = walls_[static_cast<std::size_t>(first) + (sharpest + 1) % n];
        start_at(sharpest, wi.tx * wo.ty - wi.ty * wo.tx > 1e-12, vertex[sharpest]);
      }
    };
    add_ring(req_.polygon->outer);
    for (const Ring& hole : req_.polygon->holes) {
      add_ring(hole);
    }
    any_rough_ = std::find(rough_.begin(), rough_.end(), 1) != rough_.end();
  }

  [[nodiscard]] Point local(Point p) const noexcept { return {(p.x - origin_.x) * unit_.k, (p.y - origin_.y) * unit_.k}; }

  // ------------------------------------------------------------------------------------------
  // The grid: placed disks in linked cells (reflex vertices are nodes, but not in the cells: see
  // below); per cell, the walls within reach of it (a disk of radius <= rmax centred in the cell
  // can only cross those).

  void setup_grid() {
    grid_ = CellGrid(0, 0, width_, height_, rmax_);
    probes_inside_ = clearance_ < rmax_ && !grid_.coarse;
    // The memory limit (BoundaryRequest::memory_limit) counts what is built here: the cell heads
    // (4 bytes a cell) and 12 bytes a block of cells; the (cell, wall) pairs, 16 bytes each while
    // they are listed (8, and as much again while the list moves or is copied grouped), then 12
    // (the grouped copy and the lists kept) with 1,028 bytes a walled block; then
    // peak_bytes_per_disk per disk. On a sliver 1e-7 high these lists, sized by the grid's cells
    // and not by the disks, were most of the run's memory (565 MB for 1.1M disks).
    const std::size_t blocks = ((grid_.nx + kBlock - 1) / kBlock) * ((grid_.ny + kBlock - 1) / kBlock);
    std::size_t need = grid_.cells() * sizeof(std::int32_t) + blocks * (sizeof(std::size_t) + sizeof(std::uint32_t));
    const auto over_limit = [&](std::size_t bytes, const std::string& what) {
      if (req_.memory_limit != 0 && bytes >= req_.memory_limit) {
        throw_memory_limit(req_.memory_limit, what + " (" + std::to_string(bytes) + " bytes)",
                           count_of(estimate_, 1e18));
      }
    };
    over_limit(need, "the grid over the polygon's box has " + std::to_string(grid_.cells()) + " cells");
    head_cell_.assign(grid_.cells(), kNone);

    // The reflex vertices are nodes (elements a disk can touch) but stay out of the cells: as
    // obstacles their walls cover them. A disk closer to a vertex than its radius (plus the margin)
    // is as close to the walls that end there, which are in the cell's list or found by the tree,
    // and at least as deep in them, and the walls are tried first; so no scan returned one on 5
    // shapes, and on the rough ring `big_polygon` they were most of the disks each scan near the
    // boundary tested. (Up to rounding: within a few ulps of the threshold the vertex was decided
    // exactly and the wall in floating point, and a review's simulation found probes, 0.1-0.4% of
    // those placed there on purpose, that only the vertex stopped; each stayed at least 0.999 of
    // the margin, half the clearance, from the boundary, which is what the wall test guarantees
    // everywhere else, and the certifier decides containment exactly.)
    for (std::size_t v = 0; v < corners_.size(); ++v) {
      nodes_.push_back(Node{corner_at_[v].x, corner_at_[v].y, 0, kNone, kNone});
      before_.push_back(kNone);
    }

    // Walls per cell: those meeting the cell grown by rmax + the clearance, kept for the cells of
    // walled blocks only (below). Found as (cell, wall) pairs, row by row along each wall: in a
    // row, only the columns that the wall's stretch in the row's band can reach are tested, so
    // that the work follows the walls' length and not the area of their boxes (a diagonal wall's
    // box is a quarter of the grid: testing every cell of it took 49 ms, 14% of the front, on a
    // 1M-disk diamond), and nothing is kept per cell of the grid.
    const double reach = (rmax_ + clearance_) * (1 + 1e-9) + 4 * clearance_;
    struct Pair {
      // The cell's block, then its place in the block (the lists' order): below
      // (nx + kBlock - 1) (ny + kBlock - 1), which CellGrid's cap of about 16M cells keeps far
      // below 2^32.
      std::uint32_t key;
      std::uint32_t wall;
    };
    std::vector<Pair> pairs;
    blocks_x_ = (grid_.nx + kBlock - 1) / kBlock;  // for block_of()
    for (std::size_t e = 0; e < walls_.size(); ++e) {
      const Wall& wl = walls_[e];
      const double dx = wl.bx - wl.ax;
      const double dy = wl.by - wl.ay;
      const std::int64_t c0 = col(std::min(wl.ax, wl.bx) - reach);
      const std::int64_t c1 = col(std::max(wl.ax, wl.bx) + reach);
      const std::int64_t r0 = row(std::min(wl.ay, wl.by) - reach);
      const std::int64_t r1 = row(std::max(wl.ay, wl.by) + reach);
      for (std::int64_t j = r0; j <= r1; ++j) {
        const double y0 = grid_.y0 + static_cast<double>(j) * grid_.side - reach;
        // The wall's x-extent in the row's band, grown by a cell on each side (far more than
        // rounding needs: the exact test below decides every cell; this only skips those that
        // cannot pass it).
        double t0 = 0;
        double t1 = 1;
        if (dy != 0) {
          const double ta = (y0 - grid_.side - wl.ay) / dy;
          const double tb = (y0 + 2 * grid_.side + 2 * reach - wl.ay) / dy;
          t0 = std::max(t0, std::min(ta, tb));
          t1 = std::min(t1, std::max(ta, tb));
          if (!(t0 <= t1)) {
            continue;
          }
        }
        const double xa = wl.ax + t0 * dx;
        const double xb = wl.ax + t1 * dx;
        const std::int64_t i0 = std::max(c0, col(std::min(xa, xb) - reach) - 1);
        const std::int64_t i1 = std::min(c1, col(std::max(xa, xb) + reach) + 1);
        for (std::int64_t i = i0; i <= i1; ++i) {
          const double x0 = grid_.x0 + static_cast<double>(i) * grid_.side - reach;
          if (!segment_meets_box(wl, x0, y0, x0 + grid_.side + 2 * reach, y0 + grid_.side + 2 * reach)) {
            continue;
          }
          const auto ui = static_cast<std::size_t>(i);
          const auto uj = static_cast<std::size_t>(j);
          pairs.push_back(Pair{static_cast<std::uint32_t>(block_of(uj, ui) * kBlockCells + place_in_block(uj, ui)),
                               static_cast<std::uint32_t>(e)});
        }
        if (req_.memory_limit != 0 && need + 16 * pairs.size() >= req_.memory_limit) {  // a row at a time
          over_limit(need + 16 * pairs.size(), "the domain's edges come within reach of " + std::to_string(pairs.size()) +
                                                   "+ cells of its grid, counted with multiplicity");
        }
      }
    }
    // A bit per block of kBlock x kBlock cells: whether any of them has walls. Most probes lie in
    // blocks without, and the bits of a whole front fit in the first-level cache, unlike the
    // cells' lists (a tenth of the front's cache misses were reading them).
    // (blocks: blocks_x_ * the blocks per column, counted above.)
    walled_.assign((blocks + 63) / 64, 0);
    // The pairs grouped by block (a counting sort: stable, so each block's pairs stay in the order
    // of the walls).
    std::vector<std::size_t> start(blocks + 1, 0);
    for (const Pair& q : pairs) {
      const std::size_t b = q.key / kBlockCells;
      ++start[b + 1];
      walled_[b / 64] |= std::uint64_t{1} << (b % 64);
    }
    std::partial_sum(start.begin(), start.end(), start.begin());
    if (pairs.size() > std::numeric_limits<std::uint32_t>::max()) {  // the lists index them in 32 bits
      throw LimitError("the domain's edges come within reach of " + std::to_string(pairs.size()) +
                           " cells of the packing's grid, counted with multiplicity, more than 2^32; use larger "
                           "radii or a domain with fewer edges",
                       static_cast<std::size_t>(std::min(estimate_, 1e18)));
    }
    std::vector<Pair> grouped(pairs.size());
    {
      std::vector<std::size_t> at(start.begin(), start.end() - 1);
      for (const Pair& q : pairs) {
        grouped[at[q.key / kBlockCells]++] = q;
      }
    }
    release(pairs);
    // The lists of the walled blocks' cells, block by block: a block's cells' lists one after the
    // other in wall_ids_, and kBlockCells + 1 entries in cell_walls_ from block_first_[b], so that a
    // cell's list runs from its entry to the next. Each block's pairs are put in place by cell
    // with a second counting sort, which keeps a cell's walls in the order of the walls (as when
    // every cell was tested in turn). (Begins for every cell of the grid were 4 bytes per cell, 4
    // per disk at cells of rmax, most of them for cells no wall comes near.)
    block_first_.assign(blocks, 0);
    std::size_t walled_blocks = 0;
    for (const std::uint64_t bits : walled_) {
      walled_blocks += static_cast<std::size_t>(std::popcount(bits));
    }
    over_limit(need + 12 * grouped.size() + walled_blocks * (kBlockCells + 1) * sizeof(std::uint32_t),
               "the domain's edges come near " + std::to_string(walled_blocks) + " blocks of " +
                   std::to_string(kBlockCells) + " cells of its grid, with " + std::to_string(grouped.size()) +
                   " (cell, wall) pairs");
    cell_walls_.reserve(walled_blocks * (kBlockCells + 1));
    wall_ids_.resize(grouped.size());
    std::array<std::uint32_t, kBlockCells + 1> at{};
    for (std::size_t b = 0; b < blocks; ++b) {
      if (start[b] == start[b + 1]) {
        continue;
      }
      block_first_[b] = static_cast<std::uint32_t>(cell_walls_.size());
      at.fill(0);
      for (std::size_t k = start[b]; k < start[b + 1]; ++k) {
        ++at[grouped[k].key % kBlockCells + 1];
      }
      for (std::size_t l = 0; l < kBlockCells; ++l) {
        at[l + 1] += at[l];
      }
      const auto base = static_cast<std::uint32_t>(start[b]);
      for (const std::uint32_t first : at) {
        cell_walls_.push_back(base + first);
      }
      for (std::size_t k = start[b]; k < start[b + 1]; ++k) {
        wall_ids_[base + at[grouped[k].key % kBlockCells]++] = -(static_cast<std::int32_t>(grouped[k].wall) + 1);
      }
    }
    // What stays for the run; the disks have the rest of the limit.
    fixed_bytes_ = (head_cell_.size() + wall_ids_.size() + cell_walls_.size() + block_first_.size()) *
                       sizeof(std::uint32_t) +
                   walled_.size() * sizeof(std::uint64_t);
    if (req_.memory_limit != 0) {
      over_limit(fixed_bytes_, "the grid and the lists of the walls near its cells");
      control_.limit_memory(req_.memory_limit - fixed_bytes_);
    }
  }

  // The range of cell (row, col)'s walls in wall_ids_; only for a cell in a walled block.
  [[nodiscard]] std::pair<std::uint32_t, std::uint32_t> cell_walls(std::size_t row, std::size_t col) const noexcept {
    const std::uint32_t* at = cell_walls_.data() + block_first_[block_of(row, col)] + place_in_block(row, col);
    return {at[0], at[1]};
  }

  [[nodiscard]] std::size_t block_of(std::size_t row, std::size_t col) const noexcept {
    return row / kBlock * blocks_x_ + col / kBlock;
  }
  // Cell (row, col)'s place in its block, the order of the block's lists.
  [[nodiscard]] static std::size_t place_in_block(std::size_t row, std::size_t col) noexcept {
    return row % kBlock * kBlock + col % kBlock;
  }

  // Whether segment wl meets the box [x0, x1] x [y0, y1] (Liang-Barsky clipping; conservative
  // enough: the box is already grown by the reach).
  static bool segment_meets_box(const Wall& wl, double x0, double y0, double x1, double y1) noexcept {
    double t0 = 0;
    double t1 = 1;
    const double dx = wl.bx - wl.ax;
    const double dy = wl.by - wl.ay;
    const std::array<double, 4> p{-dx, dx, -dy, dy};
    const std::array<double, 4> q{wl.ax - x0, x1 - wl.ax, wl.ay - y0, y1 - wl.ay};
    for (std::size_t k = 0; k < 4; ++k) {
      if (p[k] == 0) {
        if (q[k] < 0) {
          return false;
        }
        continue;
      }
      const double t = q[k] / p[k];
      if (p[k] < 0) {
        t0 = std::max(t0, t);
      } else {
        t1 = std::min(t1, t);
      }
      if (t0 > t1) {
        return false;
      }
    }
    return true;
  }

  [[nodiscard]] std::int64_t col(double x) const noexcept { return grid_.col(x); }
  [[nodiscard]] std::int64_t row(double y) const noexcept { return grid_.row(y); }
  // col() and row() for a candidate that passed the box test (try_gap(), fits()): inside the
  // polygon's box grown by the clearance, so that, with a clearance below rmax, everything within
  // its reach (r + rmax and a clearance or two) lies in the grid's margin of 4 rmax, and its cells
  // need no clamping (the same cells, in fewer instructions: the clamps were 6% of the front's).
  // (Not for the one cell of a grid whose margin could not be 4 rmax.)
  [[nodiscard]] std::int64_t probe_col(double x) const noexcept {
    return probes_inside_ ? grid_.col_inside(x) : grid_.col(x);
  }
  [[nodiscard]] std::int64_t probe_row(double y) const noexcept {
    return probes_inside_ ? grid_.row_inside(y) : grid_.row(y);
  }
  [[nodiscard]] std::size_t probe_cell(double x, double y) const noexcept {
    return static_cast<std::size_t>(probe_row(y)) * grid_.nx + static_cast<std::size_t>(probe_col(x));
  }

  std::int32_t add_node(double x, double y, double r) {
    const auto id = static_cast<std::int32_t>(nodes_.size());
    const std::size_t c = probe_cell(x, y);
    nodes_.push_back(Node{x, y, r, head_cell_[c], kNone});
    before_.push_back(kNone);
    head_cell_[c] = id;
    return id;
  }

  // ------------------------------------------------------------------------------------------
  // Tangent positions: a disk of radius r touching elements a and b (at the clearance), on the
  // left of a -> b. False if there is none.

  bool tangent(std::int32_t a, std::int32_t b, double r, double& px, double& py) const noexcept {
    const double g = r + clearance_;
    if (!is_wall(a) && !is_wall(b)) {
      const Node& an = nodes_[static_cast<std::size_t>(a)];
      const Node& bn = nodes_[static_cast<std::size_t>(b)];
      return tangent_to_two(an.x, an.y, an.r + g, bn.x, bn.y, bn.r + g, /*left=*/true, scale_, px, py);
    }
    if (is_wall(a) && is_wall(b)) {
      // Where the two walls' lines, moved in by g, cross.
      const Wall& wa = walls_[wall_index(a)];
      const Wall& wb = walls_[wall_index(b)];
      const double det = wa.nx * wb.ny - wa.ny * wb.nx;
      if (!(std::abs(det) > 1e-9)) {
        return false;  // parallel
      }
      const double ca = wa.w + g;
      const double cb = wb.w + g;
      px = (ca * wb.ny - cb * wa.ny) / det;
      py = (wa.nx * cb - wb.nx * ca) / det;
      return std::isfinite(px) && std::isfinite(py);
    }
    // A wall and a node: on the wall's line moved in by g, at distance rn + g from the node;
    // before the node along the wall if the wall comes first, after it otherwise.
    const bool wall_first = is_wall(a);
    const Wall& wl = walls_[wall_index(wall_first ? a : b)];
    const Node& dn = nodes_[static_cast<std::size_t>(wall_first ? b : a)];
    const double rd = dn.r + g;
    const double off = wl.nx * dn.x + wl.ny * dn.y - (wl.w + g);
    // A reflex vertex at the wall's end lies on its line: the disk touches the wall there, and
    // s is 0 (computed, rounding made s2 negative about half the time, and the gap failed).
    const double s2 = ends(wl, wall_first ? b : a) ? 0 : rd * rd - off * off;
    if (!(s2 >= 0)) {
      return false;
    }
    const double s = wall_first ? -std::sqrt(s2) : std::sqrt(s2);
    px = dn.x - off * wl.nx + s * wl.tx;
    py = dn.y - off * wl.ny + s * wl.ty;
    return true;
  }

  // ------------------------------------------------------------------------------------------
  // The walls in a bounding-box tree, for cells whose list is long (a ring of 100,000 short edges
  // puts hundreds of walls within rmax of every cell along it; scanning them all made such rings
  // cost hundreds of microseconds per disk). The tree is implicit over the walls in their order,
  // which follows the rings, so consecutive walls are neighbours and a node's box stays small:
  // leaves of kLeafWalls walls, node k's children 2k and 2k + 1, leaves from index leaves_. Built
  // once; queries allocate nothing. (Boost.Geometry's rtree allocates in its nearest query, and
  // CGAL 5.5's AABB tree is three-dimensional only.)

  struct Bounds {
    double xmin, ymin, xmax, ymax;
  };

  void build_wall_tree() {
    const std::size_t n = walls_.size();
    const std::size_t leaves = (n + kLeafWalls - 1) / kLeafWalls;
    leaves_ = std::bit_ceil(std::max<std::size_t>(leaves, 1));
    const double inf = std::numeric_limits<double>::infinity();
    tree_.assign(2 * leaves_, Bounds{inf, inf, -inf, -inf});
    for (std::size_t e = 0; e < n; ++e) {
      Bounds& b = tree_[leaves_ + e / kLeafWalls];
      const Wall& wl = walls_[e];
      b.xmin = std::min({b.xmin, wl.ax, wl.bx});
      b.ymin = std::min({b.ymin, wl.ay, wl.by});
      b.xmax = std::max({b.xmax, wl.ax, wl.bx});
      b.ymax = std::max({b.ymax, wl.ay, wl.by});
    }
    for (std::size_t k = leaves_ - 1; k >= 1; --k) {
      const Bounds& l = tree_[2 * k];
      const Bounds& r = tree_[2 * k + 1];
      tree_[k] = Bounds{std::min(l.xmin, r.xmin), std::min(l.ymin, r.ymin), std::max(l.xmax, r.xmax),
                        std::max(l.ymax, r.ymax)};
    }
  }

  // Squared distance from (x, y) to box b (0 inside; infinite for an empty box).
  static double distance2(const Bounds& b, double x, double y) noexcept {
    const double dx = std::max(std::max(b.xmin - x, 0.0), x - b.xmax);
    const double dy = std::max(std::max(b.ymin - y, 0.0), y - b.ymax);
    return dx * dx + dy * dy;
  }

  // The wall nearest to (x, y) at a squared distance below d2 (on return, its squared distance),
  // or kNone. Of walls at the same distance, the first in order, as the cell lists have them.
  // A caller that knows a wall `best` at squared distance d2 passes it: the search then prunes
  // everything farther from the start, and returns `best` if no wall is nearer (or as near and
  // before it in order).
  std::int32_t nearest_wall(double x, double y, double& d2, std::int32_t best = kNone) const noexcept {
    // Depth <= 64: at most one deferred sibling per level. Each entry carries its box's squared
    // distance, computed once when it was pushed. Not zeroed: only what was pushed is read, and
    // zeroing the stack was 4% of the instructions on a 12,000-edge ring.
    struct Entry {
      std::size_t node;
      double d2;
    };
    std::array<Entry, 128> stack;  // NOLINT(cppcoreguidelines-pro-type-member-init)
    std::size_t top = 0;
    stack[top++] = Entry{1, distance2(tree_[1], x, y)};
    while (top > 0) {
      const auto [k, box_d2] = stack[--top];
      if (!(box_d2 <= d2)) {
        continue;
      }
      if (k >= leaves_) {
        const std::size_t first = (k - leaves_) * kLeafWalls;
        const std::size_t last = std::min(first + kLeafWalls, walls_.size());
        for (std::size_t e = first; e < last; ++e) {
          const double w2 = distance2(walls_[e], x, y);
          const auto id = -(static_cast<std::int32_t>(e) + 1);
          if (w2 < d2 || (w2 == d2 && best != kNone && id > best)) {
            d2 = w2;
            best = id;
          }
        }
        continue;
      }
      // The nearer child on top, so that it is searched first and prunes the other.
      const Entry left{2 * k, distance2(tree_[2 * k], x, y)};
      const Entry right{2 * k + 1, distance2(tree_[2 * k + 1], x, y)};
      const bool left_first = left.d2 <= right.d2;
      stack[top++] = left_first ? right : left;
      stack[top++] = left_first ? left : right;
    }
    return best;
  }

  // ------------------------------------------------------------------------------------------
  // Overlap tests.

  [[nodiscard]] Probe probe(double x, double y, double r) const noexcept { return Probe::at(x, y, r, margin_, band_); }

  // How far the candidate comes into disk o's keep-out distance r + o.r + margin (> 0: it
  // overlaps); as generate/paper_front.cpp, floating point outside a narrow band, the exact predicate inside.
  double depth(const Probe& p, const Node& o) {
    const double dx = p.x - o.x;
    const double dy = p.y - o.y;
    const double d2 = dx * dx + dy * dy;
    const double hi = p.r_hi + o.r;
    if (d2 >= hi * hi) {
      return -1;
    }
    const double lo = p.r_lo + o.r;
    if (lo > 0 && d2 < lo * lo) {
      return p.r + o.r + margin_ - std::sqrt(d2);
    }
    return depth_exact(p, o);
  }

  // Out of line, so that the scan loops keep the disks they test in registers (see generate/paper_front.cpp).
  [[gnu::noinline, gnu::cold]] double depth_exact(const Probe& p, const Node& o) {
    ++stats_.exact_checks;
    return disks_closer_than_exact({p.x, p.y}, p.r, {o.x, o.y}, o.r, margin_) ? 0x1p-1000 : -1;
  }

  // Squared distance from (x, y) to wall wl.
  static double distance2(const Wall& wl, double x, double y) noexcept {
    const double u = (x - wl.ax) * wl.tx + (y - wl.ay) * wl.ty;
    double qx = wl.ax;
    double qy = wl.ay;
    if (u >= wl.len) {
      qx = wl.bx;
      qy = wl.by;
    } else if (u > 0) {
      qx += u * wl.tx;
      qy += u * wl.ty;
    }
    const double dx = x - qx;
    const double dy = y - qy;
    return dx * dx + dy * dy;
  }

  // The element the candidate overlaps most deeply (a disk or a wall; a reflex vertex is no
  // deeper than the walls that end there, up to rounding: setup_grid()), or kNone.
  // Its parents need no skipping: it touches them at the full clearance, outside the band (at
  // most 3/4 of the clearance) in which depth() and the wall test can see an overlap.
  // With Any, the first element found that the candidate overlaps: for callers that only need to
  // know whether there is one (most candidates that get this far overlap something, and the scan
  // ends there). With `quick`, the gap whose candidate this is, and no wall in the way, the disks
  // in_the_way() tries are asked first, and the first of them in the way is returned: for a gap
  // whose try fails on any disk (no move, which only a wall in the way would start).
  template <bool Any = false>
  std::int32_t deepest(const Probe& p, const Gap* quick = nullptr) {
    std::int32_t best = kNone;
    double best_depth = 0;
    const auto home_col = static_cast<std::size_t>(probe_col(p.x));
    const auto home_row = static_cast<std::size_t>(probe_row(p.y));
    const std::size_t block = block_of(home_row, home_col);
    const double reach = p.r + margin_;
    std::uint32_t first_wall = 0;
    std::uint32_t end_wall = 0;
    if ((walled_[block / 64] >> (block % 64) & 1) != 0) {
      std::tie(first_wall, end_wall) = cell_walls(home_row, home_col);
    }
    if (end_wall == first_wall) {
      // No walls within reach.
    } else if (end_wall - first_wall > kWallList) {
      // A finely divided boundary: the nearest wall, from the tree, is the deepest one.
      double d2 = reach * reach;
      const std::int32_t e = nearest_wall(p.x, p.y, d2);
      if (e != kNone) {
        if constexpr (Any) {
          return e;
        }
        best = e;
        best_depth = reach - std::sqrt(d2);
      }
    } else {
      for (std::uint32_t k = first_wall; k < end_wall; ++k) {
        const std::int32_t e = wall_ids_[k];
        const Wall& wl = walls_[wall_index(e)];
        const double d2 = distance2(wl, p.x, p.y);
        if (d2 < reach * reach) {
          if constexpr (Any) {
            return e;
          }
          const double dd = reach - std::sqrt(d2);
          if (best == kNone || dd > best_depth) {
            best = e;
            best_depth = dd;
          }
        }
      }
    }
    if (quick != nullptr && best == kNone) {
      if (const std::int32_t e = in_the_way(quick->a, quick->b, p, home_row * grid_.nx + home_col); e != kNone) {
        return e;
      }
    }
    const double r_reach = (p.r_hi + rmax_) * (1 + 1e-9);  // depth() can say yes up to r_hi + o.r
    const std::int64_t c0 = probe_col(p.x - r_reach);
    const std::int64_t c1 = probe_col(p.x + r_reach);
    const std::int64_t r0 = probe_row(p.y - r_reach);
    const std::int64_t r1 = probe_row(p.y + r_reach);
    visit_cells(head_cell_.data(), grid_.nx, nodes_.data(), kNone, c0, c1, r0, r1, [&](std::int32_t d, const Node& o) {
      const double dd = depth(p, o);
      // Of two disks in the way as deep, the older: exact ties are the rule in the band where
      // the exact predicate decides (depth_exact() says only whether), and the first in the
      // order of the scan would depend on the size of the grid's cells.
      if (dd > 0 && (Any || best == kNone || dd > best_depth || (dd == best_depth && d < best))) {
        best = d;
        best_depth = dd;
      }
      return Any && dd > 0;
    });
    return best;
  }

  // A disk in the way of the candidate for gap (x, y) among those most often there, or kNone: the
  // gap's neighbours on the front (the first element of the last gap with x second, the second of
  // the last with y first) and the disks of the candidate's own cell. Most tries fail (on the 1M
  // square, 64% of front gaps and 31% of voids), and 56% of the failures are settled here, for a
  // node or two and one cell head instead of a scan of some 18 cells and 8 disks (front 8-13%
  // faster, docs/performance.md).
  // Whatever is found is in the way, so the try fails exactly when the scan would have made it
  // fail; but it is not always the deepest element, and the void the gap leaves is bounded by
  // the pocket this one leaves (a bound all the same), so packings differ from the scan's.
  std::int32_t in_the_way(std::int32_t x, std::int32_t y, const Probe& p, std::size_t home) {
    const std::int32_t before = is_disk(x) ? before_[static_cast<std::size_t>(x)] : kNone;
    if (is_disk(before) && depth(p, nodes_[static_cast<std::size_t>(before)]) > 0) {
      return before;
    }
    const std::int32_t after = is_disk(y) ? nodes_[static_cast<std::size_t>(y)].after : kNone;
    if (is_disk(after) && depth(p, nodes_[static_cast<std::size_t>(after)]) > 0) {
      return after;
    }
    for (std::int32_t e = head_cell_[home]; e != kNone; e = nodes_[static_cast<std::size_t>(e)].cell_next) {
      if (depth(p, nodes_[static_cast<std::size_t>(e)]) > 0) {
        return e;
      }
    }
    return kNone;
  }

  // Whether the candidate really touches parent e where it should: its foot on a wall lies on the
  // edge, and it is not in the outside wedge of a reflex vertex (there it would be outside the
  // domain, touching the corner from without).
  [[nodiscard]] bool supported_by(std::int32_t e, double px, double py) const noexcept {
    if (is_wall(e)) {
      const Wall& wl = walls_[wall_index(e)];
      const double u = (px - wl.ax) * wl.tx + (py - wl.ay) * wl.ty;
      return u >= -clearance_ && u <= wl.len + clearance_;
    }
    if (is_corner(e)) {
      const Corner& c = corners_[static_cast<std::size_t>(e)];
      const Node& v = nodes_[static_cast<std::size_t>(e)];
      const double dx = px - v.x;
      const double dy = py - v.y;
      const bool right_of_in = c.ux1 * dy - c.uy1 * dx < 0;
      const bool right_of_out = c.ux2 * dy - c.uy2 * dx < 0;
      return !(right_of_in && right_of_out);
    }
    return true;
  }

  // ------------------------------------------------------------------------------------------
  // The void a failed gap leaves: the radius of the circle touching nodes a, b and d from
  // outside, on the left of a -> b (Apollonius' problem; a, b, d disks or reflex vertices), or -1
  // if there is none or it is not computed (a wall among them, centres collinear). A disk touching
  // a and b no larger than that clears d: it is the most the gap can take with d in the way.
  [[nodiscard]] double pocket(std::int32_t a, std::int32_t b, std::int32_t d) const noexcept {
    if (d == kNone) {
      return -1;
    }
    const int walls = (is_wall(a) ? 1 : 0) + (is_wall(b) ? 1 : 0) + (is_wall(d) ? 1 : 0);
    if (walls == 1) {
      return pocket_at_wall(a, b, d);
    }
    if (walls == 2) {
      return pocket_at_walls(a, b, d);
    }
    if (walls != 0) {
      return -1;
    }
    const Node& na = nodes_[static_cast<std::size_t>(a)];
    const Node& nb = nodes_[static_cast<std::size_t>(b)];
    const Node& nd = nodes_[static_cast<std::size_t>(d)];
    return pocket_of_nodes<double>(na.x, na.y, na.r, nb.x, nb.y, nb.r, nd.x, nd.y, nd.r);
  }

  // pocket(x, n, d) and pocket(n, y, d) for disks x, n, y and a node d that is no wall: the two
  // pockets a disk n placed in void (x, y) bounded by d leaves. In the lanes of a vector, in two
  // thirds of the instructions of two calls and with their two long chains of dependent
  // operations as one; the same bits (a lane that the vector leaves undecided, NaN, is computed
  // alone).
  [[nodiscard]] std::array<double, 2> pocket_pair(std::int32_t x, std::int32_t n, std::int32_t y,
                                                  std::int32_t d) const noexcept {
    const Node& a = nodes_[static_cast<std::size_t>(x)];
    const Node& m = nodes_[static_cast<std::size_t>(n)];
    const Node& b = nodes_[static_cast<std::size_t>(y)];
    const Node& o = nodes_[static_cast<std::size_t>(d)];
    const V2 rho = pocket_of_nodes<V2>(V2{a.x, m.x}, V2{a.y, m.y}, V2{a.r, m.r}, V2{m.x, b.x}, V2{m.y, b.y},
                                       V2{m.r, b.r}, lanes<V2>(o.x), lanes<V2>(o.y), lanes<V2>(o.r));
    std::array<double, 2> caps{rho[0], rho[1]};
    if (x == d) {
      caps[0] = -1;
    } else if (std::isnan(caps[0])) [[unlikely]] {
      caps[0] = pocket(x, n, d);
    }
    if (y == d) {
      caps[1] = -1;
    } else if (std::isnan(caps[1])) [[unlikely]] {
      caps[1] = pocket(n, y, d);
    }
    return caps;
  }

  // pocket() of three nodes (disks or reflex vertices) a, b, d, given by their centres and radii:
  // in a double (T = double), or two triples in the lanes of a V2. A lane whose system is
  // degenerate is -1 in a double and NaN in a V2, and one whose quadratic is linear (a lane
  // cannot branch) is NaN in a V2 too: both are rare, and pocket_pair() computes them alone.
  template <class T>
  [[nodiscard]] T pocket_of_nodes(T ax, T ay, T ra, T bx, T by, T rb, T dx, T dy, T rd) const noexcept {
    // Relative to a's centre: |p|^2 = (ra + rho)^2 and, subtracting, c_i . p = alpha_i + beta_i rho.
    // At the scale of rmax (scale_): the degeneracy test below compares fourth powers of lengths.
    const double k = scale_.k;
    bx = (bx - ax) * k;
    by = (by - ay) * k;
    dx = (dx - ax) * k;
    dy = (dy - ay) * k;
    ra = ra * k;
    rb = rb * k;
    rd = rd * k;
    const T alpha_b = (bx * bx + by * by - rb * rb + ra * ra) / 2.0;
    const T alpha_d = (dx * dx + dy * dy - rd * rd + ra * ra) / 2.0;
    const T beta_b = ra - rb;
    const T beta_d = ra - rd;
    const T det = bx * dy - by * dx;
    const T scale = (bx * bx + by * by) * (dx * dx + dy * dy);
    const auto regular = det * det > 1e-12 * scale;
    if constexpr (std::is_same_v<T, double>) {
      if (!regular) {
        return -1;
      }
    }
    const T inv = 1.0 / det;
    const T ux = (alpha_b * dy - alpha_d * by) * inv;
    const T uy = (bx * alpha_d - dx * alpha_b) * inv;
    const T vx = (beta_b * dy - beta_d * by) * inv;
    const T vy = (bx * beta_d - dx * beta_b) * inv;
    // On the left of a -> b: the pocket, not the circle on the far side.
    const T rho = smallest_root(ux, uy, vx, vy, ra, [&](T t) { return bx * (uy + t * vy) - by * (ux + t * vx) > 0.0; });
    const T scaled = select(rho < 0.0, rho, rho * scale_.inv_k);
    if constexpr (std::is_same_v<T, double>) {
      return scaled;
    } else {
      return select(regular, scaled, lanes<T>(std::numeric_limits<double>::quiet_NaN()));
    }
  }

  // pocket() with one wall among the three: the circle of radius rho at distance rho from the
  // wall's line (inside) touching the two nodes from outside; the smallest such rho.
  [[nodiscard]] double pocket_at_wall(std::int32_t a, std::int32_t b, std::int32_t d) const noexcept {
    std::int32_t w = a;
    std::int32_t i = b;
    std::int32_t j = d;
    if (is_wall(b)) {
      w = b;
      i = a;
    } else if (is_wall(d)) {
      w = d;
      i = a;
      j = b;
    }
    const Wall& wl = walls_[wall_index(w)];
    if (ends(wl, j)) {
      std::swap(i, j);
    }
    if (ends(wl, i)) {
      // A reflex vertex at the wall's end (a gap at the corner, or the corner in its way): a
      // circle touching the wall's line and passing through a point on it touches it there.
      // Its centre is i + rho n, and it touches j from outside: |i + rho n - j| = rj + rho. (The
      // general solution below meets this as a double root, which rounding turns into none.)
      if (ends(wl, j)) {
        return -1;
      }
      const Node& ni = nodes_[static_cast<std::size_t>(i)];
      const Node& nj = nodes_[static_cast<std::size_t>(j)];
      const double cx = nj.x - ni.x;
      const double cy = nj.y - ni.y;
      const double den = 2 * (wl.nx * cx + wl.ny * cy + nj.r);
      const double rho = (cx * cx + cy * cy - nj.r * nj.r) / den;
      return rho > 0 && std::isfinite(rho) ? rho : -1;
    }
    const Node& ni = nodes_[static_cast<std::size_t>(i)];
    const Node& nj = nodes_[static_cast<std::size_t>(j)];
    // Relative to i's centre: |p|^2 = (ri + rho)^2; c . p = alpha + beta rho (c = cj - ci);
    // n . p = (w - n . ci) + rho.
    const double cx = nj.x - ni.x;
    const double cy = nj.y - ni.y;
    const double ri = ni.r;
    const double alpha = (cx * cx + cy * cy - nj.r * nj.r + ri * ri) / 2;
    const double beta = ri - nj.r;
    const double off = wl.w - (wl.nx * ni.x + wl.ny * ni.y);
    const double det = cx * wl.ny - cy * wl.nx;
    if (!(det * det > 1e-12 * (cx * cx + cy * cy))) {
      return -1;
    }
    const double inv = 1 / det;
    const double ux = (alpha * wl.ny - off * cy) * inv;
    const double uy = (cx * off - wl.nx * alpha) * inv;
    const double vx = (beta * wl.ny - cy) * inv;
    const double vy = (cx - wl.nx * beta) * inv;
    return smallest_root(ux, uy, vx, vy, ri, [](double) { return true; });
  }

  // Whether node e is a reflex vertex at an end of wall wl (node coordinates and wall ends come
  // from the same ring points, so equality is exact).
  [[nodiscard]] bool ends(const Wall& wl, std::int32_t e) const noexcept {
    if (!is_corner(e)) {
      return false;
    }
    const Node& v = nodes_[static_cast<std::size_t>(e)];
    return (v.x == wl.ax && v.y == wl.ay) || (v.x == wl.bx && v.y == wl.by);
  }

  // pocket() with two walls among the three (a crevice of a rough boundary, or a corner with a disk
  // in the way): the circle of radius rho at distance rho from both walls' lines (inside) touching
  // the node from outside; the smallest such rho. Its centre moves along a line as rho grows. The
  // walls are segments: where the circle's foot on a wall's line falls off the segment, a vertex
  // and not the line bounds the pocket, and none is computed (-1).
  [[nodiscard]] double pocket_at_walls(std::int32_t a, std::int32_t b, std::int32_t d) const noexcept {
    std::int32_t w1 = a;
    std::int32_t w2 = b;
    std::int32_t i = d;
    if (!is_wall(a)) {
      w1 = d;
      i = a;
    } else if (!is_wall(b)) {
      w2 = d;
      i = b;
    }
    const Wall& p = walls_[wall_index(w1)];
    const Wall& q = walls_[wall_index(w2)];
    const Node& ni = nodes_[static_cast<std::size_t>(i)];
    // n1 . c = w1 + rho, n2 . c = w2 + rho: c = X + rho V.
    const double det = p.nx * q.ny - p.ny * q.nx;
    if (!(std::abs(det) > 1e-9)) {
      return -1;  // parallel
    }
    const double xx = (p.w * q.ny - q.w * p.ny) / det;
    const double xy = (p.nx * q.w - q.nx * p.w) / det;
    const double vx = (q.ny - p.ny) / det;
    const double vy = (p.nx - q.nx) / det;
    // A node covering the lines' crossing is met by the growing circle only on its way out: the
    // root would be the least radius clear of it, not the most.
    const double ux = xx - ni.x;
    const double uy = xy - ni.y;
    if (!(ux * ux + uy * uy > ni.r * ni.r)) {
      return -1;
    }
    const double rho = smallest_root(ux, uy, vx, vy, ni.r, [](double) { return true; });
    if (rho < 0) {
      return -1;
    }
    const double cx = xx + rho * vx;
    const double cy = xy + rho * vy;
    for (const Wall* wl : {&p, &q}) {
      const double u = (cx - wl->ax) * wl->tx + (cy - wl->ay) * wl->ty;
      if (!(u >= 0 && u <= wl->len)) {
        return -1;
      }
    }
    return rho;
  }

  // The smallest rho > 0 with |u + rho v| = ri + rho that `accept` takes, or -1; lane by lane in
  // a V2 (pocket_of_nodes()), where a lane whose quadratic is linear is NaN.
  template <class T, class Accept>
  static T smallest_root(T ux, T uy, T vx, T vy, T ri, Accept accept) noexcept {
    const T qa = vx * vx + vy * vy - 1.0;
    const T qb = 2.0 * (ux * vx + uy * vy - ri);
    const T qc = ux * ux + uy * uy - ri * ri;
    constexpr double inf = std::numeric_limits<double>::infinity();
    // Whether rho is a root to take (positive, finite, accepted), without branches.
    auto ok = [&](T rho) { return (rho > 0.0) & (rho < inf) & accept(rho); };
    if constexpr (std::is_same_v<T, double>) {
      if (qa == 0) {
        const double rho = -qc / qb;
        return ok(rho) ? rho : -1;
      }
    }
    // A negative discriminant (no root) gives NaN roots, which ok() refuses.
    const T sq = square_root(qb * qb - 4.0 * qa * qc);
    const T half = 0.5 / qa;
    const T hi = (-qb + sq) * half;
    const T lo = (-qb - sq) * half;
    const auto ok_hi = ok(hi);
    const auto ok_lo = ok(lo);
    const T best = select(ok_hi, hi, lanes<T>(-1));
    const T root = select(ok_lo & (lnot(ok_hi) | (lo < hi)), lo, best);
    if constexpr (std::is_same_v<T, double>) {
      return root;
    } else {
      return select(qa == 0.0, lanes<T>(std::numeric_limits<double>::quiet_NaN()), root);
    }
  }

  // Keeps gap g as a void for radii below class k, and below the pocket left by `blocker`.
  void push_void(Gap g, int k, std::int32_t blocker) {
    keep_void(g, k, blocker, blocker != kNone ? pocket(g.a, g.b, blocker) : -1);
  }
  // push_void() with the pocket `cap` already computed (-1: none).
  void keep_void(Gap g, int k, std::int32_t blocker, double cap) {
    if (cap >= 0) {
      k = cap < rmin_ ? 0 : std::min(k, class_of(cap));
    }
    if (k > 0) {
      g.bound = blocker;
      // Voids on a rough wall are kept apart and tried first.
      const std::size_t side =
          (is_wall(g.a) && rough_[wall_index(g.a)] != 0) || (is_wall(g.b) && rough_[wall_index(g.b)] != 0) ? 1 : 0;
      voids_[side][static_cast<std::size_t>(k)].push_back(g);
      mask_[side][static_cast<std::size_t>(k) / 64] |= std::uint64_t{1} << (static_cast<unsigned>(k) % 64);
    }
  }

  // The lowest class above cls with a void on side s (1: rough walls), or -1.
  [[nodiscard]] int first_void_above(std::size_t s, int cls) const noexcept {
    for (auto w = static_cast<std::size_t>(cls + 1) / 64; w < kMaskWords; ++w) {
      std::uint64_t bits = mask_[s][w];
      if (w == static_cast<std::size_t>(cls + 1) / 64) {
        bits &= ~std::uint64_t{0} << (static_cast<unsigned>(cls + 1) % 64);
      }
      if (bits != 0) {
        return static_cast<int>(64 * w) + std::countr_zero(bits);
      }
    }
    return -1;
  }

  // ------------------------------------------------------------------------------------------
  // Seeds: two touching disks (r and a second drawn radius) at a point inside the polygon where
  // they fit, with the gaps on both sides of the pair. Tried only while the disks cover less than
  // half of what a dense packing would, at most kSeeds times, each at up to kSeedTries points
  // drawn in the polygon's box. Returns whether the pair was placed.
  static constexpr int kSeeds = 16;
  static constexpr int kSeedTries = 256;

  bool seed(double r) {
    if (seeds_ >= kSeeds || std::numbers::pi * area_ >= 0.5 * kRandomDenseFraction * polygon_area_) {
      return false;
    }
    ++seeds_;
    const double r2 = draw();
    for (int t = 0; t < kSeedTries; ++t) {
      const double sx = width_ * rng_.uniform();
      const double sy = height_ * rng_.uniform();
      const double tx = sx + r + r2 + clearance_;
      if (!inside_polygon(sx, sy) || !fits(sx, sy, r) || !fits(tx, sy, r2)) {
        continue;
      }
      // The pair apart by the clearance, as tangent disks are (this cannot fail; checked before
      // the first disk is placed, so that nothing is left behind if it did).
      if (depth(probe(tx, sy, r2), Node{sx, sy, r, kNone, 0}) > 0) {
        continue;
      }
      const std::int32_t a = add_node(sx, sy, r);
      const std::int32_t b = add_node(tx, sy, r2);
      area_ += r2 * r2;
      push_gap(Gap{a, b});
      push_gap(Gap{b, a});
      return true;
    }
    return false;
  }

  // Whether a disk at (x, y) of radius r crosses no wall and overlaps no disk (with its centre
  // inside the polygon, it then lies inside).
  bool fits(double x, double y, double r) {
    if (!(x - r >= 0 && x + r <= width_ && y - r >= 0 && y + r <= height_)) {
      return false;
    }
    return deepest<true>(probe(x, y, r)) == kNone;
  }

  // Crossing number (floating point: the points asked about are seed centres and candidates that
  // touch only walls, at least their radius from every wall).
  [[nodiscard]] bool inside_polygon(double x, double y) const noexcept {
    // The walls whose boxes meet the ray from (x, y) to the right, from the wall tree.
    bool in = false;
    std::array<std::size_t, 128> stack;  // NOLINT(cppcoreguidelines-pro-type-member-init): see nearest_wall()
    std::size_t top = 0;
    stack[top++] = 1;
    while (top > 0) {
      const std::size_t k = stack[--top];
      const Bounds& b = tree_[k];
      if (!(b.ymin <= y && y <= b.ymax && x <= b.xmax)) {
        continue;
      }
      if (k < leaves_) {
        stack[top++] = 2 * k;
        stack[top++] = 2 * k + 1;
        continue;
      }
      const std::size_t first = (k - leaves_) * kLeafWalls;
      const std::size_t last = std::min(first + kLeafWalls, walls_.size());
      for (std::size_t e = first; e < last; ++e) {
        const Wall& w = walls_[e];
        if ((w.ay > y) != (w.by > y)) {
          const double xc = w.ax + (y - w.ay) * (w.bx - w.ax) / (w.by - w.ay);
          in = in != (x < xc);
        }
      }
    }
    return in;
  }

  // ------------------------------------------------------------------------------------------
  // Placing a disk of radius r in gap g.

  // The ring wall e belongs to.
  [[nodiscard]] std::size_t ring_of(std::int32_t e) const noexcept {
    const std::size_t i = wall_index(e);
    return static_cast<std::size_t>(std::upper_bound(ring_first_.begin(), ring_first_.end(), i) - ring_first_.begin()) -
           1;
  }

  // A candidate touching a wall and a node whose foot on the wall lies beyond the edge: along a
  // gently turning boundary (a curve divided into many short edges) it touches the next wall
  // instead. It is recomputed against the wall nearest to it, if that wall is on the same ring
  // and turned by less than kSlideTurn from the first, a few times over; otherwise it is left as
  // it is, for supported_by() to refuse.
  void slide(std::int32_t& x, std::int32_t& y, double r, double& px, double& py) {
    for (int k = 0; k < 4; ++k) {
      if (is_wall(x) == is_wall(y)) {
        return;
      }
      const bool wall_first = is_wall(x);
      const std::int32_t w = wall_first ? x : y;
      if (supported_by(w, px, py)) {
        return;
      }
      double d2 = distance2(walls_[wall_index(w)], px, py);
      const std::int32_t e = nearest_wall(px, py, d2, w);
      if (e == kNone || e == w || ring_of(e) != ring_of(w)) {
        return;
      }
      const Wall& a = walls_[wall_index(w)];
      const Wall& b = walls_[wall_index(e)];
      if (a.tx * b.tx + a.ty * b.ty < kCosSlideTurn) {
        return;
      }
      double qx = 0;
      double qy = 0;
      if (!(wall_first ? tangent(e, y, r, qx, qy) : tangent(x, e, r, qx, qy))) {
        return;
      }
      (wall_first ? x : y) = e;
      px = qx;
      py = qy;
    }
  }

  // Whether the pocket behind parents x and y (disks or reflex vertices) that a move (cases
  // (b)-(d)) brought together is worth keeping as a void. Behind them lies the element the move
  // replaced; their pocket rarely takes a disk, and beyond 4 rmin almost never: on the 3 x 3
  // square such voids were tried 178k times for 3k disks (1 in 67k beyond 8 rmin).
  [[nodiscard]] bool worth_a_void(std::int32_t x, std::int32_t y) const noexcept {
    const Node& a = nodes_[static_cast<std::size_t>(x)];
    const Node& b = nodes_[static_cast<std::size_t>(y)];
    const double dx = a.x - b.x;
    const double dy = a.y - b.y;
    const double reach = a.r + b.r + 4 * rmin_;
    return dx * dx + dy * dy < reach * reach;
  }

  bool try_gap(const Gap& g, double r, bool in_void) {
    std::int32_t x = g.a;
    std::int32_t y = g.b;
    double px = 0;
    double py = 0;
    ++stats_.attempts;
    blocker_ = kNone;
    hopeless_ = false;
    if (!tangent(x, y, r, px, py)) {
      // No disk this small touches both (too far apart, or one holds the other, or parallel
      // walls): no smaller one does either. The gap is not kept as a void for smaller radii,
      // where it would fail the same way every time until the lowest class dropped it.
      hopeless_ = true;
      return false;
    }
    const bool walled = on_wall(x) || on_wall(y);
    std::int32_t replaced = kNone;  // the parent the last move replaced
    int moves = walled ? (in_void ? kVoidMoves : kWallMoves) : kMoves;
    for (int move = 0; move <= moves; ++move) {
      slide(x, y, r, px, py);
      if (!(px - r >= box_.xmin && px + r <= box_.xmax && py - r >= box_.ymin && py + r <= box_.ymax)) {
        return false;  // outside the polygon's box, so outside the polygon
      }
      const Probe p = probe(px, py, r);
      // At the last move, only whether anything is in the way matters (but not at the first: the
      // element it finds bounds the void the gap leaves, the deepest one if the grid is scanned).
      // In the interior, the disks most often in the way are tried before the scan (in_the_way()).
      const Gap first{x, y};
      const std::int32_t d =
          move == moves && move > 0 ? deepest<true>(p) : deepest(p, move == 0 && !walled ? &first : nullptr);
      if (d == kNone) {
        if (!supported_by(x, px, py) || !supported_by(y, px, py)) {
          return false;
        }
        // Touching a disk, a candidate that crosses no wall is inside: the two disks cover the
        // segment between their centres. Touching only walls and reflex vertices, it can lie
        // wholly outside where the domain is thinner than the clearance (a spike two edges a few
        // ulps apart): its centre must then be inside.
        if (!is_disk(x) && !is_disk(y) && !inside_polygon(px, py)) {
          return false;
        }
        const std::int32_t n = add_node(px, py, r);
        if (in_void && !walled && replaced == kNone && g.bound != kNone) {
          // A disk in a void leaves two smaller pockets, between it, a parent and the element
          // that bounded the void: kept as voids, not queued on the front, if that element
          // still bounds them below rmax. (Queued, 335k of them were tried on the 3 x 3 square
          // a layer later, when their neighbourhood had left the cache, and 10% took a disk.)
          // Not after a move: the new parent can be a wall cut in, and pocket_at_wall() does
          // not tell its sides apart.
          // Both pockets first, in one computation (pocket_pair()).
          const std::array<Gap, 2> split{Gap{x, n}, Gap{n, y}};
          const std::array<double, 2> caps = is_wall(g.bound)
                                                 ? std::array<double, 2>{pocket(x, n, g.bound), pocket(n, y, g.bound)}
                                                 : pocket_pair(x, n, y, g.bound);
          for (std::size_t i = 0; i < 2; ++i) {
            if (caps[i] >= 0 && caps[i] < rmax_) {
              link(split[i]);
              keep_void(split[i], kClasses - 1, g.bound, caps[i]);
            } else {
              push_gap(split[i]);
            }
          }
        } else {
          push_gap(Gap{x, n});
          push_gap(Gap{n, y});
        }
        if (req_.fill_voids && replaced != kNone && !is_wall(x) && !is_wall(y) && worth_a_void(x, y)) {
          // The pocket on the far side of a pair from a move (cases (b)-(d)), bounded by the
          // parent the last move replaced, which lies there (bounded by n, 29k first tries of
          // these voids on the 3 x 3 square placed nothing, 95% of them blocked by that parent).
          // (The pocket behind a pair that made a gap is not kept: bounded by the element behind
          // their gap, 266k of them on the 3 x 3 square were tried 9.6k times, and the densities
          // stayed the same without them.)
          push_void(Gap{y, x}, kClasses - 1, replaced);
        }
        if (req_.fill_voids) {
          // The cusp between the new disk, a wall parent and the other parent.
          if (is_wall(x) && !is_wall(y)) {
            push_void(Gap{n, x}, kClasses - 1, y);
          } else if (is_wall(y) && !is_wall(x)) {
            push_void(Gap{y, n}, kClasses - 1, x);
          }
        }
        stats_.void_fills += in_void ? 1U : 0U;
        return true;
      }
      if (move == 0) {
        blocker_ = d;
      }
      if (move == 0 && !walled && on_wall(d)) {
        moves = kWallCut;  // the boundary in the way: move to touch it
      }
      if (move == moves || d == x || d == y) {
        return false;
      }
      // Cases (b)-(d) by geometry: touch d and one of the parents instead, whichever of the
      // two positions is nearer the first.
      ++stats_.cuts;
      double ax = 0;
      double ay = 0;
      double bx = 0;
      double by = 0;
      const bool ok_a = tangent(x, d, r, ax, ay);
      const bool ok_b = tangent(d, y, r, bx, by);
      ++stats_.attempts;
      if (!ok_a && !ok_b) {
        return false;
      }
      const double da = ok_a ? (ax - px) * (ax - px) + (ay - py) * (ay - py) : INFINITY;
      const double db = ok_b ? (bx - px) * (bx - px) + (by - py) * (by - py) : INFINITY;
      if (da <= db) {
        replaced = y;
        y = d;
        px = ax;
        py = ay;
      } else {
        replaced = x;
        x = d;
        px = bx;
        py = by;
      }
    }
    return false;
  }

  const BoundaryRequest& req_;
  Rng& rng_;
  std::vector<Disk>& out_;
  FillStats& stats_;
  RunControl control_;
  std::size_t out_before_;  // out_.size() until the run moves the nodes out (placed())
  WorkScale unit_;
  Point origin_;
  double width_ = 0, height_ = 0;
  double rmin_ = 0, rmax_ = 0, clearance_ = 0, margin_ = 0, band_ = 0;
  LengthScale scale_;  // for tangent_to_two
  RadiusClasses<kClasses> classes_;
  Box box_;              // the polygon's box (local coordinates) grown by the clearance
  double estimate_ = 0;  // of the disks the box takes (estimate_disks())
  std::size_t fixed_bytes_ = 0;  // the grid's and the wall lists', for the memory limit
  double area_ = 0;
  double polygon_area_ = 0;  // shoelace, for the seeding rule
  int seeds_ = 0;
  std::int32_t blocker_ = kNone;  // an element in the way at a failed gap's first position
  bool hopeless_ = false;         // the failed gap takes no disk of the radius tried or smaller

  std::vector<Wall> walls_;
  std::vector<Corner> corners_;    // node i < corners_.size() is reflex vertex i (radius 0)
  std::int32_t corner_count_ = 0;  // corners_.size()
  std::vector<Point> corner_at_;
  HugeVector<Node> nodes_;
  HugeVector<std::int32_t> before_;  // per disk: the first element of the last front gap with it second

  std::vector<Gap> fifo_;
  std::vector<Gap> wall_fifo_;  // gaps on a wall or a reflex vertex (grows with the perimeter only)
  std::size_t wall_head_ = 0;
  std::size_t head_ = 0;
  std::array<std::array<std::vector<Gap>, kClasses>, 2> voids_;  // [1]: on a rough wall; [.][k]: class k
  std::array<std::array<std::uint64_t, kMaskWords>, 2> mask_{};  // bit k of mask_[s]: voids_[s][k] not empty

  CellGrid grid_;
  bool probes_inside_ = false;  // probe_col(), probe_row(): no clamping needed
  HugeVector<std::int32_t> head_cell_;
  std::vector<std::uint32_t> block_first_;  // per block of cells: its first entry in cell_walls_
  std::vector<std::uint32_t> cell_walls_;   // per cell of a walled block: its first wall in wall_ids_
  std::vector<std::int32_t> wall_ids_;
  std::vector<std::uint64_t> walled_;  // a bit per block of cells: any walls (setup_grid())
  std::size_t blocks_x_ = 1;
  std::vector<Bounds> tree_;             // the wall tree (build_wall_tree)
  std::vector<std::size_t> ring_first_;  // the first wall of each ring
  std::vector<std::uint8_t> rough_;
  bool any_rough_ = false;  // a rough wall exists (else no void is kept on side 1)
  std::size_t leaves_ = 1;
};

}  // namespace

FrontResult advance_boundary(const BoundaryRequest& req, Rng& rng, std::vector<Disk>& out, FillStats& stats) {
  BoundaryFront front(req, rng, out, stats);
  return front.run();
}

}  // namespace frontpack::detail
