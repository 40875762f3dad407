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

EdgeDistanceIndex::EdgeDistanceIndex(const Domain& domain) {
  add_walls(domain);
  build_tree();
}

EdgeDistanceIndex::EdgeDistanceIndex(const Domain& domain, double h) : EdgeDistanceIndex(domain) {
  build_grid(domain, h);
}

void EdgeDistanceIndex::build_tree() {
  if (a_.empty()) {
    return;
  }
  double largest = 0;
  std::vector<Point> mid(a_.size());
  order_.resize(a_.size());
  for (std::size_t e = 0; e < a_.size(); ++e) {
    mid[e] = {0.5 * a_[e].x + 0.5 * b_[e].x, 0.5 * a_[e].y + 0.5 * b_[e].y};
    order_[e] = static_cast<std::uint32_t>(e);
    largest = std::max({largest, std::abs(a_[e].x), std::abs(a_[e].y), std::abs(b_[e].x), std::abs(b_[e].y)});
  }
  // A closest point a + t (b - a) and its distance are each within a few ulps of the largest
  // coordinate of the truth; 2^-46 of it is a hundred times that (and 64 subnormal steps).
  margin_ = 0x1p-46 * largest + 0x1p-1068;
  nodes_.reserve(2 * (a_.size() / kLeafEdges + 1));
  build_node(0, static_cast<std::uint32_t>(a_.size()), mid);
}

std::uint32_t EdgeDistanceIndex::build_node(std::uint32_t begin, std::uint32_t end, std::vector<Point>& mid) {
  const auto at = static_cast<std::uint32_t>(nodes_.size());
  Box box{a_[order_[begin]].x, a_[order_[begin]].y, a_[order_[begin]].x, a_[order_[begin]].y};
  Box mids{mid[order_[begin]].x, mid[order_[begin]].y, mid[order_[begin]].x, mid[order_[begin]].y};
  for (std::uint32_t k = begin; k < end; ++k) {
    const std::uint32_t e = order_[k];
    for (const Point p : {a_[e], b_[e]}) {
      box = {std::min(box.xmin, p.x), std::min(box.ymin, p.y), std::max(box.xmax, p.x), std::max(box.ymax, p.y)};
    }
    const Point m = mid[e];
    mids = {std::min(mids.xmin, m.x), std::min(mids.ymin, m.y), std::max(mids.xmax, m.x), std::max(mids.ymax, m.y)};
  }
  // The capsule's chord: the endpoints first and last along the box's longer side.
  const bool wide = box.width() >= box.height();
  Point c0 = a_[order_[begin]];
  Point c1 = c0;
  for (std::uint32_t k = begin; k < end; ++k) {
    for (const Point p : {a_[order_[k]], b_[order_[k]]}) {
      c0 = (wide ? p.x < c0.x : p.y < c0.y) ? p : c0;
      c1 = (wide ? p.x > c1.x : p.y > c1.y) ? p : c1;
    }
  }
  double rho = 0;
  for (std::uint32_t k = begin; k < end; ++k) {
    for (const Point p : {a_[order_[k]], b_[order_[k]]}) {
      const Point q = closest_on(c0, c1, p);
      rho = std::max(rho, std::hypot(q.x - p.x, q.y - p.y));
    }
  }
  nodes_.push_back({box, c0, c1, rho, begin, end, 0});
  if (end - begin <= kLeafEdges) {
    return at;
  }
  // Halves by count at the median midpoint along the longer side of the midpoints' box: the
  // depth is log2(E / 4), whatever the edges' lengths.
  const std::uint32_t half = begin + (end - begin) / 2;
  const bool by_x = mids.width() >= mids.height();
  std::nth_element(order_.begin() + begin, order_.begin() + half, order_.begin() + end,
                   [&mid, by_x](std::uint32_t u, std::uint32_t v) {
                     const Point p = mid[u];
                     const Point q = mid[v];
                     return by_x ? (p.x != q.x ? p.x < q.x : u < v) : (p.y != q.y ? p.y < q.y : u < v);
                   });
  build_node(begin, half, mid);
  const std::uint32_t right = build_node(half, end, mid);
  nodes_[at].right = right;
  return at;
}

double EdgeDistanceIndex::distance(Point p, double cap) const {
  double best = cap;
  if (nodes_.empty()) {
    return best;
  }
  // Depth first, the nearer child first; a box whose lower bound is no smaller than the best
  // holds no edge that could lower it. The depth is at most 32 (4 2^32 edges), so the stack of
  // pending right-hand boxes holds at most 33.
  struct Pending {
    std::uint32_t node;
    double bound;
  };
  Pending stack[64];
  std::size_t top = 0;
  stack[top++] = {0, lower_bound(nodes_[0], p)};
  while (top > 0) {
    const Pending n = stack[--top];
    if (n.bound >= best) {
      continue;
    }
    const Node& node = nodes_[n.node];
    if (node.right == 0) {
      for (std::uint32_t k = node.begin; k < node.end; ++k) {
        const Point q = closest(order_[k], p);
        best = std::min(best, std::hypot(q.x - p.x, q.y - p.y));
      }
      continue;
    }
    const std::uint32_t l = n.node + 1;
    const std::uint32_t r = node.right;
    const double bl = lower_bound(nodes_[l], p);
    const double br = lower_bound(nodes_[r], p);
    if (bl <= br) {
      stack[top++] = {r, br};
      stack[top++] = {l, bl};
    } else {
      stack[top++] = {l, bl};
      stack[top++] = {r, br};
    }
  }
  return best;
}

void EdgeDistanceIndex::collect(Point p, double d, std::vector<std::uint32_t>& out) const {
  if (nodes_.empty()) {
    return;
  }
  std::uint32_t stack[64];
  std::size_t top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const std::uint32_t at = stack[--top];
    const Node& node = nodes_[at];
    if (lower_bound(node, p) > d) {
      continue;
    }
    if (node.right == 0) {
      for (std::uint32_t k = node.begin; k < node.end; ++k) {
        const Point q = closest(order_[k], p);
        const double dist = std::hypot(q.x - p.x, q.y - p.y);
        // (The margin again: the caller judges an edge at d by its own arithmetic.)
        if (dist - (margin_ + 0x1p-46 * (std::abs(p.x) + std::abs(p.y))) <= d) {
          out.push_back(order_[k]);
        }
      }
      continue;
    }
    stack[top++] = node.right;
    stack[top++] = at + 1;
  }
}

void EdgeDistanceIndex::build_grid(const Domain& domain, double h) {
  const Box b = domain.bbox();
  // At most about 4 million cells (and at least one).
  const double area = std::max(b.width() * b.height(), 0.0);
  h = std::max(h, std::sqrt(area / 4e6));
  h_ = h > 0 ? h : 1;
  frame_.inv_x = frame_.inv_y = 1 / h_;
  frame_.x0 = b.xmin;
  frame_.y0 = b.ymin;
  frame_.nx = axis_cells(b.width() * frame_.inv_x, kMaxAxisCells);
  frame_.ny = axis_cells(b.height() * frame_.inv_y, kMaxAxisCells);
  grid_.build(frame_.cells(), a_.size(), [this](std::size_t e, auto&& emit) { edge_cells(e, emit); });
}

}  // namespace frontpack::detail
