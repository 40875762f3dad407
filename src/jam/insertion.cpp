#include "jam/insertion.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace frontpack::detail {

namespace {

constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();
// At most this many lattice rows or columns over the box, so that their indices convert to 64-bit
// integers exactly (only the rows and columns near a disk are visited).
constexpr double kMostAxisPoints = 0x1p62;

}  // namespace

Insertion::Insertion(const Domain& domain, const EdgeDistanceIndex& walls, Periodicity periodicity, const Box& cell,
                     double rmin, double rmax, const std::vector<Disk>& disks, Rng& rng)
    : walls_(walls), cell_(cell), cap_(rmax) {
  wrap_.x = periodicity != Periodicity::none;
  wrap_.y = periodicity == Periodicity::xy;
  wrap_.lx = cell.xmax - cell.xmin;
  wrap_.ly = cell.ymax - cell.ymin;
  const double per = kPerDisk * static_cast<double>(std::max<std::size_t>(disks.size(), 1));
  // The spacing from the packing's own scale (the domain's area per point, or rmin / 2), not from
  // the box: a domain whose parts lie far apart keeps a lattice fine enough for its disks.
  h_ = std::max(0.5 * rmin, std::sqrt(domain.area() / per));
  const double x0 = cell.xmin + rng.uniform() * h_;
  const double y0 = cell.ymin + rng.uniform() * h_;
  const double gx = (cell.xmax - x0) / h_;
  const double gy = (cell.ymax - y0) / h_;
  if (!(gx < kMostAxisPoints && gy < kMostAxisPoints && std::isfinite(x0) && std::isfinite(y0))) {
    return;  // a box beyond the doubles' range or 2^62 spacings: no candidate, the stage inserts nothing
  }
  const std::uint64_t nx = static_cast<std::uint64_t>(std::max(0.0, gx)) + 1;
  const std::uint64_t ny = static_cast<std::uint64_t>(std::max(0.0, gy)) + 1;
  // The lattice points within rmax of each disk's edge (in a square around it), row by row: the
  // disks whose squares span a row give it intervals of columns, merged so that each point is
  // tested once. Memory: the disks spanning a row and the points kept.
  const auto span = [this](double lo, double hi, double origin, std::uint64_t n) {
    const auto a = static_cast<std::uint64_t>(std::clamp(std::ceil((lo - origin) / h_), 0.0, static_cast<double>(n)));
    const auto b =
        static_cast<std::uint64_t>(std::clamp(std::floor((hi - origin) / h_) + 1, 0.0, static_cast<double>(n)));
    return std::pair{a, std::max(a, b)};
  };
  std::vector<std::uint32_t> order(disks.size());
  std::vector<std::pair<std::uint64_t, std::uint64_t>> rows(disks.size());  // per disk: the rows its square spans
  for (std::uint32_t i = 0; i < disks.size(); ++i) {
    order[i] = i;
    rows[i] = span(disks[i].centre.y - disks[i].radius - rmax, disks[i].centre.y + disks[i].radius + rmax, y0, ny);
  }
  std::sort(order.begin(), order.end(),
            [&](std::uint32_t p, std::uint32_t q) { return rows[p].first < rows[q].first; });
  std::vector<std::uint32_t> active;
  std::vector<std::pair<std::uint64_t, std::uint64_t>> columns;
  std::size_t next = 0;
  for (std::uint64_t j = 0; j < ny;) {
    if (active.empty()) {
      if (next == order.size()) {
        break;
      }
      j = std::max(j, rows[order[next]].first);  // (skip the rows no disk spans)
      if (j >= ny) {
        break;
      }
    }
    while (next < order.size() && rows[order[next]].first <= j) {
      active.push_back(order[next++]);
    }
    std::erase_if(active, [&](std::uint32_t i) { return rows[i].second <= j; });
    columns.clear();
    for (const std::uint32_t i : active) {
      const double reach = disks[i].radius + rmax;
      columns.push_back(span(disks[i].centre.x - reach, disks[i].centre.x + reach, x0, nx));
    }
    std::sort(columns.begin(), columns.end());
    std::uint64_t done = 0;  // the columns of this row tested so far
    for (const auto& [c0, c1] : columns) {
      for (std::uint64_t i = std::max(c0, done); i < c1; ++i) {
        // A point at least a spacing from every wall stays on its side of them while insert()
        // moves it (by less than a spacing).
        const Point p{x0 + h_ * static_cast<double>(i), y0 + h_ * static_cast<double>(j)};
        if (p.x < cell.xmax && p.y < cell.ymax && walls_.distance(p, h_) >= h_ &&
            domain.locate(p) == Location::inside) {
          candidates_.push_back(p);
        }
      }
      done = std::max(done, c1);
    }
    ++j;
  }
}

double Insertion::clearance(Point p, const std::vector<Disk>& disks) const {
  double c = walls_.distance(p, cap_);
  const auto visit = [&](std::size_t i) {
    const double dx = wrap_.dx(disks[i].centre.x - p.x);
    const double dy = wrap_.dy(disks[i].centre.y - p.y);
    c = std::min(c, std::sqrt(dx * dx + dy * dy) - disks[i].radius);
  };
  // A disk nearer than cap_ to p has its centre within cap_ + rmax = the grid's reach.
  grid_.neighbours(grid_.cell_of(p), [&](std::size_t k) {
    for (std::uint32_t e = grid_.begin(k); e < grid_.end(k); ++e) {
      visit(grid_.item(e));
    }
    for (std::uint32_t e = head_[k]; e != kNone; e = next_[e]) {
      visit(base_ + e);
    }
  });
  return c;
}

std::size_t Insertion::insert(std::vector<Disk>& disks, std::size_t count, const RadiusDistribution& radii, Rng& rng) {
  grid_.build(disks, cell_, wrap_.x, wrap_.y, 2 * cap_);
  base_ = disks.size();
  head_.assign(grid_.cells(), kNone);
  next_.clear();
  heap_.clear();
  for (std::size_t e = 0; e < candidates_.size(); ++e) {
    heap_.emplace_back(clearance(candidates_[e], disks), e);
  }
  std::make_heap(heap_.begin(), heap_.end());
  std::size_t added = 0;
  while (added < count && !heap_.empty()) {
    std::pop_heap(heap_.begin(), heap_.end());
    const auto [was, q] = heap_.back();
    heap_.pop_back();
    Point p = candidates_[q];
    const double now = clearance(p, disks);
    if (now < was) {
      // A disk appended this round came near: the point goes back with what is left of its room
      // (clearances only fall as disks are appended, so the first point popped whose clearance
      // still holds has the largest).
      heap_.emplace_back(now, q);
      std::push_heap(heap_.begin(), heap_.end());
      continue;
    }
    // Climb the clearance: steps of h/2, h/4 and h/8 to the best of the 8 points around, each
    // point less than a spacing from the lattice point (which lies at least a spacing from every
    // wall), so that the disk's centre stays on the lattice point's side of every wall. A point
    // beyond a periodic side is measured at its image in the cell, where the grid has its
    // neighbours.
    const Point start = p;
    double best = now;
    for (double step = h_ / 2; step > h_ / 16; step /= 2) {
      Point pick = p;
      for (int oy = -1; oy <= 1; ++oy) {
        for (int ox = -1; ox <= 1; ++ox) {
          const Point t{p.x + ox * step, p.y + oy * step};
          const double mx = t.x - start.x;
          const double my = t.y - start.y;
          if ((ox == 0 && oy == 0) || !(mx * mx + my * my < h_ * h_)) {
            continue;  // (p itself has clearance best)
          }
          const double c = clearance(wrap_.into_cell(t, cell_), disks);
          if (c > best) {
            best = c;
            pick = t;
          }
        }
      }
      p = pick;
    }
    p = wrap_.into_cell(p, cell_);
    disks.push_back(Disk{p, radii.quantile(rng.uniform())});
    const std::size_t k = grid_.cell_of(p);
    next_.push_back(head_[k]);
    head_[k] = static_cast<std::uint32_t>(next_.size() - 1);
    ++added;
  }
  return added;
}

}  // namespace frontpack::detail
