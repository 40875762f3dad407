// The numbers of a GeoJSON file, checked by the one number rule (common/numbers.hpp) before GDAL
// reads it. GDAL's JSON parser reads '1e-400' as 0 and '1.5.5' as a number, and its errors name
// neither the line nor the text: so every number token of the text is read here first.
#pragma once

#include <string>
#include <string_view>

namespace frontpack::detail {

/// Throws DomainFileError (bad_number) naming `source`, the line and the token as written (quoted)
/// for the first token outside a string that is not a JSON number in the range of a double
/// ('1.5.5', '+1', '0x10', '1e400', '1e-400', '.5') or is a bare word other than true, false and
/// null ('nan', 'Infinity'). Strings (with their escapes) are skipped whole; the JSON structure
/// is left to GDAL, and so is text that does not open a JSON object or array (not GeoJSON at all:
/// a DXF file given as GeoJSON is GDAL's "could not read the file as GeoJSON").
void check_geojson_numbers(std::string_view text, const std::string& source);

}  // namespace frontpack::detail
