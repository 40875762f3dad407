// GeoJSON and Shapefile polygons, read with GDAL/OGR (Debian libgdal-dev).
//
// GDAL lives in a module of its own (frontpack_ogr.so, domain/ogr_module.cpp) that the library
// loads with dlopen the first time it reads such a file: a program that never reads one does not
// load GDAL and its hundred libraries (70 ms at every start, and OpenBLAS's threads), and the
// library's users do not link them. This header is shared by both sides of that boundary.
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

/// What the module returns: the polygons, or an error (error = 1 + a DomainFileError::Kind).
struct OgrResult {
  GisPolygons gis;
  int error = 0;
  std::string message;
  std::string entity;
};

/// The module's one entry point, `frontpack_ogr_read`, found with dlsym. Never throws.
using OgrReadFunction = void(const char* path, const char* driver, OgrResult* out);

/// Every Polygon and MultiPolygon feature of every layer, with `driver` ("GeoJSON" or "ESRI
/// Shapefile") only. Z is dropped. Throws DomainFileError (unreadable, empty, unsupported_entity
/// for other geometry types, curves included) naming the file, layer and feature, and unreadable
/// if the module cannot be loaded. GDAL's messages go into the error, never to stderr.
///
/// GeoJSON is read as text first (at most kMaxInputBytes, common/read_file.hpp), its numbers
/// checked by the one number rule (domain/geojson_numbers.hpp), and GDAL reads that very text from
/// a memory file; a Shapefile (binary, three files) GDAL reads by path.
[[nodiscard]] GisPolygons read_ogr(const std::filesystem::path& path, const char* driver);

}  // namespace frontpack::detail
