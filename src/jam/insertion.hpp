// Where a round of the jam stage inserts its disks: at the points of the domain farthest from every
// disk and wall (the centres of its largest empty circles, on a lattice), so that each inserted
// disk goes where the packing has the most room, overlaps its neighbours as little as the packing
// allows, and the holes are the first to be filled. Floating point, CGAL-free: the relaxation and
// the exact checks decide what is kept.
#pragma once

#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

#include "common/rng.hpp"
#include "domain/edge_distance.hpp"
#include "frontpack/domain.hpp"
#include "frontpack/geometry.hpp"
#include "frontpack/sizes.hpp"
#include "jam/disk_cells.hpp"
#include "periodic/wrap.hpp"

namespace frontpack::detail {

class Insertion {
 public:
  /// Points per disk of the lattice of candidate points.
  static constexpr double kPerDisk = 8;

  /// The candidate points: the points of a square lattice (about kPerDisk points per disk, its
  /// spacing at least rmin / 2, offset at random) that lie within rmax of one of `disks` (the
  /// packing covers the domain: every point of it is that near a disk), inside the domain (decided
  /// exactly) and at least a spacing from every wall. `cell`: the periodic cell, or the domain's
  /// box. `walls` must outlive this.
  Insertion(const Domain& domain, const EdgeDistanceIndex& walls, Periodicity periodicity, const Box& cell, double rmin,
            double rmax, const std::vector<Disk>& disks, Rng& rng);

  /// Appends up to `count` disks to `disks`, their radii drawn from `radii` in turn, each at the
  /// candidate point with the largest clearance (the distance to the nearest disk's edge, the
  /// disks appended before it included, or wall), moved within a spacing of the lattice point to
  /// where its clearance is larger still. Returns how many it appended: fewer when the domain has
  /// no candidate point left (one thinner than two spacings).
  std::size_t insert(std::vector<Disk>& disks, std::size_t count, const RadiusDistribution& radii, Rng& rng);

  /// The lattice's spacing.
  [[nodiscard]] double spacing() const noexcept { return h_; }

 private:
  // min(rmax, the distance from p to the nearest disk's edge (negative inside a disk) or wall).
  [[nodiscard]] double clearance(Point p, const std::vector<Disk>& disks) const;

  const EdgeDistanceIndex& walls_;
  PeriodicWrap wrap_;
  Box cell_;
  double cap_ = 0;
  double h_ = 0;                   // the lattice's spacing
  std::vector<Point> candidates_;  // the lattice points kept, row by row from below
  // The disks there before the round, by cell; those appended during it chained into the same
  // cells (head_ per cell, next_ per disk appended).
  DiskCells grid_;
  std::size_t base_ = 0;
  std::vector<std::uint32_t> head_;
  std::vector<std::uint32_t> next_;
  std::vector<std::pair<double, std::size_t>> heap_;  // (clearance, index in candidates_)
};

}  // namespace frontpack::detail
