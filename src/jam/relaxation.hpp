// The relaxation of the jam stage: moves disks until no two overlap and none crosses a wall, by
// minimising the harmonic overlap energy U = 1/2 sum delta^2 (delta the overlap of a pair, or of a
// disk with a wall, each disk counted with a small gap) with FIRE (Bitzek, Koskinen, Gaehler,
// Moseler and Gumbsch, Phys. Rev. Lett. 97, 170201, 2006), the minimiser of the jamming literature.
// Floating point, CGAL-free: what it returns goes to the exact certifier as every generator's
// output does. The disks' radii never change.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <stop_token>
#include <vector>

#include "domain/edge_distance.hpp"
#include "frontpack/domain.hpp"
#include "frontpack/geometry.hpp"
#include "jam/disk_cells.hpp"
#include "periodic/wrap.hpp"

namespace frontpack::detail {

struct RelaxationFrame {
  /// The walls: every edge of the polygon being relaxed, or a shear cell's bottom and top.
  const EdgeDistanceIndex* walls = nullptr;
  Periodicity periodicity = Periodicity::none;
  Box cell{};  // the periodic cell (periodicity != none), else the box the disks stay in
  double rmin = 0;
  double rmax = 0;
  /// Least gap the relaxation leaves between two disks, or a disk and a wall, beside the one it
  /// leaves in proportion to the radii: the generators' clearance times 4, a few ulps of the
  /// coordinates, so that rounding never turns a gap into an overlap.
  double least_gap = 0;
};

class Relaxation {
 public:
  /// Relative gap kept between disks: two disks are relaxed to lie gap(r1, r2) apart, at most
  /// 2.5e-10 (r1 + r2) (or least_gap), within the statistics' contact tolerance (1e-9 rmax), so
  /// that the disks a jammed packing presses together count as touching.
  static constexpr double kRelativeGap = 2.5e-10;

  explicit Relaxation(const RelaxationFrame& frame);

  /// Moves `disks` (centres only) for at most max_iterations steps of FIRE. Returns true when
  /// every pair lies at least half its gap apart and every disk half its gap from every wall
  /// (then no two overlap and none crosses a wall, up to the certifier's exact decision), false
  /// if the iterations ran out first (the disks are left where the last step put them).
  /// `keep_going` (may be empty) is asked every 64 steps; false ends the run (returns false).
  bool run(std::vector<Disk>& disks, std::size_t max_iterations, const std::function<bool()>& keep_going,
           const std::stop_token& stop);

  /// Steps taken by the last run().
  [[nodiscard]] std::size_t iterations() const noexcept { return iterations_; }

 private:
  struct Pair {
    std::uint32_t i;
    std::uint32_t j;
    double contact;   // r_i + r_j + gap: closer than this, the pair pushes apart
    double half_gap;  // closer than contact - half_gap, the pair still overlaps
  };

  [[nodiscard]] double gap(double r1, double r2) const noexcept {
    return std::max(kRelativeGap * (r1 + r2), frame_.least_gap);
  }
  // The difference vector b - a at its nearest image in a periodic cell.
  void wrap_difference(double& dx, double& dy) const noexcept {
    dx = wrap_.dx(dx);
    dy = wrap_.dy(dy);
  }
  // The pairs lying within their separation plus the skin, and the disks within the skin of a
  // wall: rebuilt whenever a disk has moved half the skin since the last build.
  void build_lists(const std::vector<Disk>& disks);
  // Forces into force_; returns the largest overlap beyond half the gap (<= 0: done).
  double forces(const std::vector<Disk>& disks);

  // FIRE's state over a run: the time step, the mix and the steps of positive power since the
  // power was last negative; and this step's mixing of the velocities (mixing, scale, keep).
  struct Fire {
    double dt;
    double mix;
    std::size_t power_steps = 0;
    bool mixing = false;
    double scale = 0;
    double keep = 0;
  };
  // This step's mixing, from the power F.v with the mix as it stands, then FIRE's new time step
  // and mix.
  void fire_update(Fire& fire) const;
  // Mixes each velocity and moves its disk by one time step, at most max_step (kept in the cell on
  // a periodic axis). Returns whether a disk has moved farther than sqrt(rebuild2) since the lists
  // were built.
  bool move_disks(std::vector<Disk>& disks, const Fire& fire, double max_step, double rebuild2);

  RelaxationFrame frame_;
  PeriodicWrap wrap_;  // the minimum image and the wrap into the cell, as the fronts have them
  double skin_ = 0;
  std::size_t iterations_ = 0;
  // Reused from run to run and build to build: nothing is allocated per step.
  std::vector<Pair> pairs_;
  std::vector<std::uint32_t> near_wall_;
  std::vector<Point> force_;
  std::vector<Point> velocity_;
  std::vector<Point> built_at_;
  DiskCells grid_;
};

}  // namespace frontpack::detail
