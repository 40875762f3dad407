// The boundary-conforming advancing front: the domain's own edges are the walls.
//
// This generalises the open form's walls (disks of infinite radius, Sec. 3 of the paper) from the
// three sides of a rectangle to every edge of a polygon with holes, so that disks pack against
// the real boundary instead of being culled from a box fill (Sec. 2.4.5), and it fills the voids
// that the front leaves behind with later disks small enough for them. CGAL-free, like generate/paper_front.cpp:
// it is a hot loop.
#pragma once

#include <cstddef>
#include <functional>
#include <vector>

#include "generate/paper_front.hpp"
#include "frontpack/domain.hpp"
#include "frontpack/fill.hpp"
#include "common/rng.hpp"

namespace frontpack::detail {

struct BoundaryRequest {
  const Polygon* polygon = nullptr;  ///< normalised: outer ring anticlockwise, holes clockwise
  const RadiusDistribution* radii = nullptr;
  double clearance = 0;       ///< absolute, > 0 (fill.cpp computes the default)
  std::size_t max_disks = 0;  ///< stop when this many disks have been generated in total
  std::size_t memory_limit = 0;  ///< as FrontRequest::memory_limit (its grid and its walls' lists)
  bool fill_voids = true;     ///< try each new disk in the voids behind the front first
  /// As FrontRequest::tick.
  std::function<bool(std::size_t, double)> tick;
};

/// Fills the polygon from its boundary inwards, appending the disks to `out` in generation order.
/// The disks never overlap one another (decided exactly) and lie inside the polygon up to
/// floating-point rounding far below the clearance (the certifier decides containment exactly).
FrontResult advance_boundary(const BoundaryRequest& req, Rng& rng, std::vector<Disk>& out, FillStats& stats);

}  // namespace frontpack::detail
