#include "common/numbers.hpp"

#include <charconv>
#include <cmath>
#include <string>
#include <system_error>

namespace frontpack::detail {

namespace {

bool is_digit(char c) noexcept {
  return c >= '0' && c <= '9';
}

// Whether the mantissa of a well-formed decimal token (the part before any exponent) has a
// nonzero digit.
bool nonzero_mantissa(std::string_view token) noexcept {
  for (const char c : token) {
    if (c == 'e' || c == 'E') {
      return false;
    }
    if (is_digit(c) && c != '0') {
      return true;
    }
  }
  return false;
}

// Whether the exponent of a well-formed decimal token with a nonzero mantissa is negative, i.e.
// whether a value out of range is too small rather than too large: the order of magnitude,
// floor(log10 |x|) within one, is the exponent plus the position of the first nonzero digit.
bool too_small(std::string_view token) noexcept {
  long order = 0;
  long before_point = 0;       // digits before the point from the first nonzero one
  long zeros_after_point = 0;  // zeros between the point and the first nonzero digit
  bool nonzero = false;
  bool point = false;
  std::size_t i = 0;
  for (; i < token.size() && token[i] != 'e' && token[i] != 'E'; ++i) {
    const char c = token[i];
    if (c == '.') {
      point = true;
    } else if (is_digit(c)) {
      nonzero = nonzero || c != '0';
      if (!point && nonzero) {
        ++before_point;
      } else if (point && !nonzero) {
        ++zeros_after_point;
      }
    }
  }
  order = before_point > 0 ? before_point - 1 : -zeros_after_point - 1;
  if (i < token.size()) {
    std::string_view e = token.substr(i + 1);
    const bool negative = !e.empty() && e.front() == '-';
    if (!e.empty() && (e.front() == '-' || e.front() == '+')) {
      e.remove_prefix(1);
    }
    long exponent = 0;
    const auto [end, ec] = std::from_chars(e.data(), e.data() + e.size(), exponent);
    (void)end;
    if (ec == std::errc::result_out_of_range) {
      return negative;  // an exponent beyond any long decides alone
    }
    // |order| stays below a few hundred million (the token's digits), far from overflow.
    return (negative ? -exponent : exponent) + order < 0;
  }
  return order < 0;
}

}  // namespace

Decimal parse_decimal(std::string_view token) noexcept {
  Decimal d;
  const char* const first = token.data();
  const char* const last = first + token.size();
  const auto [end, ec] = std::from_chars(first, last, d.value);
  if (end != last || (ec != std::errc{} && ec != std::errc::result_out_of_range)) {
    d.status = DecimalStatus::malformed;
    return d;
  }
  const std::string_view digits = !token.empty() && token.front() == '-' ? token.substr(1) : token;
  const bool word = !digits.empty() && !is_digit(digits.front()) && digits.front() != '.';  // nan, inf
  if (ec == std::errc::result_out_of_range) {
    // (libstdc++ says so for results that round to zero or to infinity, and leaves the value.)
    d.status = too_small(digits) ? DecimalStatus::underflow : DecimalStatus::overflow;
    d.value = 0;
    return d;
  }
  // The same decided from the value, for libraries that round quietly.
  if (!word && std::isinf(d.value)) {
    d.status = DecimalStatus::overflow;
  } else if (!word && d.value == 0 && nonzero_mantissa(digits)) {
    d.status = DecimalStatus::underflow;
  } else {
    d.status = DecimalStatus::ok;
  }
  return d;
}

std::string out_of_range(std::string_view token, DecimalStatus status) {
  return quote_text(token) + " is out of the range of a double (" +
         (status == DecimalStatus::underflow ? "underflows to 0)" : "overflows to infinity)");
}

std::string quote_text(std::string_view text, std::size_t max_chars) {
  std::string out(1, '\'');
  const std::string_view shown = text.substr(0, max_chars);
  for (const char c : shown) {
    const auto u = static_cast<unsigned char>(c);
    if (u == 0) {
      out += "\\0";
    } else if (c == '\t') {
      out += "\\t";
    } else if (u < 0x20 || u >= 0x7f) {
      static constexpr char hex[] = "0123456789ABCDEF";
      out += "\\x";
      out += hex[u >> 4];
      out += hex[u & 15];
    } else {
      out += c;
    }
  }
  if (shown.size() < text.size()) {
    out += "...' (";
    out += std::to_string(text.size());
    out += " characters)";
  } else {
    out += '\'';
  }
  return out;
}

}  // namespace frontpack::detail
