// frontpack: domains from files. WKT always; DXF (CAD), GeoJSON and Shapefile (GIS) when the
// library is built with its readers (dxflib for DXF, GDAL/OGR for GeoJSON and Shapefile; see
// has_cad_readers() and docs/cad-gis.md).
//
// Curves made safe. A DXF boundary may hold circular arcs (CIRCLE, ARC, polyline bulges). Each arc
// is replaced by a polyline that lies on the DOMAIN'S side of the true arc, at most a stated
// deviation from it: chords (vertices on the arc) where the domain is inside the arc's circle, a
// tangent polyline (vertices at R / cos(theta / 2)) where the domain is outside it (a hole, a pipe,
// a concave fillet). Which side the domain is on follows from nesting the contours and their
// orientation. Every vertex frontpack constructs is checked exactly (multiprecision arithmetic)
// against the circle and moved by an ulp toward the domain's side until the check holds, so a disk
// certified inside the polygonal domain is inside the true curved domain too. The circle of an arc
// is its centre and radius as read (CIRCLE, ARC), or as computed in double from a bulge's endpoints;
// the arc's given endpoints are kept as written, so the polyline comes no nearer to the curve's
// wrong side than those endpoints are.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "frontpack/budget.hpp"
#include "frontpack/domain.hpp"
#include "frontpack/formats.hpp"
#include "frontpack/geometry.hpp"

namespace frontpack {

/// "auto", or the format's name in the table of formats (frontpack/formats.hpp).
[[nodiscard]] const char* to_string(DomainFormat format) noexcept;
/// "auto", "wkt", "dxf", "geojson", "shapefile" (also "shp", "json"), case-insensitively, by the
/// table of formats. Throws OptionError.
[[nodiscard]] DomainFormat parse_domain_format(std::string_view name);
/// The format a file's extension names (case-insensitive, by the table of formats): .dxf,
/// .geojson or .json, .shp; WKT for any other name (.wkt, .txt, none): a WKT file may be named
/// anything.
[[nodiscard]] DomainFormat domain_format_of(const std::filesystem::path& path);

/// Whether this build reads DXF, and GeoJSON and Shapefile (configure-time options
/// FRONTPACK_WITH_DXFLIB and FRONTPACK_WITH_GDAL). Without them read_domain_file() throws
/// OptionError for those formats; WKT is always read.
[[nodiscard]] bool has_dxf_reader() noexcept;
[[nodiscard]] bool has_gis_reader() noexcept;

/// Default relative deviation of a curve's polyline: 1e-3 of the curve's radius (a full circle
/// becomes a 71-gon of chords, or a 71-gon of tangents).
inline constexpr double default_relative_deviation = 1e-3;
/// Largest number of segments one arc may become; a deviation that would need more is refused.
inline constexpr std::size_t max_segments_per_curve = 1u << 20;

struct DomainReadOptions {
  DomainFormat format = DomainFormat::automatic;
  /// Largest distance between a curve and its polyline, in the file's units. 0: use
  /// relative_deviation x the curve's radius. Must be finite and >= 0.
  double max_deviation = 0.0;
  /// Used when max_deviation is 0. Must be finite and > 0.
  double relative_deviation = default_relative_deviation;
  /// DXF: two endpoints of LINE, ARC or open polyline entities join when they are at most this
  /// far apart, relative to the drawing's extent (the largest side of its bounding box). ARC
  /// endpoints are computed from centre, radius and angles, so they never meet a LINE's written
  /// endpoint exactly.
  double join_tolerance = 1e-9;
  /// What reading may make: the arc segments (every curve's polyline, counted before any is
  /// split) and the bytes the file's text takes.
  Budget budget{};
};

/// One arc (or full circle) of the file, and the polyline it became.
struct CurveReport {
  std::string entity;  ///< e.g. "CIRCLE (handle 2F, line 120)", "LWPOLYLINE (handle 31, line 140), edge 0"
  Point centre{};      ///< the circle's centre and radius, as used for the safe-side checks
  double radius = 0.0;
  double sweep = 0.0;         ///< radians, > 0 (2 pi for a full circle)
  bool domain_inside = true;  ///< domain inside the circle: chords; else a tangent polyline
  double deviation = 0.0;     ///< the largest distance between polyline and arc (before ulp nudges)
  std::size_t segments = 0;   ///< segments the arc became
  std::size_t nudged = 0;     ///< vertices moved by an ulp or more to the safe side after rounding
};

struct DomainFile {
  Domain domain;
  DomainFormat format = DomainFormat::wkt;
  std::size_t contours = 0;          ///< closed contours (rings) read
  std::size_t ignored_entities = 0;  ///< DXF annotation entities skipped (TEXT, MTEXT, DIMENSION, POINT, HATCH, ...)
  std::vector<CurveReport> curves;   ///< every arc, in file order
  /// DXF: the drawing units its HEADER's $INSUNITS names ("millimeters", "inches", "unitless", ...);
  /// empty when the file does not say, and for the other formats. Coordinates are never scaled.
  std::string units;
};

/// Reads a domain from a WKT, DXF, GeoJSON or Shapefile file.
///
/// WKT: as Domain::from_wkt_file. GeoJSON and Shapefile: every Polygon and MultiPolygon feature of
/// every layer, taken as polygons with holes as given (Z is dropped); other geometry types are an
/// error. DXF: the ENTITIES section's CIRCLE, ARC, LINE, LWPOLYLINE and 2D POLYLINE (with bulges);
/// closed polylines and circles are contours, LINE, ARC and open polylines are joined end to end
/// into contours. Contours nest by containment: a contour inside an even number of others is an
/// outer boundary, inside an odd number a hole of the one just around it. Annotation entities are
/// skipped and counted; block definitions are not read.
///
/// Throws IoError (unreadable file), OptionError (bad options, a reader this build lacks), DomainFileError (an
/// unsupported entity or geometry, an open contour, an empty file, a bad curve), WktError, and InvalidDomainError
/// (crossing or touching contours, a contour crossing itself), each naming the file and, for DXF, the entities and
/// their lines.
[[nodiscard]] DomainFile read_domain_file(const std::filesystem::path& path, const DomainReadOptions& options = {});

}  // namespace frontpack
