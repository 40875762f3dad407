// The tool's domain files: WKT, DXF, GeoJSON, Shapefile (frontpack::read_domain_file), the curve
// deviation a command chooses, and the lines that say what each curve became.
#pragma once

#include <string>

#include "frontpack/frontpack.hpp"
#include "report.hpp"

namespace frontpack_tool {

/// Reads `file` as `format` ("" or "auto": by extension) with `max_deviation` (text of
/// --max-deviation; "" for `default_deviation`, and 0 there for the library's relative default),
/// within `budget`.
[[nodiscard]] frontpack::DomainFile read_domain(const std::string& file, const std::string& format,
                                                const std::string& max_deviation, double default_deviation,
                                                const frontpack::Budget& budget);

/// DXF: the "units:" line, the drawing units the file's $INSUNITS names or that it names none
/// (coordinates are used as written either way); "" for the other formats.
[[nodiscard]] std::string units_line(const frontpack::DomainFile& file);

/// "curves:" summary lines, one per curve (the first `max_lines`, then a count), or "" when the
/// file has none.
[[nodiscard]] std::string curve_lines(const frontpack::DomainFile& file, std::size_t max_lines);

/// The curves as JSON: one object per arc (entity, centre, radius, sweep_degrees, domain_inside,
/// deviation, segments, nudged).
[[nodiscard]] Json curves_json(const frontpack::DomainFile& file);

}  // namespace frontpack_tool
