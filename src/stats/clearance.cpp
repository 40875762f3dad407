// The clearance f of a packing and its bounds on squares (stats/clearance.hpp).
#include "stats/clearance.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "common/grid_cells.hpp"

namespace frontpack::detail {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// A cell's contents are complete to 0.99 of the cell's side: the rest spares the rounding of the
// cell indices of points and disk boxes.
constexpr double kReach = 0.99;

}  // namespace

Clearance::Clearance(const Domain& domain, const DiskImages& images, const EdgeDistanceIndex& edges)
    : domain_(domain), periods_(domain), disks_(images.all()), edges_(edges), stamp_(images.all().size(), 0) {
  const std::span<const Disk> disks = images.all();
  const Box b = domain.bbox();
  const double w = b.width();
  const double h = b.height();
  double sum_r = 0;
  for (const Disk& d : disks.first(images.originals())) {
    sum_r += d.radius;
  }
  const double n = static_cast<double>(images.originals());
  // About one cell per disk in a dense packing, never more than 4 per disk (plus 16).
  const double mean_side = images.originals() == 0 ? 0 : 2 * sum_r / n;
  side_ = std::max(mean_side, std::sqrt(w * h / (4 * n + 16)));
  if (!(side_ > 0) || !std::isfinite(side_)) {
    side_ = std::max({w, h, 1e-300});
  }
  frame_.inv_x = frame_.inv_y = 1 / side_;
  frame_.x0 = b.xmin;
  frame_.y0 = b.ymin;
  frame_.nx = axis_cells(std::ceil(w * frame_.inv_x) - 1, kMaxAxisCells);
  frame_.ny = axis_cells(std::ceil(h * frame_.inv_y) - 1, kMaxAxisCells);
  members_.build_boxes(frame_, disks.size(), [&disks](std::size_t k) {
    const Disk& d = disks[k];
    return Box{d.centre.x - d.radius, d.centre.y - d.radius, d.centre.x + d.radius, d.centre.y + d.radius};
  });
}

Square Clearance::cell(std::size_t i, std::size_t j) const noexcept {
  const double a = side_ / 2;
  return Square{frame_.x0 + (static_cast<double>(i) + 0.5) * side_, frame_.y0 + (static_cast<double>(j) + 0.5) * side_,
                a};
}

void Clearance::block(std::size_t i, std::size_t j, std::vector<std::uint32_t>& out) const {
  out.clear();
  if (++stamp_now_ == 0) {  // wrapped: forget the old stamps
    std::fill(stamp_.begin(), stamp_.end(), 0);
    stamp_now_ = 1;
  }
  const std::size_t nx = frame_.nx;
  const std::size_t ny = frame_.ny;
  frame_.visit_block(i == 0 ? 0 : i - 1, std::min(i + 1, nx - 1), j == 0 ? 0 : j - 1, std::min(j + 1, ny - 1),
                     [&](std::size_t c) {
                       members_.visit(c, [&](std::uint32_t k) {
                         if (stamp_[k] != stamp_now_) {
                           stamp_[k] = stamp_now_;
                           out.push_back(k);
                         }
                       });
                     });
}

double Clearance::disk_distance(Point p, double cap) const {
  const std::size_t ci = column(p.x);
  const std::size_t cj = row(p.y);
  double best = cap;
  const auto visit = [&](std::size_t i, std::size_t j) {
    // By offsets, not by the cell's span: measured 11% faster on the 1M-edge statistics benchmark
    // (bench/stats_bench.cpp, MeasureEdges/1000000/10: 8.3 s against 9.3 s).
    const std::size_t c = j * frame_.nx + i;
    for (std::size_t e = members_.begin(c); e < members_.end(c); ++e) {
      const Disk& d = disks_[members_.item(e)];
      const double dx = p.x - d.centre.x;
      const double dy = p.y - d.centre.y;
      const double d2 = dx * dx + dy * dy;
      if (const double t = best + d.radius; t > 0 && d2 < t * t) {
        best = std::sqrt(d2) - d.radius;
      }
    }
  };
  const std::size_t reach = std::max(frame_.nx, frame_.ny);
  for (std::size_t k = 0; k <= reach; ++k) {
    visit_ring(ci, cj, k, frame_.nx, frame_.ny, visit);
    // A disk listed in no cell of the (2k + 1)-cell block misses the block: its surface is
    // farther than k cells from p.
    if (best <= (static_cast<double>(k) - 1e-6) * side_) {
      break;
    }
  }
  return best;
}

SquareBounds Clearance::bound(const Square& q, std::span<const std::uint32_t> list, Side known, double threshold,
                              std::vector<std::uint32_t>* keep) const {
  SquareBounds r;
  const double hd = q.half_diagonal();
  // The disks' part: v = min |c - c_i| - r_i at the centre, and the upper bound
  // min_i (farthest point of q from c_i) - r_i, no larger than v + hd.
  // (Square roots only for the disks that improve a minimum: sqrt(d2) - r < m exactly when
  // m + r > 0 and d2 < (m + r)^2.)
  double v = kInf;
  double upper = kInf;
  for (const std::uint32_t k : list) {
    const Disk& d = disks_[k];
    const double dx = std::abs(d.centre.x - q.x);
    const double dy = std::abs(d.centre.y - q.y);
    const double d2 = dx * dx + dy * dy;
    if (const double t = v + d.radius; t > 0 && d2 < t * t) {
      v = std::sqrt(d2) - d.radius;
    }
    const double ex = dx + q.a;
    const double ey = dy + q.a;
    const double e2 = ex * ex + ey * ey;
    if (const double t = upper + d.radius; t > 0 && e2 < t * t) {
      upper = std::sqrt(e2) - d.radius;
    }
  }
  if (upper < threshold) {
    r.pruned = true;
    r.upper = upper;
    return r;
  }
  // The boundary's part: the distance to the nearest edge, as far as it can matter (beyond
  // upper + hd it changes neither the value nor the bound, on either side).
  const double dist = edges_.distance({q.x, q.y}, upper + hd);
  if (!(v <= kReach * side_)) {
    // The list may miss the nearest disk: search the grid, as far as it can matter (a disk
    // farther than dist + hd changes neither the value, which the boundary then decides, nor the
    // bound, as f is 1-Lipschitz); v + hd bounds f on the square either way.
    v = disk_distance({q.x, q.y}, std::min(v, dist + hd));
    upper = std::min(upper, v + hd);
    if (upper < threshold) {
      r.pruned = true;
      r.upper = upper;
      return r;
    }
  }
  Side side = known;
  if (side == Side::unknown && std::min(v, dist) >= threshold) {
    const Location at = locate_wrapped(domain_, periods_, {q.x, q.y});
    side = at == Location::inside ? Side::inside : at == Location::outside ? Side::outside : Side::unknown;
    r.certain = true;  // on the boundary: f = min(v, 0)
  }
  const double signed_distance = side == Side::outside ? -dist : side == Side::inside ? dist : (r.certain ? 0 : dist);
  r.certain = r.certain || side != Side::unknown;
  r.value = std::min(v, signed_distance);
  upper = std::min(upper, signed_distance + hd);
  r.upper = upper;
  r.side = dist > hd ? side : Side::unknown;
  if (upper < threshold) {
    r.pruned = true;
    return r;
  }
  if (keep != nullptr) {
    keep->clear();
    for (const std::uint32_t k : list) {
      const Disk& d = disks_[k];
      const double dx = std::max(std::abs(d.centre.x - q.x) - q.a, 0.0);
      const double dy = std::max(std::abs(d.centre.y - q.y) - q.a, 0.0);
      if (const double t = upper + d.radius; t >= 0 && dx * dx + dy * dy <= t * t) {
        keep->push_back(k);
      }
    }
  }
  return r;
}

}  // namespace frontpack::detail
