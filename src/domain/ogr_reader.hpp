// GeoJSON and Shapefile polygons, read with GDAL/OGR (Debian libgdal-dev).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "frontpack/domain.hpp"

namespace frontpack::detail {

struct GisPolygons {
  std::vector<Polygon> polygons;
  std::vector<std::vector<std::string>> ring_names;  ///< [part][ring]: "layer L, feature F, ring R"
};

/// Every Polygon and MultiPolygon feature of every layer, with `driver` ("GeoJSON" or "ESRI
/// Shapefile") only. Z is dropped. Throws DomainFileError (unreadable, empty, unsupported_entity
/// for other geometry types, curves included) naming the file, layer and feature. GDAL's messages
/// go into the error, never to stderr.
[[nodiscard]] GisPolygons read_ogr(const std::filesystem::path& path, const char* driver);

}  // namespace frontpack::detail
