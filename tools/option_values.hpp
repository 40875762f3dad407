// The values of the tool's options read from their text: whole numbers, finite numbers, lists of
// them; each refused with an OptionError "OPTION 'TEXT': expected ..." that names the option and
// the value given (cut as given_value() cuts it).
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace frontpack_tool::cli {

/// "OPTION 'TEXT'", TEXT cut to 80 characters: how an error message names an option's value.
[[nodiscard]] std::string given_value(std::string_view option, std::string_view text);
/// A whole number in [min, max]: digits only (no sign, no exponent, no fraction), so that "-1" or
/// "1e23" is refused rather than wrapped or truncated; every value out of range gets the one
/// message "expected a whole number from MIN to MAX".
[[nodiscard]] std::uint64_t parse_count(std::string_view option, const std::string& text, std::uint64_t max,
                                        std::uint64_t min = 0);
/// Bytes: a whole number with an optional suffix K, M, G or T (powers of 1024: 512M, 2G).
[[nodiscard]] std::size_t parse_bytes(std::string_view option, const std::string& text);
/// text as a finite number, read exactly as std::from_chars reads it (no locale, correctly
/// rounded), if it is one (all of it).
[[nodiscard]] std::optional<double> finite_number(std::string_view text);
/// A finite number (finite_number()).
[[nodiscard]] double parse_double(std::string_view option, std::string_view text);
/// A finite number > 0.
[[nodiscard]] double parse_positive(std::string_view option, std::string_view text);
/// The comma-separated numbers of an option's value, each as parse_double() reads it; an item that
/// is not one (an empty item included) is refused as "OPTION 'TEXT': 'ITEM' is not a finite
/// number; expected EXPECTED".
[[nodiscard]] std::vector<double> finite_numbers(std::string_view option, const std::string& text,
                                                 std::string_view expected);

}  // namespace frontpack_tool::cli
