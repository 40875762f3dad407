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
  inv_side_ = 1 / side_;
  x0_ = b.xmin;
  y0_ = b.ymin;
  nx_ = axis_cells(std::ceil(w * inv_side_) - 1, kMaxAxisCells);
  ny_ = axis_cells(std::ceil(h * inv_side_) - 1, kMaxAxisCells);
  start_.assign(nx_ * ny_ + 1, 0);
  const auto cells = [&](const Disk& d, auto&& f) {
    const std::size_t i0 = column(d.centre.x - d.radius);
    const std::size_t i1 = column(d.centre.x + d.radius);
    const std::size_t j0 = row(d.centre.y - d.radius);
    const std::size_t j1 = row(d.centre.y + d.radius);
    for (std::size_t j = j0; j <= j1; ++j) {
      for (std::size_t i = i0; i <= i1; ++i) {
        f(j * nx_ + i);
      }
    }
  };
  for (const Disk& d : disks) {
    cells(d, [this](std::size_t c) { ++start_[c + 1]; });
  }
  for (std::size_t c = 0; c < nx_ * ny_; ++c) {
    start_[c + 1] += start_[c];
  }
  members_.resize(start_.back());
  std::vector<std::size_t> fill(start_.begin(), start_.end() - 1);
  for (std::size_t k = 0; k < disks.size(); ++k) {
    cells(disks[k], [&](std::size_t c) { members_[fill[c]++] = static_cast<std::uint32_t>(k); });
  }
}

std::size_t Clearance::column(double x) const noexcept {
  return cell_index(x, x0_, inv_side_, nx_);
}

std::size_t Clearance::row(double y) const noexcept {
  return cell_index(y, y0_, inv_side_, ny_);
}

Square Clearance::cell(std::size_t i, std::size_t j) const noexcept {
  const double a = side_ / 2;
  return Square{x0_ + (static_cast<double>(i) + 0.5) * side_, y0_ + (static_cast<double>(j) + 0.5) * side_, a};
}

void Clearance::block(std::size_t i, std::size_t j, std::vector<std::uint32_t>& out) const {
  out.clear();
  if (++stamp_now_ == 0) {  // wrapped: forget the old stamps
    std::fill(stamp_.begin(), stamp_.end(), 0);
    stamp_now_ = 1;
  }
  for (std::size_t jj = j == 0 ? 0 : j - 1; jj <= std::min(j + 1, ny_ - 1); ++jj) {
    for (std::size_t ii = i == 0 ? 0 : i - 1; ii <= std::min(i + 1, nx_ - 1); ++ii) {
      const std::size_t c = jj * nx_ + ii;
      for (std::size_t m = start_[c]; m < start_[c + 1]; ++m) {
        const std::uint32_t k = members_[m];
        if (stamp_[k] != stamp_now_) {
          stamp_[k] = stamp_now_;
          out.push_back(k);
        }
      }
    }
  }
}

double Clearance::disk_distance(Point p, double cap) const {
  const std::size_t ci = column(p.x);
  const std::size_t cj = row(p.y);
  double best = cap;
  const auto visit = [&](std::size_t i, std::size_t j) {
    const std::size_t c = j * nx_ + i;
    for (std::size_t m = start_[c]; m < start_[c + 1]; ++m) {
      const Disk& d = disks_[members_[m]];
      const double dx = p.x - d.centre.x;
      const double dy = p.y - d.centre.y;
      const double d2 = dx * dx + dy * dy;
      if (const double t = best + d.radius; t > 0 && d2 < t * t) {
        best = std::sqrt(d2) - d.radius;
      }
    }
  };
  const std::size_t reach = std::max(nx_, ny_);
  for (std::size_t k = 0; k <= reach; ++k) {
    visit_ring(ci, cj, k, nx_, ny_, visit);
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
