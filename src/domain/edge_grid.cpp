#include "domain/edge_grid.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "common/float_bits.hpp"
#include "exact/predicates.hpp"

namespace frontpack::detail {

namespace {

// Boundaries lo = b[0] < b[1] < ... < b[n] with b[n] > hi, about `n` equal steps. The step is kept
// at least 64 ulps of the coordinates, so the boundaries are strictly increasing.
std::vector<double> boundaries(double lo, double hi, std::size_t n) {
  const double extent = hi - lo;
  const double scale = std::max(std::abs(lo), std::abs(hi));
  const double min_step = 64.0 * (next_up(scale) - scale);
  if (extent > 0.0 && min_step > 0.0) {
    const double most = std::floor(extent / min_step);
    n = std::min(n, static_cast<std::size_t>(std::max(1.0, std::min(most, 1e9))));
  } else {
    n = 1;
  }
  std::vector<double> b(n + 1);
  const double step = extent / static_cast<double>(n);
  b[0] = lo;
  for (std::size_t i = 1; i < n; ++i) {
    b[i] = lo + static_cast<double>(i) * step;
  }
  b[n] = next_up(hi);
  return b;
}

// Index of the interval [b[i], b[i+1]) holding x, clamped to [0, n - 1]. Exact: the guess from
// the division is corrected by comparisons, so the result is monotone in x.
std::size_t locate_interval(const std::vector<double>& b, double inv_step, double x) noexcept {
  const std::size_t n = b.size() - 1;
  const double g = (x - b[0]) * inv_step;
  std::size_t i = 0;
  if (g >= static_cast<double>(n)) {
    i = n - 1;
  } else if (g > 0.0) {
    i = static_cast<std::size_t>(g);
  }
  while (i > 0 && x < b[i]) {
    --i;
  }
  while (i + 1 < n && x >= b[i + 1]) {
    ++i;
  }
  return i;
}

}  // namespace

std::size_t EdgeGrid::column(double x) const noexcept {
  return locate_interval(xs_, inv_w_, x);
}
std::size_t EdgeGrid::row(double y) const noexcept {
  return locate_interval(ys_, inv_h_, y);
}

template <class F>
void EdgeGrid::rasterize(std::uint32_t edge, F&& emit) const {
  const Point a = v_[edge];
  const Point b = v_[next_[edge]];
  const double xlo = std::min(a.x, b.x);
  const double xhi = std::max(a.x, b.x);
  const double ylo = std::min(a.y, b.y);
  const double yhi = std::max(a.y, b.y);
  const std::size_t i0 = column(xlo);
  const std::size_t i1 = column(xhi);
  if (i0 == i1) {
    for (std::size_t j = row(ylo), j1 = row(yhi); j <= j1; ++j) {
      emit(cell(i0, j));
    }
    return;
  }
  // The edge spans several columns. Over the exact x-range of column i (both ends are doubles),
  // the edge's y lies between its values at the two ends. We evaluate them in floating point as
  // y = a.y + t (b.y - a.y) with t = (x - a.x) / (b.x - a.x) in [0, 1] -- never a slope, which
  // overflows for steep edges (dx subnormal, or 1e-300 against 1e9) -- and widen by `margin`,
  // far above the rounding error (< 8 eps (|a.y| + |b.y|): the subtractions are exact when they
  // underflow, t carries 2 roundings, the product and the sum one each), so that the rows are a
  // superset of the exact ones. Clamping to the edge's own exact y-range keeps it tight.
  const double dx = b.x - a.x;
  const double dy = b.y - a.y;
  const double margin = 1e-14 * (std::abs(a.y) + std::abs(b.y)) + std::numeric_limits<double>::min();
  const auto y_at = [&](double x) {
    const double t = std::clamp((x - a.x) / dx, 0.0, 1.0);
    return a.y + t * dy;
  };
  for (std::size_t i = i0; i <= i1; ++i) {
    const double xa = std::max(xs_[i], xlo);
    const double xb = std::min(xs_[i + 1], xhi);
    const double ya = y_at(xa);
    const double yb = y_at(xb);
    const double lo = std::max(std::min(ya, yb) - margin, ylo);
    const double hi = std::min(std::max(ya, yb) + margin, yhi);
    for (std::size_t j = row(lo), j1 = row(hi); j <= j1; ++j) {
      emit(cell(i, j));
    }
  }
}

void EdgeGrid::build(std::span<const Point> vertices, std::span<const std::uint32_t> next, Box bounds,
                     std::size_t target_cells) {
  v_ = vertices;
  next_ = next;
  const double w = bounds.width();
  const double h = bounds.height();
  target_cells = std::max<std::size_t>(target_cells, 1);
  double nx = 1.0;
  double ny = 1.0;
  if (w > 0.0 && h > 0.0) {
    nx = std::max(1.0, std::round(std::sqrt(static_cast<double>(target_cells) * w / h)));
    ny = std::max(1.0, std::round(static_cast<double>(target_cells) / nx));
  } else if (w > 0.0) {
    nx = static_cast<double>(target_cells);
  } else if (h > 0.0) {
    ny = static_cast<double>(target_cells);
  }
  constexpr double max_side = 1 << 16;
  xs_ = boundaries(bounds.xmin, bounds.xmax, static_cast<std::size_t>(std::min(nx, max_side)));
  ys_ = boundaries(bounds.ymin, bounds.ymax, static_cast<std::size_t>(std::min(ny, max_side)));
  nx_ = xs_.size() - 1;
  ny_ = ys_.size() - 1;
  inv_w_ = w > 0.0 ? static_cast<double>(nx_) / w : 0.0;
  inv_h_ = h > 0.0 ? static_cast<double>(ny_) / h : 0.0;

  // Two passes (count, then fill) into compressed rows: one allocation, cache-friendly queries.
  const std::size_t cells = nx_ * ny_;
  cell_start_.assign(cells + 1, 0);
  const auto edges = static_cast<std::uint32_t>(vertices.size());
  for (std::uint32_t e = 0; e < edges; ++e) {
    rasterize(e, [&](std::size_t c) { ++cell_start_[c + 1]; });
  }
  for (std::size_t c = 0; c < cells; ++c) {
    cell_start_[c + 1] += cell_start_[c];
  }
  cell_edges_.resize(cell_start_[cells]);
  std::vector<std::uint32_t> fill(cell_start_.begin(), cell_start_.end() - 1);
  for (std::uint32_t e = 0; e < edges; ++e) {
    rasterize(e, [&](std::size_t c) { cell_edges_[fill[c]++] = e; });
  }
  state_.assign(cells, kMixed);
}

void EdgeGrid::append_row_edges(std::size_t i, std::size_t k, std::size_t j, std::vector<std::uint32_t>& out) const {
  const auto first = static_cast<std::ptrdiff_t>(out.size());
  for (std::size_t c = i; c < k; ++c) {
    const auto list = edges_of(cell(c, j));
    out.insert(out.end(), list.begin(), list.end());
  }
  std::sort(out.begin() + first, out.end());
  out.erase(std::unique(out.begin() + first, out.end()), out.end());
}

bool EdgeGrid::crosses_right_of(std::uint32_t e, Point p, Point& lo, Point& hi) const {
  lo = v_[e];
  hi = v_[next_[e]];
  if ((lo.y > p.y) == (hi.y > p.y)) {
    return false;  // half-open rule: exactly one endpoint strictly above the line
  }
  if (lo.y > hi.y) {
    std::swap(lo, hi);
  }
  return orientation(lo, hi, p) > 0;  // p is left of the upward edge
}

bool EdgeGrid::odd_crossings(Point p, std::size_t i, std::size_t k, std::size_t j,
                             std::vector<std::uint32_t>& scratch) const {
  scratch.clear();
  append_row_edges(i, k, j, scratch);
  const Point t{xs_[std::min(k, nx_)], p.y};
  bool odd = false;
  for (const std::uint32_t e : scratch) {
    Point lo;
    Point hi;
    // The crossing lies strictly between p and t: right of p, left of t.
    if (crosses_right_of(e, p, lo, hi) && orientation(lo, hi, t) < 0) {
      odd = !odd;
    }
  }
  return odd;
}

bool EdgeGrid::odd_crossings_up(Point p, std::size_t i, std::size_t j, std::size_t m,
                                std::vector<std::uint32_t>& scratch) const {
  scratch.clear();
  for (std::size_t r = j; r < m; ++r) {
    const auto list = edges_of(cell(i, r));
    scratch.insert(scratch.end(), list.begin(), list.end());
  }
  std::sort(scratch.begin(), scratch.end());
  scratch.erase(std::unique(scratch.begin(), scratch.end()), scratch.end());
  const Point t{p.x, ys_[std::min(m, ny_)]};
  bool odd = false;
  for (const std::uint32_t e : scratch) {
    Point lo = v_[e];
    Point hi = v_[next_[e]];
    if ((lo.x > p.x) == (hi.x > p.x)) {
      continue;  // half-open rule: exactly one endpoint strictly right of the line
    }
    if (lo.x > hi.x) {
      std::swap(lo, hi);
    }
    // The crossing lies strictly between p and t: p below the rightward edge, t above it.
    if (orientation(lo, hi, p) < 0 && orientation(lo, hi, t) > 0) {
      odd = !odd;
    }
  }
  return odd;
}

void EdgeGrid::classify_cells() {
  std::vector<std::uint32_t> scratch;
  for (std::size_t c = 0; c < nx_ * ny_; ++c) {
    state_[c] = cell_start_[c] == cell_start_[c + 1] ? kOutside : kMixed;
  }
  // Right to left along each row: an empty cell's corner (X[i], Y[j]) takes the state of the
  // next empty cell's corner to its right (or "outside" beyond the last column), flipped by the
  // parity of the edges crossed in between. Every edge is visited once per row it is listed in.
  for (std::size_t j = 0; j < ny_; ++j) {
    std::uint8_t right_state = kOutside;
    std::size_t right = nx_;
    for (std::size_t i = nx_; i-- > 0;) {
      const std::size_t c = cell(i, j);
      if (state_[c] == kMixed) {
        continue;
      }
      const bool odd = odd_crossings(Point{xs_[i], ys_[j]}, i + 1, right, j, scratch);
      state_[c] = ((right_state == kInside) != odd) ? kInside : kOutside;
      right_state = state_[c];
      right = i;
    }
  }
}

Location EdgeGrid::locate_in(Point p, std::size_t i, std::size_t j) const {
  const std::size_t c = cell(i, j);
  if (state_[c] != kMixed) {
    return state_[c] == kInside ? Location::inside : Location::outside;
  }
  for (const std::uint32_t e : edges_of(c)) {
    if (on_segment(p, v_[e], v_[next_[e]])) {
      return Location::boundary;
    }
  }
  // A cell of known state is sought to the right and upwards at once, and the shorter walk
  // wins: along a sliver (a spike a million times longer than wide) every cell of its row is
  // mixed, but the cells above it are not.
  std::size_t k = i + 1;  // right: cells [i, k) of row j are mixed
  std::size_t m = j + 1;  // up: cells [j, m) of column i are mixed
  for (;;) {
    if (k >= nx_ || state_[cell(k, j)] != kMixed) {
      const bool target_inside = k < nx_ && state_[cell(k, j)] == kInside;
      thread_local std::vector<std::uint32_t> scratch;
      const bool odd = odd_crossings(p, i, k, j, scratch);
      return (target_inside != odd) ? Location::inside : Location::outside;
    }
    if (m >= ny_ || state_[cell(i, m)] != kMixed) {
      const bool target_inside = m < ny_ && state_[cell(i, m)] == kInside;
      thread_local std::vector<std::uint32_t> scratch;
      const bool odd = odd_crossings_up(p, i, j, m, scratch);
      return (target_inside != odd) ? Location::inside : Location::outside;
    }
    ++k;
    ++m;
  }
}

Location EdgeGrid::locate(Point p) const {
  if (!(p.x >= xs_.front() && p.x < xs_.back() && p.y >= ys_.front() && p.y < ys_.back())) {
    return Location::outside;  // also NaN
  }
  return locate_in(p, column(p.x), row(p.y));
}

bool EdgeGrid::contains(const Disk& disk) const {
  const Point c = disk.centre;
  const double r = disk.radius;
  if (!(r >= 0.0) || !std::isfinite(r) || !std::isfinite(c.x) || !std::isfinite(c.y)) {
    return false;
  }
  // Cells meeting the disk's bounding box; the bounds are rounded outwards (one step beyond the
  // rounded value), so the range covers the exact box.
  const std::size_t i0 = column(next_down(c.x - r));
  const std::size_t i1 = column(next_up(c.x + r));
  const std::size_t j0 = row(next_down(c.y - r));
  const std::size_t j1 = row(next_up(c.y + r));
  bool all_inside = true;
  for (std::size_t j = j0; j <= j1 && all_inside; ++j) {
    for (std::size_t i = i0; i <= i1; ++i) {
      if (state_[cell(i, j)] != kInside) {
        all_inside = false;
        break;
      }
    }
  }
  if (all_inside) {
    return true;  // cells on the grid's border are never "inside", so no clamping happened
  }
  const Location at = locate(c);
  if (at == Location::outside) {
    return false;
  }
  if (r == 0.0) {
    return true;
  }
  if (at == Location::boundary) {
    return false;
  }
  // The centre is inside; the disk stays inside unless an edge comes closer than r.
  for (std::size_t j = j0; j <= j1; ++j) {
    for (std::size_t i = i0; i <= i1; ++i) {
      for (const std::uint32_t e : edges_of(cell(i, j))) {
        if (compare_distance_to_segment(c, v_[e], v_[next_[e]], r) == CGAL::SMALLER) {
          return false;
        }
      }
    }
  }
  return true;
}

std::size_t EdgeGrid::ray_cost(Point p) const noexcept {
  if (!(p.y >= ys_.front() && p.y < ys_.back()) || !(p.x < xs_.back())) {
    return 0;
  }
  const std::size_t i = column(p.x);
  const std::size_t j = row(p.y);
  return (nx_ - i) + (cell_start_[cell(0, j) + nx_] - cell_start_[cell(i, j)]);
}

void EdgeGrid::edges_crossing_ray(Point p, std::vector<std::uint32_t>& out) const {
  if (!(p.y >= ys_.front() && p.y < ys_.back()) || !(p.x < xs_.back())) {
    return;
  }
  const std::size_t first = out.size();
  append_row_edges(column(p.x), nx_, row(p.y), out);
  std::size_t kept = first;
  for (std::size_t n = first; n < out.size(); ++n) {
    Point lo;
    Point hi;
    if (crosses_right_of(out[n], p, lo, hi)) {
      out[kept++] = out[n];
    }
  }
  out.resize(kept);
}

}  // namespace frontpack::detail
