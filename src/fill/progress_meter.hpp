// How far a fill has come: the progress reported while the fronts, the certifier and the jam
// stage run (Generator::on_progress), and the ticks through which the stages report it. CGAL-free.
#pragma once

#include <cstddef>
#include <functional>
#include <span>
#include <stop_token>

#include "frontpack/fill.hpp"

namespace frontpack::detail {

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
