// Cell coverage: the covered fraction of each square cell (of side 8 rmax by default) lying wholly
// in the interior, as a map and its percentiles, from the exact areas of the disks' intersections
// with the cells (in floating point; overlapping disks would count their common area twice).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <vector>

#include "common/budget.hpp"
#include "common/grid_cells.hpp"
#include "common/stop.hpp"
#include "stats/parts.hpp"

namespace frontpack::detail {

namespace {

// Area of the disk of radius r centred at the origin above the line y = h (h >= 0) and between
// x0 and x1 (x0 <= x1): the integral of sqrt(r^2 - x^2) - h over the part of [x0, x1] where the
// disk reaches above the line.
double area_above(double x0, double x1, double h, double r) {
  if (h >= r) {
    return 0;
  }
  // sqrt(r^2 - x^2) as sqrt((r - x)(r + x)), and asin(x / r) as atan2(x, that root): near the
  // ends of the chord both terms stay accurate (asin of a quotient near 1 would not).
  const auto root = [r](double x) { return std::sqrt(std::max((r - x) * (r + x), 0.0)); };
  const auto g = [&root, h, r](double x) {
    const double q = root(x);
    return 0.5 * (x * q + r * r * std::atan2(x, q)) - h * x;
  };
  const double s = root(h);
  const double a = std::clamp(x0, -s, s);
  const double b = std::clamp(x1, -s, s);
  return std::max(g(b) - g(a), 0.0);
}

// Area of the disk of radius r centred at the origin inside [x0, x1] x [y0, y1].
double area_in_box(double x0, double x1, double y0, double y1, double r) {
  if (y0 < 0 && y1 <= 0) {
    return area_in_box(x0, x1, -y1, -y0, r);
  }
  if (y0 < 0) {
    return area_in_box(x0, x1, 0, -y0, r) + area_in_box(x0, x1, 0, y1, r);
  }
  return std::max(area_above(x0, x1, y0, r) - area_above(x0, x1, y1, r), 0.0);
}

// The square cells over the bounding box, and each one's place in the list of interior cells
// (-1 for a cell that is not interior).
struct CellGrid {
  Box b;
  double side = 0;
  std::size_t nx = 1;
  std::size_t ny = 1;
  std::vector<std::int64_t> index;
};

// Marks the interior cells in g.index; returns their covered areas, all 0. A cell is interior
// when its centre is inside the domain and no edge comes within band_width plus the
// half-diagonal of it (with a relative margin of 1e-9 for the rounding of the distances): then
// the boundary misses the cell and every point of it is farther than w. In a periodic cell the
// edges are the walls alone and a periodic side drops no square: the squares go on across it, the
// last one wrapping around (it overlaps the first when the period is not a multiple of the side),
// and the images of the disks cover its part beyond the side.
std::vector<double> interior_cells(const Domain& domain, const EdgeDistanceIndex& edges, double w, CellGrid& g,
                                   const std::stop_token& stop) {
  const Periods periods(domain);
  const double reach = (w + g.side * std::numbers::sqrt2 / 2) * (1 + 1e-9);
  g.index.assign(g.nx * g.ny, -1);
  std::vector<double> covered;
  for (std::size_t c = 0; c < g.nx * g.ny; ++c) {
    throw_if_stopped(stop, c);
    const Point centre{g.b.xmin + (static_cast<double>(c % g.nx) + 0.5) * g.side,
                       g.b.ymin + (static_cast<double>(c / g.nx) + 0.5) * g.side};
    if (edges.distance(centre, reach) >= reach && locate_wrapped(domain, periods, centre) == Location::inside) {
      g.index[c] = static_cast<std::int64_t>(covered.size());
      covered.push_back(0);
    }
  }
  return covered;
}

// Adds each disk's area in each interior cell it meets.
void add_disk_areas(const CellGrid& g, std::span<const Disk> disks, std::vector<double>& covered,
                    const std::stop_token& stop) {
  const Box& b = g.b;
  const double side = g.side;
  const double inv = 1 / side;
  for (std::size_t k = 0; k < disks.size(); ++k) {
    throw_if_stopped(stop, k);
    const Disk& d = disks[k];
    const std::size_t i0 = cell_index(d.centre.x - d.radius, b.xmin, inv, g.nx);
    const std::size_t i1 = cell_index(d.centre.x + d.radius, b.xmin, inv, g.nx);
    const std::size_t j0 = cell_index(d.centre.y - d.radius, b.ymin, inv, g.ny);
    const std::size_t j1 = cell_index(d.centre.y + d.radius, b.ymin, inv, g.ny);
    for (std::size_t j = j0; j <= j1; ++j) {
      for (std::size_t i = i0; i <= i1; ++i) {
        const std::int64_t at = g.index[j * g.nx + i];
        if (at < 0) {
          continue;
        }
        const double x0 = b.xmin + static_cast<double>(i) * side - d.centre.x;
        const double y0 = b.ymin + static_cast<double>(j) * side - d.centre.y;
        const double x1 = x0 + side;
        const double y1 = y0 + side;
        const double r = d.radius;
        const bool whole = x0 <= -r && x1 >= r && y0 <= -r && y1 >= r;
        covered[static_cast<std::size_t>(at)] +=
            whole ? std::numbers::pi * r * r : area_in_box(x0, x1, std::min(y0, y1), std::max(y0, y1), r);
      }
    }
  }
}

// The covered fractions as the map, and their percentiles and standard deviation; `covered` is
// not empty (and is left as fractions, sorted).
void summarise(const CellGrid& g, std::vector<double>& covered, CellCoverage& out) {
  const double area = g.side * g.side;
  double sum = 0;
  for (double& a : covered) {
    a /= area;
    sum += a;
  }
  for (std::size_t c = 0; c < g.nx * g.ny; ++c) {
    if (g.index[c] >= 0) {
      out.map[c] = covered[static_cast<std::size_t>(g.index[c])];
    }
  }
  const auto n = static_cast<double>(covered.size());
  const double mean = sum / n;
  double ss = 0;
  for (const double a : covered) {
    ss += (a - mean) * (a - mean);
  }
  std::sort(covered.begin(), covered.end());
  // Nearest rank: the smallest value with at least a fraction p of the cells at or below it.
  const auto percentile = [&covered, n](double p) {
    const double rank = std::max(std::ceil(p * n), 1.0);
    return covered[static_cast<std::size_t>(rank) - 1];
  };
  out.cells = covered.size();
  out.p1 = percentile(0.01);
  out.p5 = percentile(0.05);
  out.p50 = percentile(0.5);
  out.sd = std::sqrt(ss / n);
}

}  // namespace

void measure_cell_coverage(const Domain& domain, std::span<const Disk> disks, const EdgeDistanceIndex& edges, double w,
                           double side, const Budget& budget, CellCoverage& out, const std::stop_token& stop) {
  out.cell_side = side;
  const Box b = domain.bbox();
  if (!(side > 0) || !(b.width() > 0) || !(b.height() > 0)) {
    return;
  }
  const double gx = std::ceil(b.width() / side);
  const double gy = std::ceil(b.height() / side);
  // Per cell: its index and map entry, and for an interior cell its covered area.
  check_count(budget, gx * gy, sizeof(std::int64_t) + 2 * sizeof(double), "coverage cells",
              "use a larger cell side (--cell-side)");
  CellGrid g;
  g.b = b;
  g.side = side;
  g.nx = std::max<std::size_t>(static_cast<std::size_t>(gx), 1);
  g.ny = std::max<std::size_t>(static_cast<std::size_t>(gy), 1);
  std::vector<double> covered = interior_cells(domain, edges, w, g, stop);
  out.origin = {b.xmin, b.ymin};
  out.nx = g.nx;
  out.ny = g.ny;
  out.map.assign(g.nx * g.ny, std::numeric_limits<double>::quiet_NaN());
  if (covered.empty()) {
    return;
  }
  add_disk_areas(g, disks, covered, stop);
  summarise(g, covered, out);
}

}  // namespace frontpack::detail
