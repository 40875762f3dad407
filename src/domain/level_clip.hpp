// A domain clipped to a level: the part below y = height (FillOptions::height). CGAL stays in
// level_clip.cpp.
#pragma once

#include "frontpack/domain.hpp"

namespace frontpack::detail {

/// The domain's part below the level: the intersection with the half-plane y <= height, computed
/// exactly, its vertices rounded to doubles on the domain's side. Vertices of the domain are kept
/// as they are; each new vertex lies on y = height exactly (height is a double), with its x, the
/// crossing of an edge with the level, rounded to a double and then moved along the level, an ulp
/// at a time, until the domain holds it (Domain::locate, exact): the clipped rings lie in the
/// domain up to the thin slivers between a rounded edge and the edge it lies along, which the fill
/// certifies away (fill() certifies its disks against the unclipped domain too). Returns `domain`
/// itself for a level at or above its top; a clip that splits a polygon gives several polygons.
/// Throws OptionError for a level at or below the domain's lowest point (nothing to fill) or not
/// finite, InvalidDomainError if the rounded clip is not a valid domain (a sliver thinner than
/// the rounding).
[[nodiscard]] Domain clip_below(const Domain& domain, double height);

}  // namespace frontpack::detail
