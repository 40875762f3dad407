// BucketGrid and GridFrame (src/common/bucket_grid.hpp), the lists of the statistics', the jam's,
// the thinning's and the edge index's float grids: a query visits exactly what a scan of every item
// finds listed in the cells the query meets, each cell's items in ascending order, and points and
// boxes land in the cells cell_index gives.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <random>
#include <vector>

#include "common/bucket_grid.hpp"

namespace {

namespace fp = frontpack;
using fp::detail::BucketGrid;
using fp::detail::GridFrame;

GridFrame frame_of(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> side(0.05, 0.5);
  std::uniform_int_distribution<std::size_t> count(1, 24);
  GridFrame f;
  f.x0 = -1.5;
  f.y0 = 0.25;
  f.inv_x = 1 / side(rng);
  f.inv_y = 1 / side(rng);
  f.nx = count(rng);
  f.ny = count(rng);
  return f;
}

// A random box, partly outside the grid at times (its cells clamp to the border).
fp::Box box_of(std::mt19937_64& rng, double reach) {
  std::uniform_real_distribution<double> at(-3, 6);
  std::uniform_real_distribution<double> size(0, reach);
  const double x = at(rng);
  const double y = at(rng);
  return fp::Box{x, y, x + size(rng), y + size(rng)};
}

// Whether the cell block of box b meets the cell block of box q (a scan that never looks at the
// grid's lists).
bool blocks_meet(const GridFrame& f, const fp::Box& b, const fp::Box& q) {
  return f.column(b.xmin) <= f.column(q.xmax) && f.column(q.xmin) <= f.column(b.xmax) &&
         f.row(b.ymin) <= f.row(q.ymax) && f.row(q.ymin) <= f.row(b.ymax);
}

TEST(BucketGrid, BoxQueriesEqualABruteForceScan) {
  std::mt19937_64 rng(47);
  for (int trial = 0; trial < 200; ++trial) {
    const GridFrame f = frame_of(rng);
    std::vector<fp::Box> boxes(std::uniform_int_distribution<std::size_t>(0, 300)(rng));
    for (fp::Box& b : boxes) {
      b = box_of(rng, 1.0);
    }
    BucketGrid<std::uint32_t, std::size_t> grid;
    grid.build_boxes(f, boxes.size(), [&boxes](std::size_t k) { return boxes[k]; });
    ASSERT_EQ(grid.cells(), f.cells());
    for (std::size_t c = 0; c < grid.cells(); ++c) {
      const auto items = grid.items(c);
      ASSERT_TRUE(std::is_sorted(items.begin(), items.end()));
      ASSERT_EQ(std::adjacent_find(items.begin(), items.end()), items.end()) << "an item twice in one cell";
    }
    for (int q = 0; q < 20; ++q) {
      const fp::Box query = box_of(rng, 2.0);
      std::vector<std::uint32_t> found;
      grid.visit_box(f, query, [&found](std::uint32_t k) { found.push_back(k); });
      std::sort(found.begin(), found.end());
      found.erase(std::unique(found.begin(), found.end()), found.end());
      std::vector<std::uint32_t> expected;
      for (std::size_t k = 0; k < boxes.size(); ++k) {
        if (blocks_meet(f, boxes[k], query)) {
          expected.push_back(static_cast<std::uint32_t>(k));
        }
        // Every box that meets the query geometrically is among them.
        const fp::Box& b = boxes[k];
        if (b.xmin <= query.xmax && query.xmin <= b.xmax && b.ymin <= query.ymax && query.ymin <= b.ymax) {
          ASSERT_TRUE(blocks_meet(f, b, query));
        }
      }
      ASSERT_EQ(found, expected) << "trial " << trial << " query " << q;
    }
  }
}

// Points land in the cell cell_index gives; a cell's listings count the points in it; the order
// of the visits over a block is row by row, each cell's items ascending.
TEST(BucketGrid, PointsLandInTheirCellsInOrder) {
  std::mt19937_64 rng(7);
  for (int trial = 0; trial < 100; ++trial) {
    const GridFrame f = frame_of(rng);
    std::uniform_real_distribution<double> at(-3, 6);
    std::vector<fp::Point> points(std::uniform_int_distribution<std::size_t>(0, 500)(rng));
    for (fp::Point& p : points) {
      p = {at(rng), at(rng)};
    }
    BucketGrid<std::uint32_t, std::uint32_t> grid;
    grid.build(f, points);
    std::vector<std::uint32_t> expected;
    for (std::size_t c = 0; c < f.cells(); ++c) {
      for (std::size_t k = 0; k < points.size(); ++k) {
        if (f.cell_of(points[k]) == c) {
          expected.push_back(static_cast<std::uint32_t>(k));
        }
      }
    }
    std::vector<std::uint32_t> visited;
    f.visit_block(0, f.nx - 1, 0, f.ny - 1,
                  [&](std::size_t c) { grid.visit(c, [&](std::uint32_t k) { visited.push_back(k); }); });
    ASSERT_EQ(visited, expected) << "trial " << trial;
    // Rebuilt smaller, the grid lists only the new points.
    points.resize(points.size() / 2);
    grid.build(f, points);
    std::size_t listed = 0;
    for (std::size_t c = 0; c < grid.cells(); ++c) {
      listed += grid.end(c) - grid.begin(c);
    }
    ASSERT_EQ(listed, points.size());
  }
}

// The cells an item names in any order are listed in ascending item order, and an item may name
// no cell at all.
TEST(BucketGrid, ListsFollowItemOrderWhateverTheCellOrder) {
  BucketGrid<std::size_t, std::size_t> grid;
  grid.build(3, 4, [](std::size_t k, auto&& emit) {
    if (k == 1) {
      return;
    }
    for (std::size_t c = 3; c-- > 0;) {
      if ((c + k) % 2 == 0 || k == 3) {
        emit(c);
      }
    }
  });
  EXPECT_EQ(std::vector<std::size_t>(grid.items(0).begin(), grid.items(0).end()), (std::vector<std::size_t>{0, 2, 3}));
  EXPECT_EQ(std::vector<std::size_t>(grid.items(1).begin(), grid.items(1).end()), (std::vector<std::size_t>{3}));
  EXPECT_EQ(std::vector<std::size_t>(grid.items(2).begin(), grid.items(2).end()), (std::vector<std::size_t>{0, 2, 3}));
}

}  // namespace
