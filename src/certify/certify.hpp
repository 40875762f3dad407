// The certifier's two entry points, composed from the same parts (cull.hpp, overlap_pass.hpp,
// report.hpp): frontpack::certify() reports on any set of disks; certify_fill() below removes
// from a fill's output what the report would name. CGAL-free.
#pragma once

#include <cstddef>
#include <span>
#include <stop_token>
#include <vector>

#include "frontpack/certify.hpp"
#include "frontpack/domain.hpp"
#include "frontpack/geometry.hpp"

namespace frontpack::detail {

/// What certify_fill() reports: the certificate and the wall times of its two passes.
struct CertifyResult {
  Certificate certificate;
  double seconds_cull = 0;     ///< the exact containment pass
  double seconds_overlap = 0;  ///< the global overlap pass
};

/// Certifies a fill's raw output in place: culls the disks not inside their own polygon
/// (contains_in_own_polygon(), `part_end` as there; empty: inside the domain, for disks that
/// can have left no polygon for another, as the jam stage's), then drops one disk of every overlapping pair
/// (drop_one_of_each_pair(); frontpack's generators never make one). Returns the certificate and
/// the two passes' wall times. Throws CancelledError once `stop` is requested.
CertifyResult certify_fill(const Domain& domain, std::vector<Disk>& disks, std::span<const std::size_t> part_end,
                           const std::stop_token& stop);

}  // namespace frontpack::detail
