// Contacts between disks and with the walls, within a tolerance (floating point: measurements).
#include <algorithm>
#include <cmath>
#include <cstdint>

#include "common/grid_cells.hpp"
#include "common/stop.hpp"
#include "stats/parts.hpp"

namespace frontpack::detail {

namespace {

// Whether the pair of disks a and d of images.all() is the one copy of their contact that counts.
bool counted(const DiskImages& images, std::size_t a, std::size_t d) noexcept {
  const std::size_t n = images.originals();
  if (a < n && d < n) {
    return true;
  }
  if (a >= n && d >= n) {
    return false;
  }
  const std::size_t original = std::min(a, d);
  const std::size_t image = std::max(a, d);
  const std::size_t source = images.source(image);
  return original < source || (original == source && images.positive_shift(image));
}

}  // namespace

// Disk-disk contacts. Each disk is listed in every cell its box, grown by half the tolerance,
// meets; a pair is examined only in the cell that holds the lower-left corner of the
// intersection of the two boxes, so once. Linear for any ratio of radii. In a periodic cell the
// images take part: a contact across a side is counted once, between a disk and the image of a
// later disk (or of itself, at a positive shift); the same contact between other copies of the
// two disks is a translate of that one.
void count_contacts(const DiskImages& images, double tol, PackingStats& s, std::vector<std::size_t>& degree,
                    const std::stop_token& stop) {
  const std::span<const Disk> disks = images.all();
  const std::size_t n = disks.size();
  Box b;
  double sum_r = 0;
  for (const Disk& d : disks) {
    b.extend(d.centre);
    sum_r += d.radius;
  }
  const double h0 = 4 * sum_r / static_cast<double>(n) + tol;
  const double w = b.width() + 2 * (s.sizes.rmax + tol);
  const double ht = b.height() + 2 * (s.sizes.rmax + tol);
  const double h = std::max(h0, std::sqrt(w * ht / (4.0 * static_cast<double>(n) + 16)));
  const double inv_h = 1 / h;
  const double x0 = b.xmin - s.sizes.rmax - tol;
  const double y0 = b.ymin - s.sizes.rmax - tol;
  const std::size_t nx = axis_cells(w * inv_h, kMaxAxisCells);
  const std::size_t ny = axis_cells(ht * inv_h, kMaxAxisCells);
  const auto box_of = [tol](const Disk& d) {
    const double e = d.radius + tol / 2;
    return Box{d.centre.x - e, d.centre.y - e, d.centre.x + e, d.centre.y + e};
  };
  std::vector<std::size_t> start(nx * ny + 1, 0);
  const auto cells = [&](const Box& bx, auto&& f) {
    const std::size_t i0 = cell_index(bx.xmin, x0, inv_h, nx);
    const std::size_t i1 = cell_index(bx.xmax, x0, inv_h, nx);
    const std::size_t j0 = cell_index(bx.ymin, y0, inv_h, ny);
    const std::size_t j1 = cell_index(bx.ymax, y0, inv_h, ny);
    for (std::size_t j = j0; j <= j1; ++j) {
      for (std::size_t i = i0; i <= i1; ++i) {
        f(j * nx + i);
      }
    }
  };
  for (const Disk& d : disks) {
    cells(box_of(d), [&start](std::size_t c) { ++start[c + 1]; });
  }
  for (std::size_t c = 0; c < nx * ny; ++c) {
    start[c + 1] += start[c];
  }
  std::vector<std::uint32_t> members(start.back());
  {
    std::vector<std::size_t> fill(start.begin(), start.end() - 1);
    for (std::size_t k = 0; k < n; ++k) {
      cells(box_of(disks[k]), [&](std::size_t c) { members[fill[c]++] = static_cast<std::uint32_t>(k); });
    }
  }
  for (std::size_t c = 0; c < nx * ny; ++c) {
    detail::throw_if_stopped(stop, c);
    for (std::size_t p = start[c]; p < start[c + 1]; ++p) {
      const Disk& a = disks[members[p]];
      const Box ba = box_of(a);
      for (std::size_t q = p + 1; q < start[c + 1]; ++q) {
        const Disk& d = disks[members[q]];
        const Box bd = box_of(d);
        if (ba.xmax < bd.xmin || bd.xmax < ba.xmin || ba.ymax < bd.ymin || bd.ymax < ba.ymin) {
          continue;
        }
        const std::size_t owner = cell_index(std::max(ba.ymin, bd.ymin), y0, inv_h, ny) * nx +
                                  cell_index(std::max(ba.xmin, bd.xmin), x0, inv_h, nx);
        if (owner != c) {
          continue;
        }
        const std::size_t ka = members[p];
        const std::size_t kd = members[q];
        if (!counted(images, ka, kd)) {
          continue;
        }
        const double gap = std::hypot(a.centre.x - d.centre.x, a.centre.y - d.centre.y) - a.radius - d.radius;
        if (gap <= tol) {
          ++s.contacts;
          ++degree[images.source(ka)];
          ++degree[images.source(kd)];
        }
        if (gap < -tol) {
          ++s.overlaps;
          s.max_overlap = std::max(s.max_overlap, -gap);
        }
      }
    }
  }
}

// Wall contacts of one disk: distinct closest points of the edges it touches.
std::size_t wall_contacts(const EdgeDistanceIndex& edges, const Disk& d, double tol) {
  std::vector<Point> points;
  edges.within(d.centre, d.radius + tol, [&](Point q, double dist) {
    if (dist - d.radius > tol) {
      return;
    }
    for (const Point& r : points) {
      if (std::hypot(r.x - q.x, r.y - q.y) <= tol + 1e-9 * d.radius) {
        return;
      }
    }
    points.push_back(q);
  });
  return points.size();
}

}  // namespace frontpack::detail
