// Fills with a target: a packing fraction, a count or a level (FillOptions::fraction, count,
// height). Each runs the plain fill (fill.cpp) one or more times and works on its certified
// result; nothing here places a disk.
#pragma once

#include <cstddef>
#include <functional>
#include <vector>

#include "frontpack/fill.hpp"

namespace frontpack::detail {

/// The plain fill: `options` without targets, its generators stopped after `generation_cap`
/// disks generated (culled ones included; at most options.max_disks).
using PlainFill = std::function<Packing(const Domain&, const FillOptions&, std::size_t generation_cap)>;

/// The disks' total area (pi r^2 summed in order), shared by the targets' fraction figures.
[[nodiscard]] double disk_area(const std::vector<Disk>& disks);

/// Whether options ask for a target.
[[nodiscard]] bool has_target(const FillOptions& options) noexcept;

/// Fills below the level (if any), to the fraction or to the count (at most one of the two), with
/// options that check_options() has accepted. Returns the plain fill's packing with the targets' disks
/// and their TargetReport in Packing::target; the disks culled against the unclipped domain are
/// counted there (outside_original), not in the certificate, which is the certifier's (fill() adds
/// them to it).
[[nodiscard]] Packing fill_with_targets(const Domain& domain, const FillOptions& options, const PlainFill& plain);

/// The fill to a fraction (target_fraction.cpp): options.fraction set, no height, no count.
[[nodiscard]] Packing fill_to_fraction(const Domain& domain, const FillOptions& options, const PlainFill& plain);

/// The fill to a count (fill_count.cpp): options.count > 0, no height, no fraction.
[[nodiscard]] Packing fill_to_count(const Domain& domain, const FillOptions& options, const PlainFill& plain);

}  // namespace frontpack::detail
