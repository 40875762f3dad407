#include "fill/progress_meter.hpp"

#include <algorithm>
#include <numbers>

#include "common/packing_density.hpp"

namespace frontpack::detail {

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
