// Thinning by local density (thinning.hpp): a priority queue of neighbourhood coverages with lazy
// updates, over a uniform grid of cells of side `reach`.
#include "targets/thinning.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <queue>
#include <tuple>
#include <vector>

#include "common/bucket_grid.hpp"

namespace frontpack::detail {

namespace {

// The grid over the centres: cell (i, j) lists the indices of the disks whose centre lies in it.
// Its cell index divides by the side, where GridFrame (common/bucket_grid.hpp) multiplies by the
// reciprocal: the two round differently for a centre on a cell's edge, and the order in which the
// neighbours' areas are summed, so the thinning's result, would change.
class CentreGrid {
 public:
  CentreGrid(const std::vector<Disk>& disks, double side) : side_(side) {
    for (const Disk& d : disks) {
      box_.extend(d.centre);
    }
    nx_ = cells_along(box_.width());
    ny_ = cells_along(box_.height());
    grid_.build(nx_ * ny_, disks.size(), [&](std::size_t i, auto&& emit) { emit(cell(disks[i].centre)); });
  }

  // Calls f(j) for every disk j whose centre may lie within `side` of p (the 3 x 3 cells around).
  template <class F>
  void near(Point p, F&& f) const {
    const std::size_t ci = index(p.x, box_.xmin, nx_);
    const std::size_t cj = index(p.y, box_.ymin, ny_);
    for (std::size_t j = cj == 0 ? 0 : cj - 1; j <= std::min(cj + 1, ny_ - 1); ++j) {
      for (std::size_t i = ci == 0 ? 0 : ci - 1; i <= std::min(ci + 1, nx_ - 1); ++i) {
        grid_.visit(j * nx_ + i, f);
      }
    }
  }

 private:
  std::size_t cells_along(double length) const {
    const double n = std::floor(length / side_) + 1;
    return static_cast<std::size_t>(std::clamp(n, 1.0, 4096.0));
  }
  std::size_t index(double v, double lo, std::size_t n) const {
    const double k = std::floor((v - lo) / side_);
    return static_cast<std::size_t>(std::clamp(k, 0.0, static_cast<double>(n - 1)));
  }
  std::size_t cell(Point p) const { return index(p.y, box_.ymin, ny_) * nx_ + index(p.x, box_.xmin, nx_); }

  double side_;
  Box box_;
  std::size_t nx_ = 1;
  std::size_t ny_ = 1;
  BucketGrid<std::size_t, std::size_t> grid_;
};

// The share of the disk of radius `reach` about c that lies in the domain, at 24 points (three
// rings of equal area, eight points each, staggered), at least 1/24.
double inside_share(const Domain& domain, Point c, double reach) {
  int inside = 0;
  for (int ring = 0; ring < 3; ++ring) {
    const double rho = reach * std::sqrt((ring + 0.5) / 3.0);
    for (int k = 0; k < 8; ++k) {
      const double a = (k + 0.5 * ring) * std::numbers::pi / 4;
      inside += domain.locate({c.x + rho * std::cos(a), c.y + rho * std::sin(a)}) != Location::outside ? 1 : 0;
    }
  }
  return std::max(inside, 1) / 24.0;
}

double area_of(const Disk& d) {
  return std::numbers::pi * d.radius * d.radius;
}

}  // namespace

std::size_t thin_to_area(const Domain& domain, std::vector<Disk>& disks, double target_area, double below,
                         double reach) {
  double total = 0;
  for (const Disk& d : disks) {
    total += area_of(d);
  }
  if (disks.empty() || total <= target_area) {
    return 0;
  }
  const CentreGrid grid(disks, reach);
  const double reach2 = reach * reach;
  const std::size_t n = disks.size();
  std::vector<double> norm(n);     // the neighbourhood's area in the domain
  std::vector<double> covered(n);  // the area of the neighbours
  std::vector<std::uint32_t> version(n, 0);
  std::vector<std::uint8_t> gone(n, 0);
  for (std::size_t i = 0; i < n; ++i) {
    norm[i] = std::numbers::pi * reach2 * inside_share(domain, disks[i].centre, reach);
    double sum = 0;
    grid.near(disks[i].centre, [&](std::size_t j) {
      const double dx = disks[j].centre.x - disks[i].centre.x;
      const double dy = disks[j].centre.y - disks[i].centre.y;
      if (j != i && dx * dx + dy * dy < reach2) {
        sum += area_of(disks[j]);
      }
    });
    covered[i] = sum;
  }
  // Densest first; ties by the smaller index (the queue's top is the largest tuple).
  using Entry = std::tuple<double, std::size_t, std::uint32_t>;  // density, n - 1 - index, version
  std::priority_queue<Entry> queue;
  for (std::size_t i = 0; i < n; ++i) {
    queue.emplace(covered[i] / norm[i], n - 1 - i, 0);
  }
  std::size_t removed = 0;
  while (total > target_area && !queue.empty()) {
    const auto [density, rank, ver] = queue.top();
    queue.pop();
    (void)density;
    const std::size_t i = n - 1 - rank;
    if (gone[i] != 0 || ver != version[i]) {
      continue;
    }
    const double a = area_of(disks[i]);
    if (total - a < target_area - below) {
      continue;  // too large a step: try the next one
    }
    gone[i] = 1;
    total -= a;
    ++removed;
    grid.near(disks[i].centre, [&](std::size_t j) {
      const double dx = disks[j].centre.x - disks[i].centre.x;
      const double dy = disks[j].centre.y - disks[i].centre.y;
      if (j != i && gone[j] == 0 && dx * dx + dy * dy < reach2) {
        covered[j] -= a;
        ++version[j];
        queue.emplace(covered[j] / norm[j], n - 1 - j, version[j]);
      }
    });
  }
  std::size_t k = 0;
  for (std::size_t i = 0; i < n; ++i) {
    if (gone[i] == 0) {
      disks[k++] = disks[i];
    }
  }
  disks.resize(k);
  return removed;
}

}  // namespace frontpack::detail
