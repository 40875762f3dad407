#include "domain/geojson_numbers.hpp"

#include <cmath>

#include "common/numbers.hpp"
#include "frontpack/errors.hpp"

namespace frontpack::detail {

namespace {

bool is_digit(char c) {
  return c >= '0' && c <= '9';
}

// Whether `t` is a number by the JSON grammar (RFC 8259, section 6): -? (0 | [1-9] digits)
// (. digits)? ([eE] [+-]? digits)?.
bool json_number(std::string_view t) {
  std::size_t i = 0;
  const auto digits = [&t, &i] {
    const std::size_t from = i;
    while (i < t.size() && is_digit(t[i])) {
      ++i;
    }
    return i > from;
  };
  if (i < t.size() && t[i] == '-') {
    ++i;
  }
  if (i < t.size() && t[i] == '0') {
    ++i;
  } else if (!digits()) {
    return false;
  }
  if (i < t.size() && t[i] == '.') {
    ++i;
    if (!digits()) {
      return false;
    }
  }
  if (i < t.size() && (t[i] == 'e' || t[i] == 'E')) {
    ++i;
    if (i < t.size() && (t[i] == '+' || t[i] == '-')) {
      ++i;
    }
    if (!digits()) {
      return false;
    }
  }
  return i == t.size();
}

// A token's characters: a number's and a bare word's (letters, digits, sign, point, underscore).
bool in_token(char c) {
  return is_digit(c) || (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '+' || c == '-' || c == '.' ||
         c == '_';
}

}  // namespace

void check_geojson_numbers(std::string_view text, const std::string& source) {
  // Text that does not open a JSON object or array is no GeoJSON at all: GDAL says so.
  const std::size_t first = text.find_first_not_of(" \t\r\n", text.starts_with("\xEF\xBB\xBF") ? 3 : 0);
  if (first == std::string_view::npos || (text[first] != '{' && text[first] != '[')) {
    return;
  }
  std::size_t line = 1;
  for (std::size_t i = 0; i < text.size();) {
    const char c = text[i];
    if (c == '"') {  // a string: skipped whole, its escaped quotes and backslashes with it
      for (++i; i < text.size() && text[i] != '"'; ++i) {
        if (text[i] == '\\') {
          ++i;
        } else if (text[i] == '\n') {
          ++line;
        }
      }
      ++i;
      continue;
    }
    if (!in_token(c)) {
      line += c == '\n' ? 1 : 0;
      ++i;
      continue;
    }
    std::size_t end = i;
    while (end < text.size() && in_token(text[end])) {
      ++end;
    }
    const std::string_view token = text.substr(i, end - i);
    i = end;
    if (token == "true" || token == "false" || token == "null") {
      continue;
    }
    const std::string at = "line " + std::to_string(line) + ": ";
    if (!json_number(token)) {
      throw DomainFileError(DomainFileError::Kind::bad_number, at + quote_text(token) + " is not a JSON number",
                            source);
    }
    // The grammar leaves no nan or inf; the range is the one rule's.
    const Decimal d = parse_decimal(token);
    if (d.status != DecimalStatus::ok || !std::isfinite(d.value)) {
      throw DomainFileError(DomainFileError::Kind::bad_number, at + out_of_range(token, d.status), source);
    }
  }
}

}  // namespace frontpack::detail
