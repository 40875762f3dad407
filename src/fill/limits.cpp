#include "fill/limits.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <numbers>
#include <string>

#include "common/budget.hpp"
#include "common/format.hpp"
#include "common/packing_density.hpp"
#include "generate/run_control.hpp"

namespace frontpack::detail {

namespace {

// Bytes as a count (at most the largest size_t).
std::size_t count_of_bytes(double bytes) {
  return bytes < 0x1p63 ? static_cast<std::size_t>(bytes) : std::size_t{1} << 63;
}

}  // namespace

// Why a fill placed no disk: the first of these causes that holds, tested in this order.
// A disk of radius r inside the domain lies in one polygon's bounding box and has area pi r^2 at
// most the domain's, so r <= min(sqrt(area / pi), the largest polygon box's half-side): a cheap
// bound, exact for rectangles and corridors. A disk keeps the clearance from the walls and from
// the other disks: with it, r + clearance <= that bound.
void throw_nothing_fits(const Domain& domain, const FillOptions& options, const Packing& packing) {
  const double rmin = options.radii.min();
  const std::string r = format_double(rmin);
  if (packing.target && packing.target->fraction_requested > 0) {
    const double f = packing.target->fraction_requested;
    const double area = packing.target->area_filled;
    const double one = std::numbers::pi * rmin * rmin;
    throw NothingFitsError("no disk was kept: fraction " + format_double(f) + " of the area " + format_double(area) +
                           " is " + format_double(f * area) + ", less than one disk of the smallest radius, " + r +
                           " (area " + format_double(one) + "); ask for a fraction of at least " +
                           format_double(one / area) + " (fraction, --fraction) or use smaller radii");
  }
  if (packing.target && packing.target->height) {
    throw NothingFitsError("no disk lies wholly below the level y = " + format_double(*packing.target->height) +
                           ": the part of the domain below it (area " + format_double(packing.target->area_filled) +
                           ") holds no disk of the smallest radius, " + r +
                           "; raise the level (height, --height) or use smaller radii");
  }
  double half_side = 0;
  for (std::size_t k = 0; k < domain.num_polygons(); ++k) {
    const Box b = domain.bbox(k);
    half_side = std::max(half_side, 0.5 * std::min(b.width(), b.height()));
  }
  const double bound = std::min(std::sqrt(domain.area() / std::numbers::pi), half_side);
  if (rmin > bound) {
    throw NothingFitsError("no disk fits: the smallest radius, " + r + " (" + options.radii.describe() +
                           "), is larger than any disk this domain holds (none of radius above " +
                           format_double(bound) + "); use smaller radii");
  }
  const std::string generated =
      std::to_string(packing.certificate.generated) + (packing.certificate.generated == 1 ? " disk" : " disks");
  const Box box = domain.bbox();
  if (options.method == Method::closed && options.start &&
      !(box.xmin <= options.start->x && options.start->x <= box.xmax && box.ymin <= options.start->y &&
        options.start->y <= box.ymax)) {
    throw NothingFitsError("no disk was placed: the start point " + format_point(*options.start) +
                           " lies outside the domain's bounding box [" + format_double(box.xmin) + ", " +
                           format_double(box.xmax) + "] x [" + format_double(box.ymin) + ", " +
                           format_double(box.ymax) + "]; the closed form grew its " + generated +
                           " from there and none lay inside the domain; give a start point in the domain (start, "
                           "--start)");
  }
  const double clearance = clearance_for(domain, options);
  if (rmin + clearance > bound) {
    if (options.clearance != 0) {
      throw NothingFitsError("no disk was placed: the clearance " + format_double(clearance) +
                             " (clearance, --clearance), which every disk keeps from the walls and from the other "
                             "disks, leaves no room: with it about a disk of the smallest radius, " +
                             r + ", no disk fits in this domain (none of radius above " + format_double(bound) +
                             " does); use a smaller clearance, or 0 (automatic)");
    }
    // The scale clearance_for() takes the ulps of.
    const double scale =
        std::min(domain.max_abs_coordinate() + 5 * options.radii.max(), std::numeric_limits<double>::max());
    const double step = scale - std::nextafter(scale, 0.0);
    char order[32];
    std::snprintf(order, sizeof order, "%.3g", scale);
    throw NothingFitsError(
        std::string("no disk was placed: at the scale of this fill (largest |coordinate| + 5 rmax = ") + order +
        ") doubles are " + format_double(step) +
        " apart, and the clearance that keeps tangent disks apart exactly there, " + format_double(clearance) +
        ", leaves no room for a disk of the smallest radius, " + r + ", in this domain (none of radius above " +
        format_double(bound) +
        " fits); move the domain near the origin (a periodic cell by whole periods) or narrow the "
        "radius range");
  }
  throw NothingFitsError(std::string("no disk was placed: the ") + to_string(options.method) + " form generated " +
                         generated + " and none lay inside the domain; use smaller radii" +
                         (options.method == Method::boundary ? "" : " or the boundary method (--method boundary)"));
}

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

}  // namespace frontpack::detail
