#include "domain/edge_distance.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include "common/grid_cells.hpp"

namespace frontpack::detail {

void EdgeDistanceIndex::add_walls(const Domain& domain) {
  if (domain.periodicity() == Periodicity::none) {
    for (const Polygon& p : domain.polygons()) {
      add_ring(p.outer);
      for (const Ring& hole : p.holes) {
        add_ring(hole);
      }
    }
    return;
  }
  if (domain.periodicity() == Periodicity::x) {
    const Box c = domain.bbox();  // the cell
    const double lx = c.width();
    for (const double y : {c.ymin, c.ymax}) {
      a_.push_back({c.xmin - lx, y});
      b_.push_back({c.xmax + lx, y});
    }
  }
}

EdgeDistanceIndex::EdgeDistanceIndex(const Domain& domain, double h) {
  add_walls(domain);
  const Box b = domain.bbox();
  // At most about 4 million cells (and at least one).
  const double area = std::max(b.width() * b.height(), 0.0);
  h = std::max(h, std::sqrt(area / 4e6));
  h_ = h > 0 ? h : 1;
  inv_h_ = 1 / h_;
  x0_ = b.xmin;
  y0_ = b.ymin;
  nx_ = axis_cells(b.width() * inv_h_, kMaxAxisCells);
  ny_ = axis_cells(b.height() * inv_h_, kMaxAxisCells);
  std::vector<std::pair<std::size_t, std::uint32_t>> entries;  // (cell, edge)
  for (std::size_t e = 0; e < a_.size(); ++e) {
    const Point a = a_[e];
    const Point c = b_[e];
    const double xlo = std::min(a.x, c.x);
    const double xhi = std::max(a.x, c.x);
    const std::size_t i0 = column(xlo);
    const std::size_t i1 = column(xhi);
    for (std::size_t i = i0; i <= i1; ++i) {
      // The edge's y range over this column's x range (conservative by a relative 1e-9).
      const double cx0 = std::max(xlo, x0_ + static_cast<double>(i) * h_);
      const double cx1 = std::min(xhi, x0_ + static_cast<double>(i + 1) * h_);
      double ylo = std::min(a.y, c.y);
      double yhi = std::max(a.y, c.y);
      if (c.x != a.x) {
        const double ya = a.y + (c.y - a.y) * ((cx0 - a.x) / (c.x - a.x));
        const double yb = a.y + (c.y - a.y) * ((cx1 - a.x) / (c.x - a.x));
        ylo = std::max(ylo, std::min(ya, yb) - 1e-9 * h_);
        yhi = std::min(yhi, std::max(ya, yb) + 1e-9 * h_);
      }
      for (std::size_t j = row(ylo); j <= row(yhi); ++j) {
        entries.emplace_back(j * nx_ + i, static_cast<std::uint32_t>(e));
      }
    }
  }
  std::sort(entries.begin(), entries.end());
  start_.assign(nx_ * ny_ + 1, 0);
  for (const auto& [cell, e] : entries) {
    ++start_[cell + 1];
    edges_.push_back(e);
  }
  for (std::size_t c = 0; c < nx_ * ny_; ++c) {
    start_[c + 1] += start_[c];
  }
  // Chessboard distance transform in two passes (exact for the Chebyshev metric: each pass takes
  // the minimum over the four neighbours already visited).
  empty_rings_.assign(nx_ * ny_, 255);
  for (std::size_t c = 0; c < nx_ * ny_; ++c) {
    if (start_[c + 1] > start_[c]) {
      empty_rings_[c] = 0;
    }
  }
  const auto relax = [this](std::size_t c, std::size_t i, std::size_t j, long di, long dj) {
    const long ni = static_cast<long>(i) + di;
    const long nj = static_cast<long>(j) + dj;
    if (ni < 0 || nj < 0 || ni >= static_cast<long>(nx_) || nj >= static_cast<long>(ny_)) {
      return;
    }
    const std::uint8_t v = empty_rings_[static_cast<std::size_t>(nj) * nx_ + static_cast<std::size_t>(ni)];
    empty_rings_[c] = std::min<std::uint8_t>(empty_rings_[c], v == 255 ? 255 : static_cast<std::uint8_t>(v + 1));
  };
  for (std::size_t j = 0; j < ny_; ++j) {
    for (std::size_t i = 0; i < nx_; ++i) {
      const std::size_t c = j * nx_ + i;
      relax(c, i, j, -1, 0);
      relax(c, i, j, -1, -1);
      relax(c, i, j, 0, -1);
      relax(c, i, j, 1, -1);
    }
  }
  for (std::size_t j = ny_; j-- > 0;) {
    for (std::size_t i = nx_; i-- > 0;) {
      const std::size_t c = j * nx_ + i;
      relax(c, i, j, 1, 0);
      relax(c, i, j, 1, 1);
      relax(c, i, j, 0, 1);
      relax(c, i, j, -1, 1);
    }
  }
}

double EdgeDistanceIndex::distance(Point p, double cap) const {
  if (a_.empty()) {
    return cap;
  }
  const std::size_t ci = column(p.x);
  const std::size_t cj = row(p.y);
  const std::size_t first = empty_rings_[cj * nx_ + ci];
  if (first >= 1 && static_cast<double>(first - 1) * h_ >= cap) {
    return cap;
  }
  double best = cap;
  const auto visit = [&](std::size_t i, std::size_t j) {
    const std::size_t c = j * nx_ + i;
    for (std::size_t e = start_[c]; e < start_[c + 1]; ++e) {
      const Point q = closest(edges_[e], p);
      best = std::min(best, std::hypot(q.x - p.x, q.y - p.y));
    }
  };
  const std::size_t reach = std::max(nx_, ny_);
  for (std::size_t k = first; k <= reach; ++k) {
    visit_ring(ci, cj, k, nx_, ny_, visit);
    // Every edge not yet seen lies outside the (2k + 1)-cell block around p's cell: farther than
    // k h from p (a millionth of a cell spared for the rounding of p's cell index).
    if (best <= (static_cast<double>(k) - 1e-6) * h_) {
      break;
    }
  }
  return best;
}

}  // namespace frontpack::detail
