// Thinning a loose packing down to a target fraction: disks removed where the packing is densest,
// so that the removal evens the density out rather than making holes in one place.
#pragma once

#include <cstddef>
#include <vector>

#include "frontpack/domain.hpp"
#include "frontpack/geometry.hpp"

namespace frontpack::detail {

/// Removes disks until their total area is within [target_area - below, target_area] if it can
/// (each removal is one whole disk: a disk whose removal would go below target_area - below is
/// kept and the next one tried). The order: repeatedly the disk whose neighbourhood (the disks
/// other than itself with centres within `reach` of its centre, over the part of the
/// neighbourhood that lies in the domain, estimated at 24 points located exactly) is the most
/// densely covered; ties go to the earlier disk. Keeps the order of the disks kept. Returns the
/// number removed. Deterministic.
std::size_t thin_to_area(const Domain& domain, std::vector<Disk>& disks, double target_area, double below,
                         double reach);

}  // namespace frontpack::detail
