// frontpack: writing packings.
#pragma once

#include <filesystem>
#include <iosfwd>
#include <span>

#include "frontpack/domain.hpp"
#include "frontpack/geometry.hpp"

namespace frontpack {

struct SvgStyle {
  double width_px = 800;       ///< picture width; the height follows the domain's aspect ratio
  bool colour_by_size = true;  ///< small disks light, large disks dark
};

/// A minimal SVG picture: the domain's outline (holes included) and the disks.
void write_svg(std::ostream& out, const Domain& domain, std::span<const Disk> disks, const SvgStyle& style = {});

/// CSV "x,y,r" with a header; numbers in shortest round-trip form (reading them back gives the
/// same doubles, so a certificate holds for the file).
void write_csv(std::ostream& out, std::span<const Disk> disks);

}  // namespace frontpack
