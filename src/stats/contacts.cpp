// Contacts between disks and with the walls, within a tolerance (floating point: measurements).
#include <algorithm>
#include <cmath>
#include <cstdint>

#include "common/bucket_grid.hpp"
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
  GridFrame frame;
  frame.inv_x = frame.inv_y = 1 / h;
  frame.x0 = b.xmin - s.sizes.rmax - tol;
  frame.y0 = b.ymin - s.sizes.rmax - tol;
  frame.nx = axis_cells(w * frame.inv_x, kMaxAxisCells);
  frame.ny = axis_cells(ht * frame.inv_y, kMaxAxisCells);
  const auto box_of = [tol](const Disk& d) {
    const double e = d.radius + tol / 2;
    return Box{d.centre.x - e, d.centre.y - e, d.centre.x + e, d.centre.y + e};
  };
  BucketGrid<std::uint32_t, std::size_t> grid;
  grid.build_boxes(frame, n, [&](std::size_t k) { return box_of(disks[k]); });
  for (std::size_t c = 0; c < frame.cells(); ++c) {
    detail::throw_if_stopped(stop, c);
    const std::span<const std::uint32_t> members = grid.items(c);
    for (std::size_t p = 0; p < members.size(); ++p) {
      const Disk& a = disks[members[p]];
      const Box ba = box_of(a);
      for (std::size_t q = p + 1; q < members.size(); ++q) {
        const Disk& d = disks[members[q]];
        const Box bd = box_of(d);
        if (ba.xmax < bd.xmin || bd.xmax < ba.xmin || ba.ymax < bd.ymin || bd.ymax < ba.ymin) {
          continue;
        }
        if (frame.cell_of({std::max(ba.xmin, bd.xmin), std::max(ba.ymin, bd.ymin)}) != c) {
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
