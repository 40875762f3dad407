// The advancing front of Feng, Han & Owen (2003), closed and open forms, filling one box.
//
// This translation unit is CGAL-free and allocation-free per disk: it is the hot loop.
#pragma once

#include <cstddef>
#include <vector>

#include "common/rng.hpp"
#include "frontpack/geometry.hpp"
#include "generate/front_report.hpp"
#include "generate/settings.hpp"

namespace frontpack::detail {

/// Fills `box` with the closed or open form (settings.method), appending the disks to `out` in
/// generation order. The generated disks never overlap one another (decided exactly); they may
/// extend beyond the box. Returns the run's counters and why it stopped.
FrontReport advance_front(const FrontSettings& settings, const Box& box, Rng& rng, std::vector<Disk>& out);

}  // namespace frontpack::detail
