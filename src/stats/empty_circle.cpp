// The largest empty circle: the maximum of the clearance f (stats/clearance.hpp) over the domain,
// by branch and bound on a quadtree over the clearance grid's cells.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>
#include <vector>

#include "common/stop.hpp"
#include "stats/clearance.hpp"
#include "stats/parts.hpp"

namespace frontpack::detail {

namespace {

// Deeper than any useful refinement: a cell of the grid halved 60 times is below the doubles'
// resolution of any coordinate it could hold. A square reaching it counts its upper bound as is.
constexpr int kMaxDepth = 60;

class Search {
 public:
  Search(const Clearance& f, double tolerance) : f_(f), tolerance_(tolerance), lists_(kMaxDepth + 1) {}

  // Searches q, whose bounds b are known: a square whose upper bound is within the tolerance of
  // the best value found ends the search there (it can raise the upper bound only); the others
  // are split into four, and the children searched in decreasing order of their upper bounds
  // (the best rises fastest so), each while its bound still exceeds the best.
  void search(const Square& q, const SquareBounds& b, int depth) {
    if (b.upper <= best_ + tolerance_ || depth == kMaxDepth) {
      open_ = std::max(open_, b.upper);
      return;
    }
    const std::span<const std::uint32_t> list = lists_[static_cast<std::size_t>(depth)][4];
    auto& lists = lists_[static_cast<std::size_t>(depth) + 1];
    const double a = q.a / 2;
    std::array<Square, 4> child;
    std::array<SquareBounds, 4> bounds;
    std::array<int, 4> order{0, 1, 2, 3};
    for (int k = 0; k < 4; ++k) {
      const auto u = static_cast<std::size_t>(k);
      child[u] = Square{q.x + (k % 2 == 0 ? -a : a), q.y + (k < 2 ? -a : a), a};
      bounds[u] = bound(child[u], list, b.side, &lists[u]);
    }
    std::sort(order.begin(), order.end(), [&bounds](int p, int r) {
      return bounds[static_cast<std::size_t>(p)].upper > bounds[static_cast<std::size_t>(r)].upper;
    });
    for (const int k : order) {
      const auto u = static_cast<std::size_t>(k);
      if (bounds[u].pruned || bounds[u].upper <= best_) {
        continue;
      }
      lists[4].swap(lists[u]);  // the child's disks become the list of its own children
      search(child[u], bounds[u], depth + 1);
      lists[4].swap(lists[u]);
    }
  }

  // Bounds of q (raising the best with its centre's value).
  SquareBounds bound(const Square& q, std::span<const std::uint32_t> list, Side side,
                     std::vector<std::uint32_t>* keep) {
    const SquareBounds b = f_.bound(q, list, side, std::nextafter(best_, kInf), keep);
    if (!b.pruned && b.certain && b.value > best_) {  // > 0: the centre is inside the domain
      best_ = b.value;
      centre_ = {q.x, q.y};
    }
    return b;
  }

  // A grid cell: its bounds from its block of disks, then the search.
  double visit_cell(const Square& q, std::span<const std::uint32_t> block, bool deep) {
    auto& top = lists_[0][4];
    const SquareBounds b = bound(q, block, Side::unknown, deep ? &top : nullptr);
    if (deep && !b.pruned && b.upper > best_) {
      search(q, b, 0);
    }
    return b.upper;
  }

  [[nodiscard]] double best() const noexcept { return best_; }
  [[nodiscard]] Point centre() const noexcept { return centre_; }
  [[nodiscard]] double open() const noexcept { return open_; }

 private:
  static constexpr double kInf = std::numeric_limits<double>::infinity();
  const Clearance& f_;
  double tolerance_;
  // Per depth, the disks kept for each of the four children being searched ([0..3]) and for the
  // square itself ([4]).
  std::vector<std::array<std::vector<std::uint32_t>, 5>> lists_;
  double best_ = 0;
  Point centre_;
  double open_ = 0;  // the largest upper bound of a square left unsplit
};

}  // namespace

// Two passes over the grid cells: the first bounds each cell and takes the value at its centre
// (a good first best), the second searches the cells whose bound exceeds the best, largest bound
// first, and stops at the first cell whose bound no longer does.
EmptyCircle largest_empty_circle(const Clearance& f, double tolerance, std::vector<double>& upper,
                                 const std::stop_token& stop) {
  Search search(f, tolerance);
  std::vector<std::uint32_t> list;
  const std::size_t n = f.nx() * f.ny();
  upper.assign(n, 0);
  for (std::size_t c = 0; c < n; ++c) {
    throw_if_stopped(stop, c);
    const std::size_t i = c % f.nx();
    const std::size_t j = c / f.nx();
    f.block(i, j, list);
    upper[c] = search.visit_cell(f.cell(i, j), list, false);
  }
  std::vector<std::uint32_t> order;
  for (std::size_t c = 0; c < n; ++c) {
    if (upper[c] > search.best()) {
      order.push_back(static_cast<std::uint32_t>(c));
    }
  }
  std::sort(order.begin(), order.end(), [&upper](std::uint32_t p, std::uint32_t q) {
    return upper[p] > upper[q] || (upper[p] == upper[q] && p < q);
  });
  for (std::size_t k = 0; k < order.size(); ++k) {
    throw_if_stopped(stop, k);
    const std::size_t c = order[k];
    if (upper[c] <= search.best()) {
      break;
    }
    const std::size_t i = c % f.nx();
    const std::size_t j = c / f.nx();
    f.block(i, j, list);
    (void)search.visit_cell(f.cell(i, j), list, true);
  }
  EmptyCircle e;
  e.computed = search.best() > 0;
  e.radius = search.best();
  e.radius_upper = std::max(search.best(), search.open());
  e.centre = search.centre();
  e.tolerance = tolerance;
  return e;
}

}  // namespace frontpack::detail
