// What bounds a generator's run, the same for both fronts: the disk budget (max_disks and what the
// memory limit leaves for disks), the progress callback that may cancel, the estimates that size
// its reservations, and freeing its working arrays before the output grows.
#pragma once

#include <algorithm>
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "common/release.hpp"
#include "frontpack/geometry.hpp"
#include "frontpack/sizes.hpp"
#include "generate/front_report.hpp"

namespace frontpack::detail {

/// The LimitError of a run that would take more memory than its memory_limit: "the run would need
/// more than the memory limit of LIMIT bytes: WHAT; raise memory_limit (frontpack fill
/// --memory-limit) or use larger radii". `estimate`: the disks it would make, for LimitError.
[[noreturn]] void throw_memory_limit(std::size_t limit, const std::string& what, std::size_t estimate);

/// A count from a double, for reservations: 0 for NaN or less, at most `most`.
[[nodiscard]] inline std::size_t count_of(double v, double most) noexcept {
  return v > 0 ? static_cast<std::size_t>(v < most ? v : most) : 0;
}

/// What both generators check before each disk: the disk budget (max_disks, 0 = none, and what
/// the memory limit leaves for disks) and the progress callback, called every 2^14 disks, which
/// may cancel. Keeps a reference to `tick`.
class RunControl {
 public:
  RunControl(std::size_t max_disks, const std::function<bool(std::size_t, double)>& tick)
      : budget_(max_disks == 0 ? static_cast<std::size_t>(-1) : max_disks), max_disks_(budget_), tick_(tick) {}

  /// The disks may take `bytes` (what the memory limit leaves besides the grids): stop
  /// (FrontReport::over_memory) once they would take more, if that comes before max_disks. They
  /// are counted at `bytes_per_disk` each (FrontSettings::bytes_per_disk), and stop at 15/16 of
  /// what that allows: the bound is a measured one (the closed form's peak was 55-64 bytes per
  /// disk generated on the shapes), and vectors growing by doubling (the voids) overshoot it for a moment.
  void limit_memory(std::size_t bytes, std::size_t bytes_per_disk) noexcept {
    budget_ = std::min(budget_, bytes / 16 * 15 / bytes_per_disk);
  }
  /// The disks that may be generated in total.
  [[nodiscard]] std::size_t budget() const noexcept { return budget_; }

  /// Whether to stop before placing another disk, `placed` disks having been generated in total
  /// and `area` being the sum of r^2 over this call's; `result` says why.
  bool stop(std::size_t placed, double area, FrontReport& result) {
    if (placed >= budget_) {
      (placed >= max_disks_ ? result.truncated : result.over_memory) = true;
      return true;
    }
    if (tick_ && placed - last_tick_ >= kTickEvery) {
      last_tick_ = placed;
      if (!tick_(placed, area)) {
        result.cancelled = true;
        return true;
      }
    }
    return false;
  }

 private:
  static constexpr std::size_t kTickEvery = std::size_t{1} << 14;
  std::size_t budget_;
  std::size_t max_disks_;
  const std::function<bool(std::size_t, double)>& tick_;
  std::size_t last_tick_ = 0;
};

/// Estimated number of disks that fill `box` with radii from `radii` (a dense random packing):
/// never NaN (areas and E[r^2] that underflow are taken at the scale of rmax), infinite where the
/// count exceeds the doubles.
[[nodiscard]] double estimate_disks(const Box& box, const RadiusDistribution& radii);

/// At most how many disks, not overlapping one another, lie within `grow` of `box` (covering at
/// most its area: the estimate at density 1, E[r^2] standing for the mean square of the radii
/// drawn, within a few percent of it once they are thousands). For reservations.
[[nodiscard]] double bound_disks(const Box& box, double grow, const RadiusDistribution& radii);

}  // namespace frontpack::detail
