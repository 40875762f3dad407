// The global overlap pass: tiles of about 2^17 disks, each searched by
// CGAL::box_self_intersection_d with guests from half of its neighbours, and an exact pair test.
#include "certify/overlap_pass.hpp"

#include <CGAL/Bbox_2.h>
#include <CGAL/box_intersection_d.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "certify/cull.hpp"
#include "common/float_bits.hpp"
#include "common/stop.hpp"
#include "exact/predicates.hpp"

namespace frontpack::detail {

namespace {

// Runs CGAL::box_self_intersection_d over the disks listed in `batch` (the first `own` are one
// tile's, the rest guests from its neighbours), with boxes of number type NT (float halves the
// memory and speeds the sweep; used when every coordinate fits a float), each rounded outwards so
// that the exact box [x - r, x + r] x [y - r, y + r] lies inside it. A box's handle points at its
// disk's copy in `local` (a buffer reused from tile to tile), in batch order: its position there
// gives the disk's index (through `batch`) and whether it is a guest.
//
// Far from the origin a float cannot tell nearby disks apart (at 8e9 its step is 1024): float boxes
// are taken relative to `origin` (the smallest centre coordinates), widened by a bound on the
// rounding of the two subtractions, so that they stay tight there too.
template <class NT>
void box_pass(std::span<const Disk> disks, const std::vector<std::uint32_t>& batch, std::size_t own,
              std::vector<std::pair<std::size_t, std::size_t>>& out, std::size_t& candidates, Point origin,
              std::vector<Disk>& local) {
  using Box = CGAL::Box_intersection_d::Box_with_handle_d<NT, 2, const Disk*, CGAL::Box_intersection_d::ID_FROM_HANDLE>;
  constexpr NT inf = std::numeric_limits<NT>::infinity();
  // One step below the rounded difference is below the exact one; converting to float rounds to
  // nearest, so one more float step down keeps it below.
  const auto down = [](double v) { return std::nextafter(static_cast<NT>(next_down(v)), -inf); };
  const auto up = [](double v) { return std::nextafter(static_cast<NT>(next_up(v)), inf); };
  // The batch's disks copied out in batch order: the sweep reports pairs in no order, and the
  // pair test then reads this tile's copies instead of disks anywhere in the packing (a packing
  // whose disks were placed in voids all over the domain, the boundary method's, is in no
  // spatial order).
  local.clear();
  for (const std::uint32_t i : batch) {
    local.push_back(disks[i]);
  }
  std::vector<Box> boxes;
  boxes.reserve(batch.size());
  // (c - r) - o rounds twice, each time by at most 2^-53 of a magnitude below |c| + r + |o|.
  const auto err = [](double c, double r, double o) { return 0x1p-51 * (std::abs(c) + r + std::abs(o)); };
  for (const Disk& d : local) {
    const double x = d.centre.x;
    const double y = d.centre.y;
    const double r = d.radius;
    NT lo[2] = {down(((x - r) - origin.x) - err(x, r, origin.x)), down(((y - r) - origin.y) - err(y, r, origin.y))};
    NT hi[2] = {up(((x + r) - origin.x) + err(x, r, origin.x)), up(((y + r) - origin.y) + err(y, r, origin.y))};
    boxes.emplace_back(lo, hi, &d);
  }
  const Disk* guests = local.data() + own;
  // A cutoff of 4000 measured fastest for this use (docs/design-notes.md).
  CGAL::box_self_intersection_d(
      boxes.begin(), boxes.end(),
      [&](const Box& a, const Box& b) {
        if (a.handle() >= guests && b.handle() >= guests) {
          return;  // both guests: their own tile's pass decides them
        }
        ++candidates;
        const Disk& p = *a.handle();
        const Disk& q = *b.handle();
        if (compare_centre_distance(p.centre, q.centre, p.radius, q.radius) == CGAL::SMALLER) {
          const std::size_t i = batch[static_cast<std::size_t>(&p - local.data())];
          const std::size_t j = batch[static_cast<std::size_t>(&q - local.data())];
          out.emplace_back(std::min(i, j), std::max(i, j));
        }
      },
      std::ptrdiff_t{4000});
}

bool takes_part(const Disk& d) {
  return std::isfinite(d.centre.x) && std::isfinite(d.centre.y) && std::isfinite(d.radius) && d.radius >= 0;
}

// Square-ish tiles at least 2 rmax wide and high (rmax: the largest radius), so that overlapping
// disks have their centres in the same or neighbouring tiles, each holding about kChunk disks:
// linear time overall, and box memory for one tile at a time. (Thin strips instead of tiles
// measured slower: CGAL's sweep prefers square batches. With the batch's disks copied out, 2^17
// measured as fast as 2^18 without its 7 bytes per disk more peak memory at 1M disks, and 2^16,
// 2^15 and 2^13 slower; docs/performance.md.) The disks that take part are listed by tile,
// counting sort, stable: generation order within a tile.
class Tiles {
 public:
  static constexpr std::size_t kChunk = std::size_t{1} << 17;

  explicit Tiles(std::span<const Disk> disks) {
    for (const Disk& d : disks) {
      if (!takes_part(d)) {
        continue;
      }
      ++live_;
      all_.extend(d.centre);
      rmax_ = std::max(rmax_, d.radius);
      fits_float_ = fits_float_ && std::abs(d.centre.x) + d.radius < 1e30 && std::abs(d.centre.y) + d.radius < 1e30;
    }
    if (live_ == 0) {
      return;
    }
    choose_side();
    sort_by_tile(disks);
  }

  [[nodiscard]] bool empty() const noexcept { return live_ == 0; }
  [[nodiscard]] std::size_t columns() const noexcept { return tx_; }
  [[nodiscard]] std::size_t rows() const noexcept { return ty_; }
  /// Whether every box fits a float (then the box pass runs in floats, relative to origin()).
  [[nodiscard]] bool fits_float() const noexcept { return fits_float_; }
  [[nodiscard]] Point origin() const noexcept { return Point{all_.xmin, all_.ymin}; }
  /// The disks of tile (i, j), by index; empty for a tile outside the tiling.
  [[nodiscard]] std::span<const std::uint32_t> disks_of(std::ptrdiff_t i, std::ptrdiff_t j) const noexcept {
    if (i < 0 || j < 0 || i >= static_cast<std::ptrdiff_t>(tx_) || j >= static_cast<std::ptrdiff_t>(ty_)) {
      return {};
    }
    const std::size_t t = static_cast<std::size_t>(j) * tx_ + static_cast<std::size_t>(i);
    return std::span<const std::uint32_t>(order_).subspan(start_[t], start_[t + 1] - start_[t]);
  }

 private:
  void choose_side() {
    const double wanted = std::max(1.0, static_cast<double>(live_) / kChunk);
    const double W = all_.width();
    const double H = all_.height();
    const double min_side = 2.0 * rmax_ * (1 + 1e-9);
    side_ = std::sqrt(W * H / wanted);
    if (!(side_ > min_side) || !std::isfinite(side_)) {
      side_ = std::max(min_side, std::max(W, H) / wanted);
    }
    if (!(side_ > 0)) {
      side_ = 1;  // all centres coincide and every radius is 0
    }
    // (An infinite side, for radii beyond about 9e307, is one tile: side = 1 made it 10^12 of them.)
    const auto tiles_along = [this](double extent) {
      return static_cast<std::size_t>(std::min(1e6, std::floor(extent / side_))) + 1;
    };
    tx_ = tiles_along(W);
    ty_ = tiles_along(H);
  }

  [[nodiscard]] std::size_t tile_of(const Disk& d) const noexcept {
    const auto i = std::min(tx_ - 1, static_cast<std::size_t>(std::max(0.0, (d.centre.x - all_.xmin) / side_)));
    const auto j = std::min(ty_ - 1, static_cast<std::size_t>(std::max(0.0, (d.centre.y - all_.ymin) / side_)));
    return j * tx_ + i;
  }

  void sort_by_tile(std::span<const Disk> disks) {
    start_.assign(tx_ * ty_ + 1, 0);
    for (const Disk& d : disks) {
      if (takes_part(d)) {
        ++start_[tile_of(d) + 1];
      }
    }
    for (std::size_t t = 0; t < tx_ * ty_; ++t) {
      start_[t + 1] += start_[t];
    }
    order_.resize(live_);
    std::vector<std::uint32_t> fill(start_.begin(), start_.end() - 1);
    for (std::size_t i = 0; i < disks.size(); ++i) {
      if (takes_part(disks[i])) {
        order_[fill[tile_of(disks[i])]++] = static_cast<std::uint32_t>(i);
      }
    }
  }

  Box all_;  // of the centres
  double rmax_ = 0;
  bool fits_float_ = true;
  std::size_t live_ = 0;
  double side_ = 1;
  std::size_t tx_ = 0;
  std::size_t ty_ = 0;
  std::vector<std::uint32_t> start_;
  std::vector<std::uint32_t> order_;
};

// Appends to `batch` (which holds tile (i, j)'s own disks) the guests of that tile: the disks of
// its neighbours right, upper left, up and upper right whose boxes meet the box of the own disks'
// boxes, so that every pair of neighbouring tiles is searched once.
void add_guests(std::span<const Disk> disks, const Tiles& tiles, std::size_t i, std::size_t j,
                std::vector<std::uint32_t>& batch) {
  Box extent;  // of the own disks' boxes
  for (const std::uint32_t k : batch) {
    const Disk& d = disks[k];
    extent.extend(Point{d.centre.x - d.radius, d.centre.y - d.radius});
    extent.extend(Point{d.centre.x + d.radius, d.centre.y + d.radius});
  }
  const double slack =
      0x1p-50 * (std::abs(extent.xmin) + std::abs(extent.xmax) + std::abs(extent.ymin) + std::abs(extent.ymax));
  constexpr std::ptrdiff_t kGuestTiles[4][2] = {{1, 0}, {-1, 1}, {0, 1}, {1, 1}};
  for (const auto& offset : kGuestTiles) {
    for (const std::uint32_t k :
         tiles.disks_of(static_cast<std::ptrdiff_t>(i) + offset[0], static_cast<std::ptrdiff_t>(j) + offset[1])) {
      const Disk& d = disks[k];
      if (d.centre.x - d.radius <= extent.xmax + slack && d.centre.x + d.radius >= extent.xmin - slack &&
          d.centre.y - d.radius <= extent.ymax + slack && d.centre.y + d.radius >= extent.ymin - slack) {
        batch.push_back(k);
      }
    }
  }
}

}  // namespace

void overlapping_pairs(std::span<const Disk> disks, std::vector<std::pair<std::size_t, std::size_t>>& out,
                       std::size_t& candidates, const std::stop_token& stop) {
  out.clear();
  candidates = 0;
  const Tiles tiles(disks);
  if (tiles.empty()) {
    return;
  }
  std::vector<std::uint32_t> batch;
  std::vector<Disk> local;
  for (std::size_t j = 0; j < tiles.rows(); ++j) {
    for (std::size_t i = 0; i < tiles.columns(); ++i) {
      const std::span<const std::uint32_t> own =
          tiles.disks_of(static_cast<std::ptrdiff_t>(i), static_cast<std::ptrdiff_t>(j));
      if (own.empty()) {
        continue;
      }
      throw_if_stopped(stop);
      batch.assign(own.begin(), own.end());
      add_guests(disks, tiles, i, j, batch);
      if (tiles.fits_float()) {
        box_pass<float>(disks, batch, own.size(), out, candidates, tiles.origin(), local);
      } else {
        box_pass<double>(disks, batch, own.size(), out, candidates, Point{0, 0}, local);
      }
    }
  }
  std::sort(out.begin(), out.end());
}

std::size_t drop_one_of_each_pair(std::vector<Disk>& disks,
                                  std::span<const std::pair<std::size_t, std::size_t>> pairs) {
  if (pairs.empty()) {
    return 0;
  }
  std::size_t dropped = 0;
  std::vector<std::uint8_t> drop(disks.size(), 0);
  for (const auto& [i, j] : pairs) {
    if (drop[i] == 0 && drop[j] == 0) {
      drop[j] = 1;
      ++dropped;
    }
  }
  keep_where(disks, drop, 0);
  return dropped;
}

}  // namespace frontpack::detail
