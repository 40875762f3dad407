// The chain of wall disks along one ring (src/decks/wall_disks.cpp) and its verification: what a
// deck says about its walls is checked on the disks it writes, not assumed from how they were
// placed.
#pragma once

#include <cstddef>
#include <span>
#include <string>
#include <vector>

#include "frontpack/domain.hpp"
#include "frontpack/geometry.hpp"

namespace frontpack::detail {

/// A wall disk of a ring's chain and the ring edge it was placed from (the disks about the corner
/// at that edge's end count as the edge's).
struct ChainDisk {
  Disk disk;
  std::size_t edge = 0;
};

/// One ring's wall disks: the closed chain in ring order, and the smaller disks in the tips of
/// narrow outside corners (each with the edge that ends at its corner).
struct RingWalls {
  std::vector<ChainDisk> chain;
  std::vector<ChainDisk> tips;
};

/// The smallest wall radius the coordinates of `bbox` can hold: 8 ulps of the largest coordinate
/// magnitude M, divided by 1e-6. A wall disk sits wall_radius (1 + 1e-6) from its edge, and its
/// centre is computed with a rounding error of a few ulps of M; below this radius that error
/// exceeds the gap of 1e-6 wall radii, and far below it the offset itself is lost in rounding
/// (1e-30 at M = 2 put every centre on the ring).
[[nodiscard]] double wall_radius_floor(const Box& bbox);

/// The complement of `domain` inside its bounding box grown by room for walls of `wall_radius` and
/// the reach 2 (wall_radius + rmin): what wall disks are certified in (Domain::contains).
[[nodiscard]] Domain wall_complement(const Domain& domain, double wall_radius, double rmin);

/// The wall disks of `ring` (a ring of the domain `outside` is the complement of), placed in
/// floating point and certified exactly in `outside`; those that are not inside it are dropped.
[[nodiscard]] RingWalls ring_walls(const Domain& outside, const Ring& ring, double wall_radius);

/// The number of candidates ring_walls places for `ring` (before any is certified), in floating
/// point so that it cannot overflow: at least 2 perimeter / wall_radius.
[[nodiscard]] double ring_wall_count(const Ring& ring, double wall_radius);

/// Verifies the chain of `ring` (named `where` in messages, e.g. "hole 2 of polygon 1") and throws
/// OptionError naming the ring and the place unless:
///   - every chain disk lies in `outside`, the closed complement of the domain (exact);
///   - consecutive chain disks (cyclically) have centres closer than 2 (wall_radius + rmin), so no
///     disk of radius rmin passes between them;
///   - the chain covers the ring: it goes round it once (the disks' edges in ring order), and every
///     ring vertex it passes over between two consecutive disks lies closer than 2 (wall_radius +
///     rmin) to the segment between their centres, or is the corner that one of those two disks
///     closes: it leaves a gap narrower than 2 rmin to the lines of both edges that meet there
///     (the disk that closes a narrow outside corner, however deep its tip). So a pocket outside the ring that no wall
///     disk reaches (a notch narrower than a wall disk, closed across its mouth) is at most 2 (wall_radius + rmin)
///     deep; a deeper one, or a stretch of ring with no wall disk, is refused.
/// Together: a disk of radius >= rmin inside the ring's side cannot reach the far side of the chain,
/// nor go deeper than that into a pocket.
void verify_wall_chain(const Domain& outside, const Ring& ring, std::span<const ChainDisk> chain, double wall_radius,
                       double rmin, const std::string& where);

}  // namespace frontpack::detail
