// visit_cells() (src/generate/disk_grid.hpp), the generators' grid scan: it visits exactly the disks a
// plain walk of the cells' chains visits, in the same order (the generators' choices, and so
// their packings, depend on it), stops where the visitor says, and does so both for blocks of up
// to 32 cells (gathered first) and for larger ones, with either end-of-chain marker the
// generators use.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <random>
#include <utility>
#include <vector>

#include "generate/disk_grid.hpp"

namespace {

using frontpack::detail::kGatherCells;
using frontpack::detail::visit_cells;

struct Node {
  double x, y, r;
  std::int32_t cell_next;
};

// A grid of nx x ny cells with `disks` disks dropped into random cells (chains newest first, as
// the generators link them).
struct Grid {
  std::size_t nx, ny;
  std::int32_t none;
  std::vector<std::int32_t> heads;
  std::vector<Node> nodes;

  Grid(std::size_t nx_, std::size_t ny_, std::size_t disks, std::int32_t none_, std::uint64_t seed)
      : nx(nx_), ny(ny_), none(none_), heads(nx_ * ny_, none_) {
    std::mt19937_64 rng(seed);
    std::uniform_int_distribution<std::size_t> cell(0, nx * ny - 1);
    for (std::size_t i = 0; i < disks; ++i) {
      const std::size_t c = cell(rng);
      nodes.push_back(Node{static_cast<double>(c % nx), static_cast<double>(c / nx), 1, heads[c]});
      heads[c] = static_cast<std::int32_t>(i);
    }
  }

  // The reference: rows, cells in them, chains, stopping after visiting `stop` disks.
  [[nodiscard]] std::vector<std::int32_t> walk(std::int64_t c0, std::int64_t c1, std::int64_t r0, std::int64_t r1,
                                               std::size_t stop) const {
    std::vector<std::int32_t> seen;
    for (std::int64_t j = r0; j <= r1; ++j) {
      for (std::int64_t i = c0; i <= c1; ++i) {
        for (std::int32_t d = heads[static_cast<std::size_t>(j) * nx + static_cast<std::size_t>(i)]; d != none;
             d = nodes[static_cast<std::size_t>(d)].cell_next) {
          seen.push_back(d);
          if (seen.size() == stop) {
            return seen;
          }
        }
      }
    }
    return seen;
  }

  [[nodiscard]] std::vector<std::int32_t> visit(std::int64_t c0, std::int64_t c1, std::int64_t r0, std::int64_t r1,
                                                std::size_t stop, bool& stopped) const {
    std::vector<std::int32_t> seen;
    stopped = visit_cells(heads.data(), nx, nodes.data(), none, c0, c1, r0, r1, [&](std::int32_t d, const Node& o) {
      EXPECT_EQ(&o, &nodes[static_cast<std::size_t>(d)]);
      seen.push_back(d);
      return seen.size() == stop;
    });
    return seen;
  }
};

void check_blocks(const Grid& g, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_int_distribution<std::int64_t> col(0, static_cast<std::int64_t>(g.nx) - 1);
  std::uniform_int_distribution<std::int64_t> row(0, static_cast<std::int64_t>(g.ny) - 1);
  std::size_t small = 0;
  std::size_t large = 0;
  for (int t = 0; t < 2000; ++t) {
    std::int64_t c0 = col(rng);
    std::int64_t c1 = col(rng);
    std::int64_t r0 = row(rng);
    std::int64_t r1 = row(rng);
    if (t % 2 == 0) {  // half of them small enough to be gathered
      c1 = std::min<std::int64_t>(c0 + static_cast<std::int64_t>(rng() % 6), static_cast<std::int64_t>(g.nx) - 1);
      r1 = std::min<std::int64_t>(r0 + static_cast<std::int64_t>(rng() % 6), static_cast<std::int64_t>(g.ny) - 1);
    }
    if (c1 < c0) {
      std::swap(c0, c1);
    }
    if (r1 < r0) {
      std::swap(r0, r1);
    }
    (static_cast<std::size_t>((c1 - c0 + 1) * (r1 - r0 + 1)) <= kGatherCells ? small : large) += 1;
    const std::vector<std::int32_t> all = g.walk(c0, c1, r0, r1, 0);
    bool stopped = true;
    ASSERT_EQ(g.visit(c0, c1, r0, r1, 0, stopped), all) << c0 << ".." << c1 << " x " << r0 << ".." << r1;
    EXPECT_FALSE(stopped);
    if (!all.empty()) {
      const std::size_t stop = 1 + rng() % all.size();
      const std::vector<std::int32_t> part = g.visit(c0, c1, r0, r1, stop, stopped);
      EXPECT_TRUE(stopped);
      EXPECT_EQ(part, g.walk(c0, c1, r0, r1, stop));
    }
  }
  // Both paths were taken, many times.
  EXPECT_GT(small, 300U);
  EXPECT_GT(large, 300U);
}

TEST(VisitCells, VisitsWhatTheChainsHoldInOrderAndStopsWhenTold) {
  // The open front's end of chain (-1) and the boundary front's (the least int32).
  check_blocks(Grid(40, 30, 2500, -1, 1), 11);
  check_blocks(Grid(40, 30, 2500, std::numeric_limits<std::int32_t>::min(), 2), 12);
}

TEST(VisitCells, BlocksAtTheGatheringLimit) {
  // Blocks of exactly kGatherCells cells (gathered) and of one more (not), in several shapes.
  static_assert(kGatherCells == 32);
  const Grid g(40, 40, 3000, -1, 6);
  for (const auto& [w, h] : {std::pair{4, 8}, std::pair{8, 4}, std::pair{1, 32}, std::pair{32, 1}, std::pair{3, 11},
                             std::pair{11, 3}, std::pair{33, 1}, std::pair{1, 33}}) {
    for (std::int64_t c0 = 0; c0 + w <= 40; c0 += 3) {
      const std::int64_t r0 = (c0 * 7) % (41 - h);
      bool stopped = true;
      const std::vector<std::int32_t> all = g.walk(c0, c0 + w - 1, r0, r0 + h - 1, 0);
      ASSERT_EQ(g.visit(c0, c0 + w - 1, r0, r0 + h - 1, 0, stopped), all) << w << " x " << h << " at " << c0;
      EXPECT_FALSE(stopped);
      ASSERT_FALSE(all.empty());
      EXPECT_EQ(g.visit(c0, c0 + w - 1, r0, r0 + h - 1, all.size() / 2 + 1, stopped),
                g.walk(c0, c0 + w - 1, r0, r0 + h - 1, all.size() / 2 + 1));
      EXPECT_TRUE(stopped);
    }
  }
}

TEST(VisitCells, SparseAndDenseGrids) {
  check_blocks(Grid(64, 64, 100, -1, 3), 13);   // mostly empty cells
  check_blocks(Grid(16, 16, 4000, -1, 4), 14);  // long chains
  check_blocks(Grid(1, 200, 300, -1, 5), 15);   // one column
}

}  // namespace
