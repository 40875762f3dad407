#include "generate/boundary/wall_index.hpp"

#include <bit>
#include <limits>
#include <numeric>

#include "generate/run_control.hpp"

namespace frontpack::detail {

void SetupBudget::check(std::size_t bytes, const std::string& what) const {
  if (limit != 0 && bytes >= limit) {
    throw_memory_limit(limit, what + " (" + std::to_string(bytes) + " bytes)", count_of(estimate, 1e18));
  }
}

struct WallIndex::Pair {
  // The cell's block, then its place in the block (the lists' order): below
  // (nx + kBlock - 1) (ny + kBlock - 1), which CellGrid's cap of about 16M cells keeps far
  // below 2^32.
  std::uint32_t key;
  std::uint32_t wall;
};

std::size_t WallIndex::block_bytes(const CellGrid& grid) noexcept {
  const std::size_t blocks = ((grid.nx + kBlock - 1) / kBlock) * ((grid.ny + kBlock - 1) / kBlock);
  return blocks * (sizeof(std::size_t) + sizeof(std::uint32_t));
}

void WallIndex::build(const std::vector<Wall>& walls, const CellGrid& grid, double reach, std::size_t need,
                      const SetupBudget& budget) {
  walls_ = &walls;
  blocks_x_ = (grid.nx + kBlock - 1) / kBlock;  // for block_of()
  const std::size_t blocks = blocks_x_ * ((grid.ny + kBlock - 1) / kBlock);
  std::vector<Pair> pairs = list_pairs(grid, reach, need, budget);
  group(pairs, blocks, need, budget);
  build_tree();
}

void WallIndex::release() noexcept {
  detail::release(block_first_);
  detail::release(cell_walls_);
  detail::release(wall_ids_);
  detail::release(walled_);
}

// Walls per cell: those meeting the cell grown by rmax + the clearance, kept for the cells of
// walled blocks only (below). Found as (cell, wall) pairs, row by row along each wall: in a
// row, only the columns that the wall's stretch in the row's band can reach are tested, so
// that the work follows the walls' length and not the area of their boxes (a diagonal wall's
// box is a quarter of the grid: testing every cell of it took 49 ms, 14% of the front, on a
// 1M-disk diamond), and nothing is kept per cell of the grid.
std::vector<WallIndex::Pair> WallIndex::list_pairs(const CellGrid& grid, double reach, std::size_t need,
                                                   const SetupBudget& budget) const {
  std::vector<Pair> pairs;
  for (std::size_t e = 0; e < walls_->size(); ++e) {
    const Wall& wl = (*walls_)[e];
    const double dx = wl.bx - wl.ax;
    const double dy = wl.by - wl.ay;
    const std::int64_t c0 = grid.col(std::min(wl.ax, wl.bx) - reach);
    const std::int64_t c1 = grid.col(std::max(wl.ax, wl.bx) + reach);
    const std::int64_t r0 = grid.row(std::min(wl.ay, wl.by) - reach);
    const std::int64_t r1 = grid.row(std::max(wl.ay, wl.by) + reach);
    for (std::int64_t j = r0; j <= r1; ++j) {
      const double y0 = grid.y0 + static_cast<double>(j) * grid.side - reach;
      // The wall's x-extent in the row's band, grown by a cell on each side (far more than
      // rounding needs: the exact test below decides every cell; this only skips those that
      // cannot pass it).
      double t0 = 0;
      double t1 = 1;
      if (dy != 0) {
        const double ta = (y0 - grid.side - wl.ay) / dy;
        const double tb = (y0 + 2 * grid.side + 2 * reach - wl.ay) / dy;
        t0 = std::max(t0, std::min(ta, tb));
        t1 = std::min(t1, std::max(ta, tb));
        if (!(t0 <= t1)) {
          continue;
        }
      }
      const double xa = wl.ax + t0 * dx;
      const double xb = wl.ax + t1 * dx;
      const std::int64_t i0 = std::max(c0, grid.col(std::min(xa, xb) - reach) - 1);
      const std::int64_t i1 = std::min(c1, grid.col(std::max(xa, xb) + reach) + 1);
      for (std::int64_t i = i0; i <= i1; ++i) {
        const double x0 = grid.x0 + static_cast<double>(i) * grid.side - reach;
        if (!segment_meets_box(wl, x0, y0, x0 + grid.side + 2 * reach, y0 + grid.side + 2 * reach)) {
          continue;
        }
        const auto ui = static_cast<std::size_t>(i);
        const auto uj = static_cast<std::size_t>(j);
        pairs.push_back(Pair{static_cast<std::uint32_t>(block_of(uj, ui) * kBlockCells + place_in_block(uj, ui)),
                             static_cast<std::uint32_t>(e)});
      }
      if (budget.limit != 0 && need + 16 * pairs.size() >= budget.limit) {  // a row at a time
        budget.check(need + 16 * pairs.size(), "the domain's edges come within reach of " +
                                                   std::to_string(pairs.size()) +
                                                   "+ cells of its grid, counted with multiplicity");
      }
    }
  }
  return pairs;
}

// The pairs grouped into the cells' lists.
void WallIndex::group(std::vector<Pair>& pairs, std::size_t blocks, std::size_t need, const SetupBudget& budget) {
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
                     static_cast<std::size_t>(std::min(budget.estimate, 1e18)));
  }
  std::vector<Pair> grouped(pairs.size());
  {
    std::vector<std::size_t> at(start.begin(), start.end() - 1);
    for (const Pair& q : pairs) {
      grouped[at[q.key / kBlockCells]++] = q;
    }
  }
  detail::release(pairs);
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
  budget.check(need + 12 * grouped.size() + walled_blocks * (kBlockCells + 1) * sizeof(std::uint32_t),
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
      wall_ids_[base + at[grouped[k].key % kBlockCells]++] = wall_id(grouped[k].wall);
    }
  }
}

void WallIndex::build_tree() {
  const std::size_t n = walls_->size();
  const std::size_t leaves = (n + kLeafWalls - 1) / kLeafWalls;
  leaves_ = std::bit_ceil(std::max<std::size_t>(leaves, 1));
  const double inf = std::numeric_limits<double>::infinity();
  tree_.assign(2 * leaves_, Bounds{inf, inf, -inf, -inf});
  for (std::size_t e = 0; e < n; ++e) {
    Bounds& b = tree_[leaves_ + e / kLeafWalls];
    const Wall& wl = (*walls_)[e];
    b.xmin = std::min({b.xmin, wl.ax, wl.bx});
    b.ymin = std::min({b.ymin, wl.ay, wl.by});
    b.xmax = std::max({b.xmax, wl.ax, wl.bx});
    b.ymax = std::max({b.ymax, wl.ay, wl.by});
  }
  for (std::size_t k = leaves_ - 1; k >= 1; --k) {
    const Bounds& l = tree_[2 * k];
    const Bounds& r = tree_[2 * k + 1];
    tree_[k] =
        Bounds{std::min(l.xmin, r.xmin), std::min(l.ymin, r.ymin), std::max(l.xmax, r.xmax), std::max(l.ymax, r.ymax)};
  }
}

}  // namespace frontpack::detail
