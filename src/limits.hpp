// What a fill may take and how far it has come: the disk-count and memory estimates checked
// against FillOptions::max_disks and memory_limit before the run, the clearance, the progress
// reported while the fronts run, and why a run placed no disk. CGAL-free.
#pragma once

#include <cstddef>
#include <functional>
#include <span>
#include <stop_token>

#include "frontpack/fill.hpp"
#include "options/clearance.hpp"

namespace frontpack::detail {

struct RunBudget {
  double estimate = 0;           ///< disks a dense packing of every polygon's box takes
  std::size_t memory_bytes = 0;  ///< what the run may take (0: no limit), for the generators
};

/// The estimate of the disks a fill makes, and the memory it may take (options.memory_limit, or
/// three quarters of the physical memory if 0). Throws LimitError if the estimate exceeds
/// options.max_disks, or if its disks at peak_bytes_per_disk each exceed the memory limit. A fill
/// to a count (options.count > 0: the plain fill under fill_to_count) makes at most
/// `generation_cap` disks, and is estimated so.
[[nodiscard]] RunBudget check_limits(const Domain& domain, const FillOptions& options, const RadiusDistribution& radii,
                                     std::size_t generation_cap);

/// Throws NothingFitsError naming why the fill of `domain` with `options` gave `packing` no disk:
/// a fraction or a level that keeps none, radii larger than the domain holds, a start point
/// outside the domain, a clearance (given, or the one the precision at the domain's coordinates
/// needs) that leaves no room; else the disks generated, none inside.
[[noreturn]] void throw_nothing_fits(const Domain& domain, const FillOptions& options, const Packing& packing);

/// Progress of a fill across its polygons: the area of the disks generated over the area a dense
/// packing covers (kEstimateFraction of it) where the method puts disks: the domain itself for
/// the boundary method, the polygons' boxes for the paper's forms (which cull what overhangs),
/// so that the fraction reaches about 1 as the front ends, holes or not. Holds references to
/// `progress` and `stop`.
class ProgressMeter {
 public:
  ProgressMeter(const Domain& domain, Method method, const std::function<bool(const Progress&)>& progress,
                const std::stop_token& stop);

  /// The generators' tick (FrontSettings::tick) for the next polygon: false once `stop` is
  /// requested or the callback cancels. Empty if there is no callback and no stop is possible.
  [[nodiscard]] std::function<bool(std::size_t, double)> tick() const;

  /// The disks a polygon's run appended, once it has returned.
  void polygon_done(std::span<const Disk> disks);

  /// The jam stage's tick (jam/jam.hpp): reports Phase::jam with the disks and the fraction of
  /// the rounds done; false once `stop` is requested or the callback cancels. Empty if there is
  /// no callback and no stop is possible.
  [[nodiscard]] std::function<bool(std::size_t, double)> jam_tick() const;

  /// Reports the front's end (fraction 1, `generated` disks) and the certification's start.
  void generated(std::size_t generated) const;
  /// Reports a certification's start (fraction 0), as the jam stage's certification begins.
  void certifying(std::size_t disks) const;
  /// Reports a certification's end (fraction 1), the fill's or the front's before the jam stage.
  void finish(std::size_t generated) const;

 private:
  const std::function<bool(const Progress&)>& progress_;
  const std::stop_token& stop_;
  double to_cover_ = 0;        // the area the front is expected to cover
  double covered_before_ = 0;  // by the disks of the polygons done
};

}  // namespace frontpack::detail
