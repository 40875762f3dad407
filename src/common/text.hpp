// Text helpers for the readers of user text (WKT, radius specs, disk files): trimming, splitting
// and ASCII case folding, independent of the locale (a program that sets one must not change
// what a file means).
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace frontpack::detail {

/// A space or a tab: the separators of a disk file's fields.
[[nodiscard]] constexpr bool is_space_or_tab(char c) noexcept {
  return c == ' ' || c == '\t';
}

/// What std::isspace accepts in the C locale: space, \t, \n, \v, \f, \r.
[[nodiscard]] constexpr bool is_c_space(char c) noexcept {
  return c == ' ' || (c >= '\t' && c <= '\r');
}

/// `s` without the leading and trailing characters for which `blank` holds.
template <class Blank>
[[nodiscard]] std::string_view trim(std::string_view s, Blank blank) {
  while (!s.empty() && blank(s.front())) {
    s.remove_prefix(1);
  }
  while (!s.empty() && blank(s.back())) {
    s.remove_suffix(1);
  }
  return s;
}

/// The fields of `s` between the separators `sep` (views into `s`; n separators give n + 1
/// fields, empty ones included).
[[nodiscard]] inline std::vector<std::string_view> split(std::string_view s, char sep) {
  std::vector<std::string_view> out;
  std::size_t start = 0;
  while (true) {
    const std::size_t at = s.find(sep, start);
    out.push_back(s.substr(start, at == std::string_view::npos ? std::string_view::npos : at - start));
    if (at == std::string_view::npos) {
      return out;
    }
    start = at + 1;
  }
}

/// The fields of `line` separated by runs of spaces and tabs (views into `line`; none empty).
[[nodiscard]] inline std::vector<std::string_view> tokens(std::string_view line) {
  std::vector<std::string_view> out;
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && is_space_or_tab(line[i])) {
      ++i;
    }
    const std::size_t start = i;
    while (i < line.size() && !is_space_or_tab(line[i])) {
      ++i;
    }
    if (i > start) {
      out.push_back(line.substr(start, i - start));
    }
  }
  return out;
}

/// `s` with A-Z turned into a-z (other bytes as they are).
[[nodiscard]] inline std::string ascii_lower(std::string_view s) {
  std::string out(s);
  for (char& c : out) {
    c = c >= 'A' && c <= 'Z' ? static_cast<char>(c - 'A' + 'a') : c;
  }
  return out;
}

/// `s` with a-z turned into A-Z (other bytes as they are).
[[nodiscard]] inline std::string ascii_upper(std::string_view s) {
  std::string out(s);
  for (char& c : out) {
    c = c >= 'a' && c <= 'z' ? static_cast<char>(c - 'a' + 'A') : c;
  }
  return out;
}

}  // namespace frontpack::detail
