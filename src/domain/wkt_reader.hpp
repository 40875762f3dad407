// A strict WKT reader for 2D POLYGON and MULTIPOLYGON with exact error positions.
//
// We do not hand user text to CGAL's WKT reader: in CGAL 5.5 it crashes on `POLYGON EMPTY`, traps
// on NaN with Epeck, and silently accepts unclosed rings (see shared/design.md). This reader checks
// the grammar only; geometric validity is the Domain's job.
#pragma once

#include <cstddef>
#include <string_view>
#include <vector>

#include "frontpack/geometry.hpp"

namespace frontpack::detail {

struct ParsedRing {
  std::vector<Point> points;         ///< as written, closing point included
  std::vector<std::size_t> offsets;  ///< character offset of each point
};

struct ParsedPolygon {
  std::vector<ParsedRing> rings;  ///< ring 0 outer, the rest holes
};

/// Throws WktError (with offset, line and column) on anything but a 2D POLYGON / MULTIPOLYGON.
/// Numbers are decoded with correct rounding (std::from_chars); one out of the range of doubles,
/// overflowing or underflowing to 0, is refused (bad_number), as by every reader (common/numbers.hpp).
/// Offending tokens are quoted by quote_text() (escaped, at most 40 characters).
[[nodiscard]] std::vector<ParsedPolygon> parse_wkt(std::string_view text);

/// 1-based line and column of a character offset.
struct TextPosition {
  std::size_t line = 1;
  std::size_t column = 1;
};
[[nodiscard]] TextPosition text_position(std::string_view text, std::size_t offset) noexcept;

}  // namespace frontpack::detail
