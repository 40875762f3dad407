// DXF entities to contours, read with dxflib (Debian libdxflib-dev). OGR's DXF driver (GDAL 3.6)
// hands arcs over only as tessellated linestrings, with their centre and radius lost; dxflib
// gives each CIRCLE's and ARC's centre, radius and angles, and each polyline vertex's bulge, as
// written (docs/cad-gis.md).
#pragma once

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include "domain/contour.hpp"
#include "domain/contour_chain.hpp"
#include "frontpack/geometry.hpp"

namespace frontpack::detail {

struct DxfContents {
  std::vector<Contour> closed;  ///< CIRCLEs and closed polylines
  std::vector<Piece> open;      ///< LINEs, ARCs and open polylines, to be chained
  std::size_t ignored = 0;      ///< annotation entities skipped
  Box extent;                   ///< of every point and every circle
  std::string units;            ///< $INSUNITS named ("millimeters"), or "" when absent
};

/// Reads the ENTITIES section of an ASCII DXF file, after checking its group structure and its
/// numbers (dxf_groups.hpp). Throws IoError, and DomainFileError naming the file, the entity type,
/// its handle and its line, and the line and text of a bad value.
[[nodiscard]] DxfContents read_dxf(const std::filesystem::path& path);

}  // namespace frontpack::detail
