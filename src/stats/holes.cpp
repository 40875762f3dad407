// Holes that take a disk of radius rho: the connected components of {f >= rho} (f the clearance,
// stats/clearance.hpp), resolved on the leaves of a quadtree over the clearance grid's cells.
//
// A square is dropped when f < rho on it (its upper bound), kept whole when f >= rho on it (the
// centre's certain value minus the half-diagonal), and split otherwise, down to a half-diagonal
// of rho / 32. The kept squares (leaves) cover {f >= rho}, and every point of the domain in a
// leaf has f >= rho - 2 rho / 32 (a leaf's upper bound is at most its centre's value plus its
// half-diagonal). The count is that of the connected components of the union of the closed
// leaves (squares touching at an edge or a corner are joined) that hold a leaf whose centre is
// certified to have f >= rho: a hole where a disk of radius rho (1 + 1/32) fits is never
// missed, and two holes are counted as one only when {f >= rho (1 - 1/16)} joins them.
//
// The cost. The squares examined (probes) grow as the length of the level set {f = rho} over the
// leaves' side rho / 22.6: about 20 per grid cell and level below the cell's, so a radius far below
// the disks' asks for millions per cell (the radius 1e-6 in 5 disks of 0.125: about 10^8 per
// cell). Before the search, the squares are examined down to kEstimateDepth levels below the grid's
// (at most 85 a cell); each square left open there yields about twice as many at every further
// level (a curve met by a square meets two of its four quarters), so the probes are estimated as
// those made plus 4 n (2^(D - kEstimateDepth) - 1), n the open squares and D the leaves' depth,
// and held to StatsOptions::budget (detail::check_count) before the search; the search stops with
// the same LimitError if it exceeds the budget all the same.
//
// A periodic cell: {f >= rho} continues across a periodic side, and the grid's part beyond the
// cell's high sides repeats the cell's low sides. A leaf is also joined with every leaf that its
// translate by a period (one or both axes, either way) touches, so a hole across a side, or seen
// twice in that part, is one component (the translate touches within a rounding margin).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>
#include <string_view>
#include <vector>

#include "common/budget.hpp"
#include "common/stop.hpp"
#include "stats/clearance.hpp"
#include "stats/parts.hpp"

namespace frontpack::detail {

namespace {

// Leaf coordinates stay below 2^62: 2^24 grid cells per axis, halved at most 38 times.
constexpr int kMaxDepth = 38;

// The levels below the grid's examined to estimate the probes (see the file's comment).
constexpr int kEstimateDepth = 3;

// The memory a probe may take: a leaf (32 bytes), its parent and counted marks.
constexpr double kBytesPerProbe = 40;

constexpr std::string_view kWhat = "hole probes";
constexpr std::string_view kAdvice = "use a larger hole radius (--hole-radius)";

// A leaf: depth below its grid cell and coordinates in the squares of that depth over the whole
// grid (grid cell (i, j) at depth d spans x in [i 2^d, (i + 1) 2^d)).
struct Leaf {
  int depth;
  std::int64_t x;
  std::int64_t y;
  bool certified;
  [[nodiscard]] bool operator<(const Leaf& o) const noexcept {
    return depth != o.depth ? depth < o.depth : x != o.x ? x < o.x : y < o.y;
  }
};

class HoleSearch {
 public:
  // A search down to depth `limit` below the grid cells (kMaxDepth: the whole search; less: the
  // estimate, which keeps no leaves), stopped by a LimitError past `allowed` probes.
  HoleSearch(const Clearance& f, double rho, int limit, const Budget& budget, double allowed)
      : f_(f),
        rho_(rho),
        delta_(rho / 32),
        limit_(limit),
        budget_(budget),
        allowed_(allowed),
        lists_(kMaxDepth + 1),
        first_(f.nx() * f.ny() + 1, 0) {}

  // The squares examined so far, and those left open at the depth limit.
  [[nodiscard]] double probes() const noexcept { return probes_; }
  [[nodiscard]] double open_at_limit() const noexcept { return open_at_limit_; }

  // A grid cell known to hold no point with f >= rho.
  void skip_cell(std::size_t c) { first_[c + 1] = leaves_.size(); }

  // The leaves of grid cell c (cells in increasing order), sorted for lookups.
  void visit_cell(std::size_t c, std::span<const std::uint32_t> block) {
    const std::size_t i = c % f_.nx();
    const std::size_t j = c / f_.nx();
    const std::size_t begin = leaves_.size();
    visit(f_.cell(i, j), block, Side::unknown, 0, static_cast<std::int64_t>(i), static_cast<std::int64_t>(j));
    std::sort(leaves_.begin() + static_cast<std::ptrdiff_t>(begin), leaves_.end());
    first_[c + 1] = leaves_.size();
  }

  void visit(const Square& q, std::span<const std::uint32_t> list, Side side, int depth, std::int64_t x,
             std::int64_t y) {
    if (++probes_ > allowed_) {
      check_count(budget_, probes_, kBytesPerProbe, kWhat, kAdvice);  // throws
    }
    std::vector<std::uint32_t>& keep = lists_[static_cast<std::size_t>(depth)];
    const SquareBounds b = f_.bound(q, list, side, rho_, &keep);
    if (b.pruned) {
      return;
    }
    const double hd = q.half_diagonal();
    const bool full = b.certain && b.value - hd >= rho_;
    if (full || hd <= delta_ || depth == kMaxDepth) {
      if (limit_ == kMaxDepth) {
        leaves_.push_back({depth, x, y, full || (b.certain && b.value >= rho_)});
      }
      return;
    }
    if (depth == limit_) {
      ++open_at_limit_;
      return;
    }
    const double a = q.a / 2;
    for (const auto& [sx, sy] : {std::pair{0, 0}, std::pair{1, 0}, std::pair{0, 1}, std::pair{1, 1}}) {
      visit(Square{q.x + (2 * sx - 1) * a, q.y + (2 * sy - 1) * a, a}, keep, b.side, depth + 1, 2 * x + sx, 2 * y + sy);
    }
  }

  // Union-find over the leaves. Each leaf looks up the 8 squares of its own size around it and
  // their ancestors: a leaf it touches that is as large or larger holds one of them, and a
  // smaller one finds it the same way.
  [[nodiscard]] std::size_t components(const std::stop_token& stop) {
    std::vector<std::uint32_t> parent(leaves_.size());
    std::iota(parent.begin(), parent.end(), 0U);
    const auto find = [&parent](std::uint32_t a) {
      while (parent[a] != a) {
        parent[a] = parent[parent[a]];
        a = parent[a];
      }
      return a;
    };
    for (std::size_t k = 0; k < leaves_.size(); ++k) {
      throw_if_stopped(stop, k);
      const Leaf& leaf = leaves_[k];
      for (int dy = -1; dy <= 1; ++dy) {
        for (int dx = -1; dx <= 1; ++dx) {
          if (dx == 0 && dy == 0) {
            continue;
          }
          std::int64_t x = leaf.x + dx;
          std::int64_t y = leaf.y + dy;
          std::int64_t ox = leaf.x;
          std::int64_t oy = leaf.y;
          // Up to the first ancestor shared with the leaf itself (a leaf has no leaf above it).
          for (int d = leaf.depth; d >= 0 && x >= 0 && y >= 0 && (x != ox || y != oy);
               --d, x >>= 1, y >>= 1, ox >>= 1, oy >>= 1) {
            if (const std::size_t at = find_leaf(d, x, y); at != kNone) {
              const std::uint32_t a = find(static_cast<std::uint32_t>(k));
              const std::uint32_t b = find(static_cast<std::uint32_t>(at));
              parent[std::max(a, b)] = std::min(a, b);
              break;
            }
          }
        }
      }
    }
    if (f_.periods().any()) {
      join_across_sides(parent, find, stop);
    }
    std::vector<std::uint8_t> counted(leaves_.size(), 0);
    for (std::size_t k = 0; k < leaves_.size(); ++k) {
      if (leaves_[k].certified) {
        counted[find(static_cast<std::uint32_t>(k))] = 1;
      }
    }
    return static_cast<std::size_t>(std::count(counted.begin(), counted.end(), std::uint8_t{1}));
  }

 private:
  const Clearance& f_;
  double rho_;
  double delta_;
  int limit_;
  const Budget& budget_;
  double allowed_;
  double probes_ = 0;
  double open_at_limit_ = 0;
  std::vector<std::vector<std::uint32_t>> lists_;
  std::vector<Leaf> leaves_;        // grid cell by grid cell, each cell's sorted
  std::vector<std::size_t> first_;  // grid cell c's leaves: [first_[c], first_[c + 1])

  static constexpr std::size_t kNone = ~std::size_t{0};

  // A leaf's square.
  [[nodiscard]] Box box_of(const Leaf& leaf) const noexcept {
    const double a = std::ldexp(f_.side(), -leaf.depth);
    const Point o = f_.origin();
    const double x = o.x + static_cast<double>(leaf.x) * a;
    const double y = o.y + static_cast<double>(leaf.y) * a;
    return Box{x, y, x + a, y + a};
  }

  // Joins each leaf with the leaves its translates by a period touch (see the file's comment).
  template <class Find>
  void join_across_sides(std::vector<std::uint32_t>& parent, Find& find, const std::stop_token& stop) {
    const Periods& p = f_.periods();
    const Point o = f_.origin();
    const double gx = o.x + static_cast<double>(f_.nx()) * f_.side();
    const double gy = o.y + static_cast<double>(f_.ny()) * f_.side();
    // The margin for the rounding of the leaves' corners and of the translation.
    const double eps =
        1e-9 * f_.side() + 0x1p-48 * std::max({std::abs(o.x), std::abs(o.y), std::abs(gx), std::abs(gy)});
    const int jy = p.y ? 1 : 0;
    for (std::size_t k = 0; k < leaves_.size(); ++k) {
      throw_if_stopped(stop, k);
      const Box b = box_of(leaves_[k]);
      for (int j = -jy; j <= jy; ++j) {
        for (int i = -1; i <= 1; ++i) {
          const double tx = static_cast<double>(i) * p.lx;
          const double ty = static_cast<double>(j) * p.ly;
          const Box t{b.xmin + tx - eps, b.ymin + ty - eps, b.xmax + tx + eps, b.ymax + ty + eps};
          if ((i == 0 && j == 0) || t.xmax < o.x || t.xmin > gx || t.ymax < o.y || t.ymin > gy) {
            continue;
          }
          for (std::size_t r = f_.row(t.ymin); r <= f_.row(t.ymax); ++r) {
            for (std::size_t c = f_.column(t.xmin); c <= f_.column(t.xmax); ++c) {
              const std::size_t cell = r * f_.nx() + c;
              for (std::size_t m = first_[cell]; m < first_[cell + 1]; ++m) {
                const Box u = box_of(leaves_[m]);
                if (u.xmin <= t.xmax && t.xmin <= u.xmax && u.ymin <= t.ymax && t.ymin <= u.ymax) {
                  const std::uint32_t a = find(static_cast<std::uint32_t>(k));
                  const std::uint32_t d = find(static_cast<std::uint32_t>(m));
                  parent[std::max(a, d)] = std::min(a, d);
                }
              }
            }
          }
        }
      }
    }
  }

  // The leaf with these coordinates, if any: a binary search among its grid cell's leaves.
  [[nodiscard]] std::size_t find_leaf(int depth, std::int64_t x, std::int64_t y) const {
    const std::int64_t i = x >> depth;
    const std::int64_t j = y >> depth;
    if (i >= static_cast<std::int64_t>(f_.nx()) || j >= static_cast<std::int64_t>(f_.ny())) {
      return kNone;
    }
    const std::size_t c = static_cast<std::size_t>(j) * f_.nx() + static_cast<std::size_t>(i);
    const auto begin = leaves_.begin() + static_cast<std::ptrdiff_t>(first_[c]);
    const auto end = leaves_.begin() + static_cast<std::ptrdiff_t>(first_[c + 1]);
    const Leaf key{depth, x, y, false};
    const auto it = std::lower_bound(begin, end, key);
    return it != end && it->depth == depth && it->x == x && it->y == y ? static_cast<std::size_t>(it - leaves_.begin())
                                                                       : kNone;
  }
};

// The probes the budget allows: max_count, and the memory allowed over kBytesPerProbe (each
// unlimited when 0).
double allowed_probes(const Budget& budget) {
  constexpr double kNone = std::numeric_limits<double>::infinity();
  const double memory = memory_allowed(budget);
  return std::min(budget.max_count > 0 ? static_cast<double>(budget.max_count) : kNone,
                  memory > 0 ? std::floor(memory / kBytesPerProbe) : kNone);
}

// Runs the search over the grid cells (those whose upper bound reaches rho).
void search_cells(HoleSearch& search, const Clearance& f, double rho, std::span<const double> cell_upper,
                  const std::stop_token& stop) {
  std::vector<std::uint32_t> list;
  for (std::size_t c = 0; c < f.nx() * f.ny(); ++c) {
    throw_if_stopped(stop, c);
    if (!cell_upper.empty() && cell_upper[c] < rho) {
      search.skip_cell(c);
      continue;
    }
    f.block(c % f.nx(), c / f.nx(), list);
    search.visit_cell(c, list);
  }
}

}  // namespace

std::size_t count_holes(const Clearance& f, double rho, std::span<const double> cell_upper, const Budget& budget,
                        const std::stop_token& stop) {
  if (!(rho > 0)) {
    return 0;
  }
  const double allowed = allowed_probes(budget);
  // D, the depth of the smallest leaves: the grid cell's half-diagonal halved until rho / 32.
  const double levels = std::ceil(std::log2(f.cell(0, 0).half_diagonal() / (rho / 32)));
  const int depth = levels > 0 ? static_cast<int>(std::min(levels, static_cast<double>(kMaxDepth))) : 0;
  if (depth > kEstimateDepth) {
    HoleSearch estimate(f, rho, kEstimateDepth, budget, allowed);
    search_cells(estimate, f, rho, cell_upper, stop);
    const double more = 4 * estimate.open_at_limit() * (std::ldexp(1.0, depth - kEstimateDepth) - 1);
    check_count(budget, estimate.probes() + more, kBytesPerProbe, kWhat, kAdvice);
  }
  HoleSearch search(f, rho, kMaxDepth, budget, allowed);
  search_cells(search, f, rho, cell_upper, stop);
  return search.components(stop);
}

}  // namespace frontpack::detail
