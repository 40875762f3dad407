#include "periodic/cell.hpp"

#include <cmath>

#include "exact/periodic_predicates.hpp"

namespace frontpack::detail {

bool cell_contains(const Box& cell, Periodicity axes, const Disk& disk) noexcept {
  const double x = disk.centre.x;
  const double y = disk.centre.y;
  const double r = disk.radius;
  // NaN fails every comparison below; an infinite radius is refused here.
  if (!(r >= 0) || !std::isfinite(r) || !(cell.xmin <= x && x < cell.xmax)) {
    return false;
  }
  if (axes == Periodicity::x) {
    return std::isfinite(y) && between_walls(y, r, cell.ymin, cell.ymax);
  }
  return cell.ymin <= y && y < cell.ymax;
}

Location locate_in_cell(const Box& cell, Periodicity axes, Point p) noexcept {
  if (!(cell.xmin <= p.x && p.x < cell.xmax)) {
    return Location::outside;
  }
  if (axes == Periodicity::x) {
    if (p.y == cell.ymin || p.y == cell.ymax) {
      return Location::boundary;
    }
    return cell.ymin < p.y && p.y < cell.ymax ? Location::inside : Location::outside;
  }
  return cell.ymin <= p.y && p.y < cell.ymax ? Location::inside : Location::outside;
}

}  // namespace frontpack::detail
