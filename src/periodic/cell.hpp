// Containment and point location in a periodic cell [xmin, xmax) x [ymin, ymax) (Domain::periodic).
//
// A disk belongs to the cell when its centre does: xmin <= x < xmax on a periodic axis (exact
// comparisons of doubles; the half-open side gives every point of the plane exactly one image in
// the cell). With Periodicity::x the bottom and top are walls: the closed disk must lie between
// them, ymin <= y - r and y + r <= ymax, decided exactly (y - r rounded is not exact). With
// Periodicity::xy the centre's y is half-open as its x. A disk with a NaN, infinite or negative
// radius, or a non-finite centre, is never inside.
//
// Point location: `inside` for a point of the half-open cell (Periodicity::x: strictly between the
// walls), `boundary` for a point on a wall (Periodicity::x: y = ymin or y = ymax with x in
// [xmin, xmax)), `outside` otherwise. A periodic side is no boundary: the plane continues there.
#pragma once

#include "frontpack/domain.hpp"
#include "frontpack/geometry.hpp"

namespace frontpack::detail {

[[nodiscard]] bool cell_contains(const Box& cell, Periodicity axes, const Disk& disk) noexcept;
[[nodiscard]] Location locate_in_cell(const Box& cell, Periodicity axes, Point p) noexcept;

}  // namespace frontpack::detail
