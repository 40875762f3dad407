// Every check of the fill options alone and with the domain (frontpack/options.hpp,
// check_options()), and the clearance tangent disks keep (clearance.hpp). Checks that need a run's
// results (a fraction above the one the method reaches, the estimates against the budget) stay
// where those results are.
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "common/format.hpp"
#include "frontpack/options.hpp"
#include "options/clearance.hpp"

namespace frontpack {

namespace {

using detail::format_double;

std::string label(std::string_view name) {
  return option_label(fill_option(name));
}

// Whether a value lies in its option's range. A count or a real at its default means "not given"
// (count 0: no count; clearance 0: automatic), and an optional option not given is none.
bool in_range(const OptionInfo& info, const OptionValue& value) {
  const OptionValue given = default_value(info);
  if (const auto* n = std::get_if<std::uint64_t>(&value); n != nullptr && info.kind == OptionKind::count) {
    return *n == std::get<std::uint64_t>(given) || (*n >= info.count_min && *n <= info.count_max);
  }
  if (const auto* x = std::get_if<double>(&value)) {
    const auto* d = std::get_if<double>(&given);
    const bool above = info.real_min_open ? *x > info.real_min : *x >= info.real_min;
    const bool below = info.real_max_open ? *x < info.real_max : *x <= info.real_max;
    return (d != nullptr && *x == *d) || (std::isfinite(*x) && above && below);
  }
  if (const auto* p = std::get_if<Point>(&value)) {
    return std::isfinite(p->x) && std::isfinite(p->y);
  }
  return true;
}

// Every value in its option's range, or its default.
void check_ranges(const FillOptions& o) {
  for (const OptionInfo& info : fill_option_list()) {
    const OptionValue value = info.get(o);
    if (!in_range(info, value)) {
      throw OptionError(std::string(info.name) + " " + value_text(info, value) + ": expected " + expected_text(info));
    }
  }
}

// Fills with a target (FillOptions::fraction, count, height; docs/fraction.md).
void check_targets(const Domain& domain, const FillOptions& o) {
  if (o.jam && (o.fraction || o.count != 0)) {
    throw OptionError(o.fraction
                          ? "jam makes the packing as dense as it gets; a target fraction leaves gaps: give one or "
                            "the other"
                          : "jam inserts disks until the packing jams; a count stops at a number of disks: give "
                            "one or the other");
  }
  if (o.fraction && o.count > 0) {
    throw OptionError("a target fraction and a count together over-determine the fill: give one of them");
  }
  if (o.count > 0 && o.method == Method::boundary) {
    throw OptionError(
        "count: the boundary method starts its fronts on every wall at once, so its first disks line all the "
        "walls and a count would leave the middle empty; use --method open (fills from the bottom, layer by "
        "layer) or --method closed (a blob grown from the start point)");
  }
  if (o.count > o.max_disks) {
    throw OptionError("count " + std::to_string(o.count) + " exceeds max_disks = " + std::to_string(o.max_disks));
  }
  if (o.height && domain.periodicity() != Periodicity::none) {
    throw OptionError("height: a periodic cell has no level to fill to (it has no bottom on a periodic axis)");
  }
}

// The closed form's start point: the closed form only, one polygon (each polygon of several is
// filled from the centre of its own box).
void check_start(const Domain& domain, const FillOptions& o) {
  if (!o.start) {
    return;
  }
  if (o.method != Method::closed) {
    throw OptionError(label("start") + " is where the closed form (method closed) places its first disks; the " +
                      to_string(o.method) + " form has no start point");
  }
  if (domain.num_polygons() > 1) {
    throw OptionError(label("start") + ": the domain has " + std::to_string(domain.num_polygons()) +
                      " polygons, each filled from its own start (the centre of its bounding box); a start point "
                      "takes a domain of one polygon");
  }
}

// A periodic cell: the boundary method and the closed form wrap around it (the open form, which
// grows from the bottom of a box with walls, does not).
void check_periodic(const Domain& domain, const FillOptions& o, double clearance) {
  if (domain.periodicity() == Periodicity::none) {
    return;
  }
  if (o.method == Method::open) {
    throw OptionError(
        "a periodic cell is filled by the boundary method or the closed form; the open form does not wrap around a "
        "cell");
  }
  // Each front segment and each disk's reach are a few times the larger of rmax and the clearance
  // (tangent disks are placed the clearance apart): at 10 times it their images are far enough
  // apart that the nearest image is the one meant (periodic/wrap.hpp). The clearance is a
  // few ulps of the coordinates, so it is the larger only for a cell far from the origin against
  // its size (at 1.4e10 it is 2e-4: a cell a few ulps across had a tangent disk placed many periods
  // away, and the nearest image made it overlap its neighbours).
  const Box cell = domain.bbox();
  const bool precision = clearance > o.radii.max();
  const double least = 10 * std::max(o.radii.max(), clearance);
  const bool narrow =
      cell.xmax - cell.xmin < least || (domain.periodicity() == Periodicity::xy && cell.ymax - cell.ymin < least);
  if (narrow) {
    const std::string size = format_double(cell.xmax - cell.xmin) + " x " + format_double(cell.ymax - cell.ymin);
    if (!precision) {
      throw OptionError("a periodic cell must be at least 10 rmax = " + format_double(least) +
                        " across each periodic direction; it is " + size);
    }
    throw OptionError(
        "a periodic cell must be at least 10 times the clearance that keeps tangent disks apart "
        "exactly at its coordinates (largest |coordinate| " +
        format_double(domain.max_abs_coordinate()) + ": clearance " + format_double(clearance) +
        ", larger than rmax), " + format_double(least) + ", across each periodic direction; it is " + size +
        ": move the cell near the origin, by whole periods");
  }
  if (o.start &&
      (o.start->x < cell.xmin || o.start->x >= cell.xmax || o.start->y < cell.ymin || o.start->y >= cell.ymax)) {
    throw OptionError("the start point must lie in the periodic cell");
  }
}

}  // namespace

void check_options(const Domain& domain, const FillOptions& o) {
  check_ranges(o);
  (void)o.radii.distribution();  // throws if empty
  check_targets(domain, o);
  if (o.method == Method::boundary && !o.fill_voids) {
    // Its voids are half of the method: without them every gap that a drawn radius does not fit
    // is dropped, and the packing keeps large empty areas (packing fraction 0.63-0.65).
    throw OptionError(
        "fill_voids = false gives the paper's forms as published (methods closed and open); the "
        "boundary method keeps its voids always (without them it leaves large empty areas)");
  }
  check_start(domain, o);
  check_periodic(domain, o, detail::clearance_for(domain, o));
}

namespace detail {

// The clearance: a few ulps of the largest coordinate any disk centre can have (the domain's,
// plus the margin by which generated disks overhang the filled box), so that neither the
// floating-point tangency nor the rounding of the output (box corner + local position) can make
// tangent disks overlap. docs/robustness.md, "Clearance".
double clearance_for(const Domain& domain, const FillOptions& o) {
  // (At most the largest double: radii beyond about 3.6e307 made it infinite.)
  const double scale = std::min(domain.max_abs_coordinate() + 5 * o.radii.max(), std::numeric_limits<double>::max());
  if (!(scale >= std::numeric_limits<double>::min())) {
    // Every coordinate and radius subnormal: a clearance of a few ulps underflows to 0.
    throw OptionError(
        "the domain and the radii are too small: their size (largest |coordinate| + 5 rmax = " + format_double(scale) +
        ") must be at least 2.2250738585072014e-308, the smallest normal double, for a clearance of a "
        "few ulps to separate tangent disks; scale the domain up (by a power of two, which is exact)");
  }
  const double minimum = 16 * 0x1p-52 * scale;
  if (o.clearance == 0) {
    return 4 * minimum;
  }
  if (!std::isfinite(o.clearance) || o.clearance < minimum) {
    throw OptionError("clearance must be 0 (automatic) or a finite number >= " + format_double(minimum) +
                      " for this domain and radius range, got " + format_double(o.clearance));
  }
  return o.clearance;
}

}  // namespace detail

}  // namespace frontpack
