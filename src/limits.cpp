#include "limits.hpp"

#include <algorithm>
#include <cstdint>
#include <limits>
#include <numbers>

#include "common/budget.hpp"
#include "common/packing_density.hpp"
#include "generate/run_control.hpp"

namespace frontpack::detail {

namespace {

// Bytes as a count (at most the largest size_t).
std::size_t count_of_bytes(double bytes) {
  return bytes < 0x1p63 ? static_cast<std::size_t>(bytes) : std::size_t{1} << 63;
}

}  // namespace

RunBudget check_limits(const Domain& domain, const FillOptions& options, const RadiusDistribution& radii,
                       std::size_t generation_cap) {
  double estimate = 0;
  for (std::size_t p = 0; p < domain.num_polygons(); ++p) {
    estimate += estimate_disks(domain.bbox(p), radii);
  }
  if (options.count > 0) {
    // A fill to a count: its generators stop at the cap (fill_count.cpp), whatever the domain holds.
    estimate = std::min(estimate, static_cast<double>(generation_cap));
  }
  const Budget budget{options.max_disks, options.memory_limit};
  check_count(budget, estimate, static_cast<double>(peak_bytes_per_disk), "disks", "use larger radii");
  const double memory_limit = memory_allowed(budget);
  // The limit holds during the run too (the estimate is only an estimate: a box far thinner than
  // the disks makes more than it says): the generators count their grids against it and stop
  // their disks short of it, peak_bytes_per_disk each (FrontResult::over_memory, a LimitError).
  return RunBudget{estimate, memory_limit >= 1 ? count_of_bytes(memory_limit) : 0};
}

ProgressMeter::ProgressMeter(const Domain& domain, Method method, const std::function<bool(const Progress&)>& progress,
                             const std::stop_token& stop)
    : progress_(progress), stop_(stop) {
  if (method == Method::boundary) {
    to_cover_ = kEstimateFraction * domain.area();
    return;
  }
  for (std::size_t p = 0; p < domain.num_polygons(); ++p) {
    to_cover_ += kEstimateFraction * domain.bbox(p).width() * domain.bbox(p).height();
  }
}

std::function<bool(std::size_t, double)> ProgressMeter::tick() const {
  if (!progress_ && !stop_.stop_possible()) {
    return {};
  }
  return [this](std::size_t total, double r2) {
    if (stop_.stop_requested()) {
      return false;
    }
    if (!progress_) {
      return true;
    }
    const double covered = covered_before_ + std::numbers::pi * r2;
    return progress_(Progress{total, std::min(0.99, covered / std::max(to_cover_, 1e-300)), covered, Phase::generate});
  };
}

std::function<bool(std::size_t, double)> ProgressMeter::jam_tick() const {
  if (!progress_ && !stop_.stop_possible()) {
    return {};
  }
  return [this](std::size_t disks, double fraction) {
    if (stop_.stop_requested()) {
      return false;
    }
    return !progress_ || progress_(Progress{disks, fraction, covered_before_, Phase::jam});
  };
}

void ProgressMeter::polygon_done(std::span<const Disk> disks) {
  for (const Disk& d : disks) {
    covered_before_ += std::numbers::pi * d.radius * d.radius;
  }
}

void ProgressMeter::generated(std::size_t generated) const {
  if (progress_) {
    (void)progress_(Progress{generated, 1.0, covered_before_, Phase::generate});
  }
  certifying(generated);
}

void ProgressMeter::certifying(std::size_t disks) const {
  if (progress_) {
    (void)progress_(Progress{disks, 0.0, covered_before_, Phase::certify});
  }
}

void ProgressMeter::finish(std::size_t generated) const {
  if (progress_) {
    (void)progress_(Progress{generated, 1.0, covered_before_, Phase::certify});
  }
}

}  // namespace frontpack::detail
