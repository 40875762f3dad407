// A DXF file's group stream, read and checked before dxflib sees it (docs/cad-gis.md, "What a DXF
// file must be"). dxflib reads a group as two lines with fgets and strtol/atof-like conversions:
// a file cut short loses its last entity (an entity is handed over when the next one's "0" group
// arrives), a value that does not parse becomes 0, and a line longer than its buffer is split in
// two. So the file is read here first: every group code is an integer from 0 to 1071, sections
// open and close, the file ends with its EOF group, and every numeric value is read by the
// project's one number rule (common/numbers.hpp) where the reader uses it. dxflib then reads the
// groups as checked here, re-written one value per line (dxf_reader.cpp).
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace frontpack::detail {

/// One group: its code, its value as written (leading and trailing blanks and the line end
/// removed, as dxflib removes them), and the file line of its value (1-based).
struct DxfGroup {
  int code = 0;
  std::string_view value;
  std::size_t line = 0;
};

/// The groups of `text` up to and including the EOF group; what follows EOF is not read. Throws
/// DomainFileError naming `source` and the line: truncated (the file ends before EOF, or on a
/// group code without its value), bad_structure (a code that is not an integer from 0 to 1071, a
/// line over dxflib's 1022 characters or holding a NUL byte, a SECTION without its name or its
/// ENDSEC, a group between sections other than SECTION, EOF or a comment).
[[nodiscard]] std::vector<DxfGroup> read_dxf_groups(std::string_view text, const std::string& source);

/// Checks the counts dxflib allocates by before the items they count arrive (LWPOLYLINE group 90,
/// SPLINE groups 72, 73 and 74, LEADER group 76), in every section: a whole number from 0 to the
/// number of the entity's groups, and an LWPOLYLINE's 90 equal to its vertices (groups 10), since
/// dxflib drops the vertices past the count and hands over (0, 0) for those missing (an LWPOLYLINE
/// without a group 90 is refused: dxflib would take the previous one's). Throws DomainFileError
/// (bad_number; bad_structure for a missing 90) naming the entity, the group, its line and the value.
void check_dxf_counts(const std::vector<DxfGroup>& groups, const std::string& source);

/// An entity's name in messages: "CIRCLE (handle 2F, line 120)"; a type or handle that is not a
/// short word is quoted (quote_text), so that no message carries raw control bytes or a long line.
[[nodiscard]] std::string dxf_entity_name(std::string_view type, std::string_view handle, std::size_t line);

/// What a group code's value is, by the DXF reference's code ranges.
enum class DxfValueType { text, real, integer };
[[nodiscard]] DxfValueType dxf_value_type(int code) noexcept;

/// A real value by the one number rule, or a DomainFileError (bad_number) naming `source`,
/// `entity`, the group's code and line and the value as written.
[[nodiscard]] double dxf_real(const DxfGroup& g, const std::string& source, const std::string& entity);

/// A whole number from `min` to `max`, or a DomainFileError (bad_number) as dxf_real's.
[[nodiscard]] long long dxf_integer(const DxfGroup& g, long long min, long long max, const std::string& source,
                                    const std::string& entity);

/// Checks a numeric group's value (real or integer, by its code) and refuses it as dxf_real does.
void check_dxf_number(const DxfGroup& g, const std::string& source, const std::string& entity);

/// The units $INSUNITS `code` names ("unitless" for 0, "millimeters" for 4, ...), for codes 0 to 24.
[[nodiscard]] const char* dxf_units_name(long long code) noexcept;
inline constexpr long long kDxfUnitsMax = 24;

}  // namespace frontpack::detail
