// frontpack: exact certification of a set of disks against a domain.
//
//   const frontpack::CertifyReport report = frontpack::certify(domain, disks);
//   if (report.outside.empty() && report.overlapping.empty()) { /* a valid packing */ }
//
// fill() certifies its own output with the same functions (src/certify/); this header lets any
// packing, from frontpack or elsewhere, be checked the same way. Every decision is exact on the
// given doubles (docs/robustness.md).
#pragma once

#include <cstddef>
#include <optional>
#include <span>
#include <stop_token>
#include <tuple>
#include <utility>
#include <vector>

#include "frontpack/domain.hpp"
#include "frontpack/fields.hpp"
#include "frontpack/geometry.hpp"

namespace frontpack {

/// The certifier's report.
struct Certificate {
  std::size_t generated = 0;
  std::size_t culled = 0;
  std::size_t dropped = 0;
  std::size_t candidate_pairs = 0;
  bool exact = true;

  static constexpr auto fields() {
    return std::tuple{
        field("generated", &Certificate::generated, "disks produced by the generator"),
        field("culled", &Certificate::culled, "removed because not entirely inside the domain (exact)"),
        field("dropped", &Certificate::dropped, "removed by the global overlap pass (0 for frontpack's generator)"),
        field("candidate_pairs", &Certificate::candidate_pairs, "pairs whose boxes met, each decided exactly"),
        field("exact", &Certificate::exact, "every containment and every pair was decided exactly")};
  }
};

/// What certify() found about an arbitrary set of disks. Which disks are outside and which pairs
/// overlap is decided exactly; how bad it is (the deepest overlap, the farthest outside) is
/// computed in floating point from those decisions (approximate), for reports.
struct CertifyReport {
  Certificate certificate;
  std::vector<std::size_t> outside;
  std::vector<std::pair<std::size_t, std::size_t>> overlapping;
  std::optional<std::pair<std::size_t, std::size_t>> deepest_overlap;
  double deepest_overlap_depth = 0;
  std::optional<std::size_t> farthest_outside;
  double farthest_outside_by = 0;

  static constexpr auto fields() {
    return std::tuple{
        field("certificate", &CertifyReport::certificate, "the certifier's counts"),
        field("outside", &CertifyReport::outside,
              "indices of the disks not inside the closed domain (non-finite or negative disks included)"),
        field("overlapping", &CertifyReport::overlapping,
              "index pairs (i < j) whose interiors intersect, sorted (touching is fine); in a periodic cell also "
              "(i, i) for a disk that overlaps its own image (its diameter exceeds a period)")
            .json("overlapping_pairs"),
        field("deepest_overlap", &CertifyReport::deepest_overlap,
              "the pair of `overlapping` with the deepest overlap r_i + r_j - |c_i - c_j| (none if empty)")
            .json("disks")
            .in("deepest_overlap"),
        field("deepest_overlap_depth", &CertifyReport::deepest_overlap_depth, "that overlap, r_i + r_j - |c_i - c_j|")
            .json("depth")
            .in("deepest_overlap"),
        field("farthest_outside", &CertifyReport::farthest_outside,
              "the disk of `outside` reaching farthest out (none if empty)")
            .json("disk")
            .in("farthest_outside"),
        field("farthest_outside_by", &CertifyReport::farthest_outside_by,
              "how far it reaches out: the largest r - d, d the signed distance from its centre to the boundary "
              "(positive inside); infinity for a non-finite or negative disk")
            .json("by")
            .in("farthest_outside")};
  }
};

/// Certifies any set of disks against a domain, exactly: which disks are not inside the closed
/// domain, and which pairs overlap (interiors intersect; touching is fine). Disks with a
/// negative, NaN or infinite radius or centre are "outside". Pairs among outside disks are
/// reported too. Throws CancelledError once `stop` is requested.
///
/// A periodic cell (Domain::periodic): "inside" is Domain::contains (the centre in the half-open
/// cell; with Periodicity::x the disk between the walls), and (i, j) overlap when disk i overlaps
/// an image of disk j, j translated by whole periods (kx (xmax - xmin), ky (ymax - ymin)), the
/// periods taken exactly; every image is considered, whatever the radii (a disk wider than the
/// cell meets its own image: the pair (i, i)). Centres outside the cell (a simulation's unwrapped
/// dump) are wrapped by whole periods for the search and the exact test uses the total shift; they
/// are also reported outside. A disk more than 2^50 periods away takes part in no pair.
/// deepest_overlap uses the nearest image.
[[nodiscard]] CertifyReport certify(const Domain& domain, std::span<const Disk> disks, std::stop_token stop = {});

}  // namespace frontpack
