// The clearance tangent disks keep (FillOptions::clearance), for check_options() and for every
// run (the targets' runs with scaled radii included). CGAL-free.
#pragma once

#include "frontpack/fill.hpp"

namespace frontpack::detail {

/// The clearance tangent disks keep (FillOptions::clearance, or a few ulps of the largest
/// coordinate a disk can have if 0). Throws OptionError for a clearance below that, or a domain
/// and radii too small for one.
[[nodiscard]] double clearance_for(const Domain& domain, const FillOptions& options);

}  // namespace frontpack::detail
