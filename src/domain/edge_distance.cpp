#include "domain/edge_distance.hpp"

#include <utility>

namespace frontpack::detail {

EdgeDistanceIndex::EdgeDistanceIndex(const Domain& domain, double h) {
  for (const Polygon& p : domain.polygons()) {
    add_ring(p.outer);
    for (const Ring& hole : p.holes) {
      add_ring(hole);
    }
  }
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
}

}  // namespace frontpack::detail
