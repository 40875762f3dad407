// The boundary-conforming advancing front: the domain's own edges are the walls.
//
// This generalises the open form's walls (disks of infinite radius, Sec. 3 of the paper) from the
// three sides of a rectangle to every edge of a polygon with holes, so that disks pack against
// the real boundary instead of being culled from a box fill (Sec. 2.4.5), and it fills the voids
// that the front leaves behind with later disks small enough for them. CGAL-free, like generate/paper_front.cpp:
// it is a hot loop.
#pragma once

#include <cstddef>
#include <vector>

#include "common/rng.hpp"
#include "frontpack/domain.hpp"
#include "frontpack/geometry.hpp"
#include "generate/front_report.hpp"
#include "generate/settings.hpp"

namespace frontpack::detail {

/// Fills the polygon from its boundary inwards, appending the disks to `out` in generation order.
/// The disks never overlap one another (decided exactly) and lie inside the polygon up to
/// floating-point rounding far below the clearance (the certifier decides containment exactly).
/// `polygon` is normalised: outer ring anticlockwise, holes clockwise. Returns the run's counters
/// and why it stopped.
FrontReport advance_boundary(const FrontSettings& settings, const Polygon& polygon, Rng& rng, std::vector<Disk>& out);

}  // namespace frontpack::detail
