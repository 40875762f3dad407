// Option values from text (frontpack/options.hpp, namespace option_text).

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <limits>
#include <system_error>

#include "frontpack/errors.hpp"
#include "frontpack/options.hpp"

namespace frontpack::option_text {

namespace {

// 'TEXT', TEXT cut to n characters (and "..." after it if it was).
std::string quoted(std::string_view text, std::size_t n) {
  std::string out(1, '\'');
  out.append(text.substr(0, n)).append(text.size() > n ? "...'" : "'");
  return out;
}

}  // namespace

std::string given_value(std::string_view option, std::string_view text) {
  return std::string(option) + " " + quoted(text, 80);
}

std::uint64_t parse_count(std::string_view option, std::string_view text, std::uint64_t max, std::uint64_t min) {
  std::uint64_t value = 0;
  const char* first = text.data();
  const char* last = text.data() + text.size();
  const bool digits = !text.empty() && text.find_first_not_of("0123456789") == std::string_view::npos;
  const auto [end, ec] = digits ? std::from_chars(first, last, value) : std::from_chars_result{first, std::errc()};
  const std::string range = "a whole number from " + std::to_string(min) + " to " + std::to_string(max);
  if (!digits) {
    throw OptionError(given_value(option, text) + ": expected " + range + (text.empty() ? "" : " (digits only)"));
  }
  if (ec == std::errc::result_out_of_range || end != last || value > max) {
    throw OptionError(given_value(option, text) + ": too large; expected " + range);
  }
  if (value < min) {
    throw OptionError(given_value(option, text) + ": expected " + range);
  }
  return value;
}

std::size_t parse_bytes(std::string_view option, std::string_view text) {
  std::size_t digits = 0;
  while (digits < text.size() && text[digits] >= '0' && text[digits] <= '9') {
    ++digits;
  }
  int shift = -1;
  if (digits == text.size()) {
    shift = 0;
  } else if (digits + 1 == text.size()) {
    const std::string units = "KMGT";
    const std::size_t u = units.find(static_cast<char>(std::toupper(static_cast<unsigned char>(text.back()))));
    shift = u == std::string::npos ? -1 : 10 * static_cast<int>(u + 1);
  }
  if (digits == 0 || shift < 0) {
    throw OptionError(given_value(option, text) + ": expected " + std::string(bytes_expected));
  }
  std::uint64_t value = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + digits, value);
  (void)end;
  if (ec != std::errc{} || value > (std::numeric_limits<std::size_t>::max() >> shift)) {
    throw OptionError(given_value(option, text) + ": too large");
  }
  return static_cast<std::size_t>(value) << shift;
}

std::optional<double> finite_number(std::string_view text) {
  double value = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (text.empty() || ec != std::errc{} || end != text.data() + text.size() || !std::isfinite(value)) {
    return std::nullopt;
  }
  return value;
}

double parse_double(std::string_view option, std::string_view text) {
  const std::optional<double> value = finite_number(text);
  if (!value) {
    throw OptionError(given_value(option, text) + ": expected a finite number, e.g. 0.5 or -2e-3");
  }
  return *value;
}

double parse_positive(std::string_view option, std::string_view text) {
  const std::optional<double> value = finite_number(text);
  if (!value || !(*value > 0)) {
    throw OptionError(given_value(option, text) + ": expected a finite number > 0");
  }
  return *value;
}

std::vector<double> finite_numbers(std::string_view option, std::string_view text, std::string_view expected) {
  std::vector<double> values;
  std::size_t begin = 0;
  while (true) {
    const std::size_t comma = std::min(text.find(',', begin), text.size());
    const std::string_view item = text.substr(begin, comma - begin);
    const std::optional<double> value = finite_number(item);
    if (!value) {
      throw OptionError(given_value(option, text) + ": " + quoted(item, 40) + " is not a finite number; expected " +
                        std::string(expected));
    }
    values.push_back(*value);
    if (comma == text.size()) {
      return values;
    }
    begin = comma + 1;
  }
}

}  // namespace frontpack::option_text
