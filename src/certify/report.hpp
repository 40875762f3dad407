// The "how bad" figures of a certificate report: the deepest overlap and the disk reaching
// farthest out, in floating point from the exact decisions. CGAL-free declaration.
#pragma once

#include <span>

#include "frontpack/certify.hpp"

namespace frontpack::detail {

/// Fills report.deepest_overlap(_depth) from report.overlapping and report.farthest_outside(_by)
/// from report.outside (approximate figures; which disks are outside and which pairs overlap is
/// already decided, exactly).
void measure_worst(const Domain& domain, std::span<const Disk> disks, CertifyReport& report);

}  // namespace frontpack::detail
