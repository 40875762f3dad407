#include "domain/wkt_reader.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <string>

#include "common/numbers.hpp"
#include "common/text.hpp"
#include "frontpack/errors.hpp"

namespace frontpack::detail {

TextPosition text_position(std::string_view text, std::size_t offset) noexcept {
  TextPosition pos;
  const std::size_t end = std::min(offset, text.size());
  for (std::size_t i = 0; i < end; ++i) {
    if (text[i] == '\n') {
      ++pos.line;
      pos.column = 1;
    } else {
      ++pos.column;
    }
  }
  return pos;
}

namespace {

bool is_space(char c) noexcept {
  return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f' || c == '\v';
}
bool is_alpha(char c) noexcept {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_';
}
bool is_digit(char c) noexcept {
  return c >= '0' && c <= '9';
}

std::string upper(std::string_view s) {
  return ascii_upper(s);
}

// Other OGC / ISO geometry types: recognised so that the message can say "unsupported" rather
// than "syntax error".
constexpr std::array<std::string_view, 16> other_types = {
    "POINT",        "LINESTRING", "MULTIPOINT",        "MULTILINESTRING", "GEOMETRYCOLLECTION",
    "TRIANGLE",     "TIN",        "POLYHEDRALSURFACE", "CIRCULARSTRING",  "COMPOUNDCURVE",
    "CURVEPOLYGON", "MULTICURVE", "MULTISURFACE",      "CURVE",           "SURFACE",
    "GEOMETRY"};

class Parser {
 public:
  explicit Parser(std::string_view text) : text_(text) {}

  std::vector<ParsedPolygon> parse() {
    if (text_.substr(0, 3) == "\xEF\xBB\xBF") {
      pos_ = 3;  // a UTF-8 byte order mark, as some editors write
    }
    skip_space();
    const std::size_t start = pos_;
    const std::string_view word = read_word();
    if (word.empty()) {
      fail(WktError::Kind::syntax, "expected POLYGON or MULTIPOLYGON, found " + describe_here(start), start);
    }
    const std::string keyword = upper(word);
    if (keyword == "SRID" || (pos_ < text_.size() && text_[pos_] == '=')) {
      fail(WktError::Kind::syntax, "extended WKT (SRID=...;) is not supported; give the geometry only", start);
    }
    for (const char* base : {"POLYGON", "MULTIPOLYGON"}) {
      const std::string b(base);
      if (keyword.size() > b.size() && keyword.compare(0, b.size(), b) == 0) {
        const std::string dim = keyword.substr(b.size());
        if (dim == "Z" || dim == "M" || dim == "ZM") {
          fail(WktError::Kind::dimension, dim + " coordinates are not supported: frontpack domains are 2D (x y)",
               start + b.size());
        }
      }
    }
    std::vector<ParsedPolygon> polygons;
    if (keyword == "POLYGON") {
      reject_dimension();
      polygons.push_back(parse_polygon_text("POLYGON EMPTY"));
    } else if (keyword == "MULTIPOLYGON") {
      reject_dimension();
      parse_multipolygon_text(polygons);
    } else if (is_other_type(keyword)) {
      fail(WktError::Kind::unsupported_geometry,
           "unsupported geometry type " + keyword + ": a domain must be a POLYGON or MULTIPOLYGON", start);
    } else {
      fail(WktError::Kind::syntax, "expected POLYGON or MULTIPOLYGON, found " + quote_text(word), start);
    }
    skip_space();
    if (pos_ < text_.size()) {
      fail(WktError::Kind::syntax, "unexpected " + describe_here(pos_) + " after the end of the geometry", pos_);
    }
    return polygons;
  }

 private:
  [[noreturn]] void fail(WktError::Kind kind, const std::string& detail, std::size_t offset) const {
    const TextPosition p = text_position(text_, offset);
    throw WktError(kind, detail, offset, p.line, p.column);
  }

  void skip_space() noexcept {
    while (pos_ < text_.size() && is_space(text_[pos_])) {
      ++pos_;
    }
  }

  std::string_view read_word() noexcept {
    const std::size_t start = pos_;
    while (pos_ < text_.size() && is_alpha(text_[pos_])) {
      ++pos_;
    }
    return text_.substr(start, pos_ - start);
  }

  // The token at `offset`, quoted (quote_text(): at most 40 characters, escaped), for "found ..."
  // in messages.
  std::string describe_here(std::size_t offset) const {
    if (offset >= text_.size()) {
      return "end of input";
    }
    std::size_t end = offset;
    if (is_alpha(text_[offset]) || is_digit(text_[offset]) || text_[offset] == '-' || text_[offset] == '+' ||
        text_[offset] == '.') {
      while (end < text_.size() && !is_space(text_[end]) && text_[end] != '(' && text_[end] != ')' &&
             text_[end] != ',') {
        ++end;
      }
    } else {
      end = offset + 1;
    }
    return quote_text(text_.substr(offset, end - offset));
  }

  static bool is_other_type(const std::string& keyword) {
    return std::find(other_types.begin(), other_types.end(), keyword) != other_types.end();
  }

  // "POLYGON Z (...)", "POLYGON M", "POLYGON ZM" (the "POLYGONZ" spelling is caught in parse()).
  void reject_dimension() {
    skip_space();
    const std::size_t start = pos_;
    const std::string_view word = read_word();
    if (word.empty()) {
      return;
    }
    const std::string w = upper(word);
    if (w == "Z" || w == "M" || w == "ZM") {
      fail(WktError::Kind::dimension, w + " coordinates are not supported: frontpack domains are 2D (x y)", start);
    }
    pos_ = start;  // not a dimension word: let the caller report it
  }

  // True if the next token is EMPTY (consumed); the caller decides what EMPTY means there.
  bool peek_empty() {
    skip_space();
    const std::size_t start = pos_;
    const std::string_view word = read_word();
    if (!word.empty() && upper(word) == "EMPTY") {
      return true;
    }
    pos_ = start;
    return false;
  }

  void expect(char c, const char* what) {
    skip_space();
    if (pos_ >= text_.size() || text_[pos_] != c) {
      fail(WktError::Kind::syntax, std::string("expected ") + what + ", found " + describe_here(pos_), pos_);
    }
    ++pos_;
  }

  // Reads ',' (returns true) or ')' (returns false).
  bool comma_or_close(const char* list) {
    skip_space();
    if (pos_ < text_.size() && text_[pos_] == ',') {
      ++pos_;
      return true;
    }
    if (pos_ < text_.size() && text_[pos_] == ')') {
      ++pos_;
      return false;
    }
    fail(WktError::Kind::syntax, std::string("expected ',' or ')' in ") + list + ", found " + describe_here(pos_),
         pos_);
  }

  ParsedPolygon parse_polygon_text(const char* context) {
    if (peek_empty()) {
      fail(WktError::Kind::empty_geometry,
           std::string(context) + ": a domain and each of its polygons must have positive area", pos_ - 5);
    }
    expect('(', "'(' to open a polygon");
    ParsedPolygon polygon;
    do {
      polygon.rings.push_back(parse_ring());
    } while (comma_or_close("a polygon's list of rings"));
    return polygon;
  }

  void parse_multipolygon_text(std::vector<ParsedPolygon>& polygons) {
    if (peek_empty()) {
      fail(WktError::Kind::empty_geometry, "MULTIPOLYGON EMPTY: a domain must have positive area", pos_ - 5);
    }
    expect('(', "'(' to open a multipolygon");
    do {
      polygons.push_back(parse_polygon_text("EMPTY polygon in a MULTIPOLYGON"));
    } while (comma_or_close("a multipolygon's list of polygons"));
  }

  ParsedRing parse_ring() {
    if (peek_empty()) {
      fail(WktError::Kind::empty_geometry, "empty ring: every ring must have vertices", pos_ - 5);
    }
    expect('(', "'(' to open a ring");
    ParsedRing ring;
    do {
      skip_space();
      ring.offsets.push_back(pos_);
      const double x = parse_number();
      const double y = parse_number();
      skip_space();
      if (pos_ < text_.size() && text_[pos_] != ',' && text_[pos_] != ')') {
        const std::size_t at = pos_;
        if (is_digit(text_[pos_]) || text_[pos_] == '-' || text_[pos_] == '+' || text_[pos_] == '.') {
          fail(WktError::Kind::dimension,
               "point with more than 2 coordinates (or a missing comma): frontpack domains are 2D (x y), found " +
                   describe_here(at),
               at);
        }
      }
      ring.points.push_back(Point{x, y});
    } while (comma_or_close("a ring's list of points"));
    return ring;
  }

  double parse_number() {
    skip_space();
    const std::size_t start = pos_;
    std::size_t i = pos_;
    if (i < text_.size() && (text_[i] == '+' || text_[i] == '-')) {
      ++i;
    }
    if (i < text_.size() && is_alpha(text_[i])) {
      std::size_t end = i;
      while (end < text_.size() && is_alpha(text_[end])) {
        ++end;
      }
      const std::string word = upper(text_.substr(i, end - i));
      if (word == "NAN" || word == "INF" || word == "INFINITY") {
        fail(WktError::Kind::bad_number,
             "non-finite number " + quote_text(text_.substr(start, end - start)) + ": coordinates must be finite",
             start);
      }
      fail(WktError::Kind::syntax, "expected a number, found " + describe_here(start), start);
    }
    const std::size_t mantissa = i;
    while (i < text_.size() && is_digit(text_[i])) {
      ++i;
    }
    if (i < text_.size() && text_[i] == '.') {
      ++i;
      while (i < text_.size() && is_digit(text_[i])) {
        ++i;
      }
    }
    const bool has_digit = std::any_of(text_.begin() + static_cast<std::ptrdiff_t>(mantissa),
                                       text_.begin() + static_cast<std::ptrdiff_t>(i), is_digit);
    if (!has_digit) {
      fail(WktError::Kind::syntax, "expected a number, found " + describe_here(start), start);
    }
    if (i < text_.size() && (text_[i] == 'e' || text_[i] == 'E')) {
      std::size_t j = i + 1;
      if (j < text_.size() && (text_[j] == '+' || text_[j] == '-')) {
        ++j;
      }
      if (j >= text_.size() || !is_digit(text_[j])) {
        fail(WktError::Kind::syntax, "malformed exponent in number " + describe_here(start), start);
      }
      while (j < text_.size() && is_digit(text_[j])) {
        ++j;
      }
      i = j;
    }
    // The number must end here: "1.5.2" or "12abc" are not numbers.
    if (i < text_.size() && (is_alpha(text_[i]) || text_[i] == '.')) {
      fail(WktError::Kind::syntax, "malformed number " + describe_here(start), start);
    }
    // parse_decimal() (std::from_chars) does not take a leading '+'. Out of the range of doubles:
    // refused (common/numbers.hpp), underflow included (read as 0, it moved a vertex).
    const std::size_t from = text_[start] == '+' ? start + 1 : start;
    const Decimal d = parse_decimal(text_.substr(from, i - from));
    if (d.status == DecimalStatus::overflow || d.status == DecimalStatus::underflow) {
      fail(WktError::Kind::bad_number, "number " + out_of_range(text_.substr(start, i - start), d.status), start);
    }
    if (d.status != DecimalStatus::ok) {
      fail(WktError::Kind::syntax, "malformed number " + describe_here(start), start);
    }
    pos_ = i;
    return d.value;
  }

  std::string_view text_;
  std::size_t pos_ = 0;
};

}  // namespace

std::vector<ParsedPolygon> parse_wkt(std::string_view text) {
  return Parser(text).parse();
}

}  // namespace frontpack::detail
