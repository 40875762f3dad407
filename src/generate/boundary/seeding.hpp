// Where the boundary front starts. Sec. 3's open front starts in the corners of a rectangle's three
// walls; here every edge of every ring is a wall, the reflex vertices are obstacles of radius 0,
// and the front starts at the sharp corners of every ring (the sharpest one of a ring without).
// Where the walls could start no front (a boundary rougher than the smallest disk), a seed pair of
// disks starts one inside. Set-up and rare: out of line.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "common/rng.hpp"
#include "frontpack/domain.hpp"
#include "generate/boundary/elements.hpp"
#include "generate/boundary/obstacles.hpp"
#include "generate/boundary/walls.hpp"
#include "generate/settings.hpp"

namespace frontpack::detail {

/// The polygon as the front sees it, and its first gaps.
struct Seeding {
  std::vector<Wall> walls;              // every ring's edges, the outer ring's first, local
  std::vector<Corner> corners;          // the reflex vertices, in ring order
  std::vector<Point> corner_at;         // and where they are
  std::vector<std::size_t> ring_first;  // the first wall of each ring
  std::vector<std::uint8_t> rough;      // per wall: shorter than 2 rmax at a sharp corner
  bool any_rough = false;
  std::vector<Gap> gaps;  // the first gaps, in the order the front takes them
  double area = 0;        // the polygon's, by the shoelace over the walls (holes subtract)
};

/// The polygon's bounding box (its outer ring's).
[[nodiscard]] Box outer_box(const Polygon& polygon) noexcept;

/// The walls, reflex vertices and first gaps of `polygon` (normalised: outer ring anticlockwise,
/// holes clockwise) in `frame`'s local coordinates. Gaps name a reflex vertex by its index in
/// `corners`, which is its node id.
[[nodiscard]] Seeding seed_at_corners(const Polygon& polygon, const RunFrame& frame);

/// A periodic cell ([0, width) x [0, height), local) as the front sees it: no wall if it is
/// periodic in x and y; else its bottom and top as two walls (each a ring of its own), reaching
/// 4 rmax beyond the cell on either side so that a disk near a periodic side, or its image, has
/// its foot on them. No corner and no first gap: seeds start the front (boundary_front.cpp).
[[nodiscard]] Seeding seed_periodic_cell(const RunFrame& frame, Periodicity periodicity);

/// A shear cell's first disks (local centres): one of radius r on the bottom wall and one of
/// radius r2 on the top wall, each at a random x, the clearance from its wall. The top one is
/// absent if the cell is lower than the two disks stacked (r + r2 and three clearances), the
/// bottom one if it is lower than that disk.
[[nodiscard]] std::array<std::optional<Point>, 2> seed_on_walls(const RunFrame& frame, Rng& rng, double r, double r2);

/// A place inside the polygon for a seed pair: a disk of radius r at the point returned and one of
/// radius r2 beside it, to the right, apart by the clearance, both clear of every element. Tried
/// at up to kSeedTries points drawn in the polygon's box; nothing if none fits.
[[nodiscard]] std::optional<Point> seed_pair_at(Obstacles& obstacles, const Elements& elements, const RunFrame& frame,
                                                Rng& rng, double r, double r2);

}  // namespace frontpack::detail
