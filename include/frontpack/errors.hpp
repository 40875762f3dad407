// frontpack: the error policy.
//
// The library never prints and never exits. Every failure it reports is an exception derived
// from frontpack::Error, whose what() is a complete, human-readable sentence naming the problem
// and where it is. The typed accessors carry the same facts for programs. Callers that only
// want a message catch frontpack::Error; the frontpack tool maps each type to its own exit code.
#pragma once

#include <cstddef>
#include <optional>
#include <stdexcept>
#include <string>

#include "frontpack/geometry.hpp"

namespace frontpack {

/// Base of every error frontpack throws.
class Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// A run stopped because its std::stop_token was requested (FillOptions::stop, StatsOptions::stop,
/// WriteOptions::stop, certify()'s `stop`): it returns nothing, and leaves no output file.
class CancelledError : public Error {
 public:
  CancelledError();
};

/// Invalid options: a radius spec or size table, a window, a limit. The message names the option
/// and the offending part.
class OptionError : public Error {
 public:
  using Error::Error;
};

/// A request that would exceed FillOptions::max_disks or memory_limit, refused up front with the
/// estimate in the message, or a run stopped at memory_limit; the message names the option to
/// raise, by its library and its tool name (max_disks, --max-disks).
class LimitError : public Error {
 public:
  LimitError(const std::string& message, std::size_t estimate) : Error(message), estimate_(estimate) {}
  [[nodiscard]] std::size_t estimate() const noexcept { return estimate_; }

 private:
  std::size_t estimate_;
};

/// A fill that placed no disk: fill() and Generator::run() never return an empty packing (unless
/// cancelled); the message names why, e.g. "no disk fits: the smallest radius of constant:2 is 2,
/// and no disk of radius above 0.5 fits in this domain; use smaller radii", or the fraction that
/// keeps none, the start point outside the domain, the clearance, the precision at the domain's
/// coordinates. The frontpack tool exits 8.
class NothingFitsError : public Error {
 public:
  using Error::Error;
};

/// A file could not be opened, read or written.
class IoError : public Error {
 public:
  IoError(const std::string& message, std::string path);
  [[nodiscard]] const std::string& path() const noexcept { return path_; }

 private:
  std::string path_;
};

/// The WKT text is not a 2D POLYGON or MULTIPOLYGON that frontpack can read.
///
/// offset() is the 0-based character offset into the text, line() and column() are 1-based.
class WktError : public Error {
 public:
  enum class Kind {
    syntax,                ///< malformed text: an unexpected token, a missing parenthesis or comma
    unsupported_geometry,  ///< a geometry type other than POLYGON / MULTIPOLYGON
    empty_geometry,        ///< EMPTY (a domain must have area)
    dimension,             ///< Z / M / ZM geometries or points with more than 2 coordinates
    bad_number,            ///< a non-finite (nan, inf) or out-of-range number
  };
  /// `source` names where the text came from (a file name), or is empty.
  WktError(Kind kind, std::string detail, std::size_t offset, std::size_t line, std::size_t column,
           std::string source = {});

  [[nodiscard]] Kind kind() const noexcept { return kind_; }
  /// The message without its position prefix, e.g. "expected ',' or ')' in a ring's list of points, found 'x'".
  [[nodiscard]] const std::string& detail() const noexcept { return detail_; }
  [[nodiscard]] const std::string& source() const noexcept { return source_; }
  [[nodiscard]] std::size_t offset() const noexcept { return offset_; }
  [[nodiscard]] std::size_t line() const noexcept { return line_; }
  [[nodiscard]] std::size_t column() const noexcept { return column_; }

 private:
  Kind kind_;
  std::string detail_;
  std::string source_;
  std::size_t offset_;
  std::size_t line_;
  std::size_t column_;
};

/// The geometry is not a valid polygonal domain (OGC Simple Features validity).
///
/// part() and ring() index the input as given (ring 0 is the outer ring, ring k >= 1 the k-th
/// hole); vertex() and other_vertex() are 0-based indices of vertices in their rings as written
/// (an edge i runs from vertex i to vertex i + 1). Facts that do not apply are empty.
class InvalidDomainError : public Error {
 public:
  enum class Kind {
    empty,                    ///< no polygon at all
    non_finite_coordinate,    ///< nan or inf in a coordinate
    coordinate_out_of_range,  ///< |coordinate| above frontpack::max_coordinate
    unclosed_ring,            ///< a WKT ring whose last point differs from its first
    too_few_vertices,         ///< fewer than 3 distinct vertices
    zero_area,                ///< all vertices of a ring are collinear
    self_intersection,        ///< two edges of one ring intersect (crossing, touching, or a spike)
    rings_cross,              ///< two rings cross (properly, or at a common point)
    rings_overlap,            ///< two rings share a segment of positive length
    hole_outside_shell,       ///< a hole not inside its outer ring
    nested_holes,             ///< a hole inside another hole of the same polygon
    overlapping_parts,        ///< the interiors of two polygons of a multipolygon intersect
    disconnected_interior,    ///< touching rings split the interior of a polygon
  };

  struct Site {
    std::size_t part = 0;
    std::size_t ring = 0;
    std::optional<std::size_t> vertex;
  };

  InvalidDomainError(Kind kind, const std::string& detail, Site site, std::optional<Site> other = {},
                     std::optional<Point> where = {});

  [[nodiscard]] Kind kind() const noexcept { return kind_; }
  [[nodiscard]] const Site& site() const noexcept { return site_; }
  [[nodiscard]] const std::optional<Site>& other_site() const noexcept { return other_; }
  /// The offending point, where one exists (an intersection, a touch point, a bad vertex).
  [[nodiscard]] const std::optional<Point>& where() const noexcept { return where_; }

 private:
  Kind kind_;
  Site site_;
  std::optional<Site> other_;
  std::optional<Point> where_;
};

/// A disk file (CSV, Yade text) that does not follow its format. what() reads
/// "SOURCE:LINE: DETAIL" or "SOURCE:LINE:COLUMN: DETAIL", e.g.
/// "disks.csv:17: expected 3 comma-separated numbers, got 'abc,1'".
///
/// line() is 1-based; column() is the 1-based character column of the offending field, or 0 when
/// the problem is the whole line or file.
class DiskFileError : public Error {
 public:
  enum class Kind {
    empty_file,          ///< no line at all
    missing_header,      ///< a CSV whose first line is not "x,y,r"
    blank_line,          ///< an empty (or whitespace-only) line
    field_count,         ///< not exactly the number of fields the format has
    bad_number,          ///< a field that is not a decimal number, or is out of the double range
    non_finite,          ///< nan or inf
    bad_radius,          ///< a radius <= 0
    nonzero_z,           ///< a Yade z coordinate other than 0
    unsupported_format,  ///< a Yade "#format" other than x_y_z_r or x_y_z_r_matId, a LAMMPS atom style
                         ///< other than sphere, VTK data compressed or in a layout frontpack does not read
    syntax,              ///< a line or XML element that is not what the format has there
    missing_item,        ///< a required header, section, column, element or array is absent
    count_mismatch,      ///< fewer or more entries than the file declares (atoms, points, values)
    duplicate_id,        ///< a LAMMPS atom id given twice, or a dump's timestep (two snapshots of one)
  };
  DiskFileError(Kind kind, std::string detail, std::string source, std::size_t line, std::size_t column = 0);

  [[nodiscard]] Kind kind() const noexcept { return kind_; }
  /// The message without its "source:line:" prefix.
  [[nodiscard]] const std::string& detail() const noexcept { return detail_; }
  [[nodiscard]] const std::string& source() const noexcept { return source_; }
  [[nodiscard]] std::size_t line() const noexcept { return line_; }
  [[nodiscard]] std::size_t column() const noexcept { return column_; }

 private:
  Kind kind_;
  std::string detail_;
  std::string source_;
  std::size_t line_;
  std::size_t column_;
};

/// A CAD or GIS file (DXF, GeoJSON, Shapefile) that does not describe a domain frontpack can read.
/// what() reads "SOURCE: ENTITY: DETAIL", or "SOURCE: DETAIL" when no entity applies, e.g.
/// "drum.dxf: LWPOLYLINE (handle 31, line 140): open contour: its end (1 0) meets no other entity".
class DomainFileError : public Error {
 public:
  enum class Kind {
    unreadable,          ///< the reader rejects the file (not DXF, not GeoJSON, a broken shapefile)
    empty,               ///< no closed contour, no polygon
    unsupported_entity,  ///< an entity or geometry type frontpack does not read (ELLIPSE, SPLINE, INSERT, a LineString)
    open_contour,        ///< a chain of LINE, ARC or open polyline entities that does not close
    branching_contour,   ///< three or more entity ends meet at one point
    bad_curve,           ///< a non-finite or non-positive radius, a bulge whose arc is not representable
    truncated,           ///< DXF: the file ends before its EOF group (cut short)
    bad_structure,       ///< DXF: a group code that is not one, a SECTION without ENDSEC, a group out of place
    bad_number,          ///< DXF: a numeric group value that is not a finite number in range (or not whole)
  };
  DomainFileError(Kind kind, std::string detail, std::string source, std::string entity = {});

  [[nodiscard]] Kind kind() const noexcept { return kind_; }
  [[nodiscard]] const std::string& detail() const noexcept { return detail_; }
  [[nodiscard]] const std::string& source() const noexcept { return source_; }
  /// The entity named, e.g. "ARC (handle 3A, line 210)", or empty.
  [[nodiscard]] const std::string& entity() const noexcept { return entity_; }

 private:
  Kind kind_;
  std::string detail_;
  std::string source_;
  std::string entity_;
};

/// Name of an error kind, as used in messages and in the test corpus (e.g. "self_intersection").
[[nodiscard]] const char* to_string(WktError::Kind kind) noexcept;
[[nodiscard]] const char* to_string(InvalidDomainError::Kind kind) noexcept;
[[nodiscard]] const char* to_string(DiskFileError::Kind kind) noexcept;
[[nodiscard]] const char* to_string(DomainFileError::Kind kind) noexcept;

}  // namespace frontpack
