// Certification: exact containment (Domain::contains, through its edge grid) and the global
// overlap pass (CGAL::box_self_intersection_d + an exact pair predicate).
#include <CGAL/AABB_segment_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Bbox_2.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/box_intersection_d.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "certify/certify.hpp"
#include "exact/predicates.hpp"
#include "common/float_bits.hpp"
#include "common/stop.hpp"
#include "frontpack/certify.hpp"

namespace frontpack {

namespace detail {

namespace {

// Runs CGAL::box_self_intersection_d over the disks listed in `batch` (the first `own` are one
// tile's, the rest guests from its neighbours), with boxes of number type NT (float halves the
// memory and speeds the sweep; used when every coordinate fits a float), each rounded outwards so
// that the exact box [x - r, x + r] x [y - r, y + r] lies inside it. A box's handle points at its
// disk's copy in `local` (a buffer reused from tile to tile), in batch order: its position there
// gives the disk's index (through `batch`) and whether it is a guest.
//
// Far from the origin a float cannot tell nearby disks apart (at 8e9 its step is 1024): float boxes
// are taken relative to `origin` (the smallest centre coordinates), widened by a bound on the
// rounding of the two subtractions, so that they stay tight there too.
template <class NT>
void box_pass(std::span<const Disk> disks, const std::vector<std::uint32_t>& batch, std::size_t own,
              std::vector<std::pair<std::size_t, std::size_t>>& out, std::size_t& candidates, Point origin,
              std::vector<Disk>& local) {
  using Box = CGAL::Box_intersection_d::Box_with_handle_d<NT, 2, const Disk*, CGAL::Box_intersection_d::ID_FROM_HANDLE>;
  constexpr NT inf = std::numeric_limits<NT>::infinity();
  // One step below the rounded difference is below the exact one; converting to float rounds to
  // nearest, so one more float step down keeps it below.
  const auto down = [](double v) { return std::nextafter(static_cast<NT>(next_down(v)), -inf); };
  const auto up = [](double v) { return std::nextafter(static_cast<NT>(next_up(v)), inf); };
  // The batch's disks copied out in batch order: the sweep reports pairs in no order, and the
  // pair test then reads this tile's copies instead of disks anywhere in the packing (a packing
  // whose disks were placed in voids all over the domain, the boundary method's, is in no
  // spatial order).
  local.clear();
  for (const std::uint32_t i : batch) {
    local.push_back(disks[i]);
  }
  std::vector<Box> boxes;
  boxes.reserve(batch.size());
  // (c - r) - o rounds twice, each time by at most 2^-53 of a magnitude below |c| + r + |o|.
  const auto err = [](double c, double r, double o) { return 0x1p-51 * (std::abs(c) + r + std::abs(o)); };
  for (const Disk& d : local) {
    const double x = d.centre.x;
    const double y = d.centre.y;
    const double r = d.radius;
    NT lo[2] = {down(((x - r) - origin.x) - err(x, r, origin.x)), down(((y - r) - origin.y) - err(y, r, origin.y))};
    NT hi[2] = {up(((x + r) - origin.x) + err(x, r, origin.x)), up(((y + r) - origin.y) + err(y, r, origin.y))};
    boxes.emplace_back(lo, hi, &d);
  }
  const Disk* guests = local.data() + own;
  // A cutoff of 4000 measured fastest for this use (docs/design-notes.md).
  CGAL::box_self_intersection_d(
      boxes.begin(), boxes.end(),
      [&](const Box& a, const Box& b) {
        if (a.handle() >= guests && b.handle() >= guests) {
          return;  // both guests: their own tile's pass decides them
        }
        ++candidates;
        const Disk& p = *a.handle();
        const Disk& q = *b.handle();
        if (compare_centre_distance(p.centre, q.centre, p.radius, q.radius) == CGAL::SMALLER) {
          const std::size_t i = batch[static_cast<std::size_t>(&p - local.data())];
          const std::size_t j = batch[static_cast<std::size_t>(&q - local.data())];
          out.emplace_back(std::min(i, j), std::max(i, j));
        }
      },
      std::ptrdiff_t{4000});
}

}  // namespace

void contains(const Domain& domain, std::span<const Disk> disks, std::span<std::uint8_t> inside,
              const std::stop_token& stop) {
  constexpr std::size_t kBlock = std::size_t{1} << 16;
  for (std::size_t begin = 0; begin < disks.size(); begin += kBlock) {
    throw_if_stopped(stop);
    const std::size_t n = std::min(kBlock, disks.size() - begin);
    domain.contains(disks.subspan(begin, n), inside.subspan(begin, n));
  }
}

void overlapping_pairs(std::span<const Disk> disks, std::vector<std::pair<std::size_t, std::size_t>>& out,
                       std::size_t& candidates, const std::stop_token& stop) {
  out.clear();
  candidates = 0;
  // Square-ish tiles at least 2 rmax wide and high (rmax: the largest radius), so that
  // overlapping disks have their centres in the same or neighbouring tiles. Each tile is searched
  // with guests from half of its neighbours -- right, upper left, up, upper right -- so that every
  // pair of neighbouring tiles is searched once; a guest joins if its box meets the box of the
  // tile's own disks, and pairs of two guests are left to their own tiles. Each CGAL run sees
  // about kChunk disks: linear time overall, and box memory for one tile at a time. (Thin strips
  // instead of tiles measured slower: CGAL's sweep prefers square batches. With the batch's disks
  // copied out, 2^17 measured as fast as 2^18 without its 7 bytes per disk more peak memory at 1M
  // disks, and 2^16, 2^15 and 2^13 slower; docs/performance.md.)
  constexpr std::size_t kChunk = std::size_t{1} << 17;
  Box all;
  double rmax = 0;
  bool fits_float = true;
  std::size_t live = 0;
  const auto takes_part = [](const Disk& d) {
    return std::isfinite(d.centre.x) && std::isfinite(d.centre.y) && std::isfinite(d.radius) && d.radius >= 0;
  };
  for (const Disk& d : disks) {
    if (!takes_part(d)) {
      continue;
    }
    ++live;
    all.extend(d.centre);
    rmax = std::max(rmax, d.radius);
    fits_float = fits_float && std::abs(d.centre.x) + d.radius < 1e30 && std::abs(d.centre.y) + d.radius < 1e30;
  }
  if (live == 0) {
    return;
  }
  const double wanted = std::max(1.0, static_cast<double>(live) / kChunk);
  const double W = all.width();
  const double H = all.height();
  const double min_side = 2.0 * rmax * (1 + 1e-9);
  double side = std::sqrt(W * H / wanted);
  if (!(side > min_side) || !std::isfinite(side)) {
    side = std::max(min_side, std::max(W, H) / wanted);
  }
  if (!(side > 0)) {
    side = 1;  // all centres coincide and every radius is 0
  }
  // (An infinite side, for radii beyond about 9e307, is one tile: side = 1 made it 10^12 of them.)
  const auto tiles_along = [side](double extent) {
    return static_cast<std::size_t>(std::min(1e6, std::floor(extent / side))) + 1;
  };
  const std::size_t tx = tiles_along(W);
  const std::size_t ty = tiles_along(H);
  const auto tile_of = [&](const Disk& d) {
    const auto i = std::min(tx - 1, static_cast<std::size_t>(std::max(0.0, (d.centre.x - all.xmin) / side)));
    const auto j = std::min(ty - 1, static_cast<std::size_t>(std::max(0.0, (d.centre.y - all.ymin) / side)));
    return j * tx + i;
  };
  // Counting sort of the disks by tile (stable: keeps generation order within a tile).
  std::vector<std::uint32_t> start(tx * ty + 1, 0);
  for (const Disk& d : disks) {
    if (takes_part(d)) {
      ++start[tile_of(d) + 1];
    }
  }
  for (std::size_t t = 0; t < tx * ty; ++t) {
    start[t + 1] += start[t];
  }
  std::vector<std::uint32_t> order(live);
  {
    std::vector<std::uint32_t> fill(start.begin(), start.end() - 1);
    for (std::size_t i = 0; i < disks.size(); ++i) {
      if (takes_part(disks[i])) {
        order[fill[tile_of(disks[i])]++] = static_cast<std::uint32_t>(i);
      }
    }
  }
  std::vector<std::uint32_t> batch;
  std::vector<Disk> local;
  for (std::size_t j = 0; j < ty; ++j) {
    for (std::size_t i = 0; i < tx; ++i) {
      const std::size_t t = j * tx + i;
      batch.assign(order.begin() + start[t], order.begin() + start[t + 1]);
      const std::size_t own = batch.size();
      if (own == 0) {
        continue;
      }
      throw_if_stopped(stop);
      Box extent;  // of the own disks' boxes
      for (const std::uint32_t k : batch) {
        const Disk& d = disks[k];
        extent.extend(Point{d.centre.x - d.radius, d.centre.y - d.radius});
        extent.extend(Point{d.centre.x + d.radius, d.centre.y + d.radius});
      }
      const double slack =
          0x1p-50 * (std::abs(extent.xmin) + std::abs(extent.xmax) + std::abs(extent.ymin) + std::abs(extent.ymax));
      const auto guest_tile = [&](std::ptrdiff_t di, std::ptrdiff_t dj) {
        const std::ptrdiff_t gi = static_cast<std::ptrdiff_t>(i) + di;
        const std::ptrdiff_t gj = static_cast<std::ptrdiff_t>(j) + dj;
        if (gi < 0 || gj < 0 || gi >= static_cast<std::ptrdiff_t>(tx) || gj >= static_cast<std::ptrdiff_t>(ty)) {
          return;
        }
        const std::size_t g = static_cast<std::size_t>(gj) * tx + static_cast<std::size_t>(gi);
        for (std::size_t m = start[g]; m < start[g + 1]; ++m) {
          const Disk& d = disks[order[m]];
          if (d.centre.x - d.radius <= extent.xmax + slack && d.centre.x + d.radius >= extent.xmin - slack &&
              d.centre.y - d.radius <= extent.ymax + slack && d.centre.y + d.radius >= extent.ymin - slack) {
            batch.push_back(order[m]);
          }
        }
      };
      guest_tile(1, 0);
      guest_tile(-1, 1);
      guest_tile(0, 1);
      guest_tile(1, 1);
      if (fits_float) {
        box_pass<float>(disks, batch, own, out, candidates, Point{all.xmin, all.ymin}, local);
      } else {
        box_pass<double>(disks, batch, own, out, candidates, Point{0, 0}, local);
      }
    }
  }
  std::sort(out.begin(), out.end());
}

}  // namespace detail

namespace {

// The "how bad" figures of a report, in floating point from the exact decisions. The distance
// from a centre to the boundary comes from an AABB tree of the domain's edges (CGAL 5.5's tree is
// 3D: the edges lie in the plane z = 0), built only when some disk is outside.
void measure_worst(const Domain& domain, std::span<const Disk> disks, CertifyReport& report) {
  for (const auto& [i, j] : report.overlapping) {
    const Disk& a = disks[i];
    const Disk& b = disks[j];
    const double depth = a.radius + b.radius - std::hypot(a.centre.x - b.centre.x, a.centre.y - b.centre.y);
    if (!report.deepest_overlap || depth > report.deepest_overlap_depth) {
      report.deepest_overlap = std::make_pair(i, j);
      report.deepest_overlap_depth = depth;
    }
  }
  if (report.outside.empty()) {
    return;
  }
  using K = CGAL::Simple_cartesian<double>;
  using Segments = std::vector<K::Segment_3>;
  using Tree = CGAL::AABB_tree<CGAL::AABB_traits<K, CGAL::AABB_segment_primitive<K, Segments::const_iterator>>>;
  Segments edges;
  const auto add_ring = [&edges](const Ring& ring) {
    for (std::size_t k = 0; k < ring.size(); ++k) {
      const Point& p = ring[k];
      const Point& q = ring[(k + 1) % ring.size()];
      edges.emplace_back(K::Point_3(p.x, p.y, 0), K::Point_3(q.x, q.y, 0));
    }
  };
  for (const Polygon& polygon : domain.polygons()) {
    add_ring(polygon.outer);
    for (const Ring& hole : polygon.holes) {
      add_ring(hole);
    }
  }
  Tree tree(edges.cbegin(), edges.cend());
  tree.accelerate_distance_queries();
  for (const std::size_t i : report.outside) {
    const Disk& d = disks[i];
    double by = std::numeric_limits<double>::infinity();
    if (std::isfinite(d.centre.x) && std::isfinite(d.centre.y) && std::isfinite(d.radius) && d.radius >= 0) {
      const double distance = std::sqrt(tree.squared_distance(K::Point_3(d.centre.x, d.centre.y, 0)));
      by = domain.locate(d.centre) == Location::inside ? d.radius - distance : d.radius + distance;
    }
    if (!report.farthest_outside || by > report.farthest_outside_by) {
      report.farthest_outside = i;
      report.farthest_outside_by = by;
    }
  }
}

}  // namespace

CertifyReport certify(const Domain& domain, std::span<const Disk> disks, std::stop_token stop) {
  CertifyReport report;
  std::vector<std::uint8_t> inside(disks.size());
  detail::contains(domain, disks, inside, stop);
  for (std::size_t i = 0; i < disks.size(); ++i) {
    if (inside[i] == 0) {
      report.outside.push_back(i);
    }
  }
  detail::overlapping_pairs(disks, report.overlapping, report.certificate.candidate_pairs, stop);
  report.certificate.generated = disks.size();
  report.certificate.culled = report.outside.size();
  report.certificate.exact = true;
  measure_worst(domain, disks, report);
  return report;
}

}  // namespace frontpack
