// Numbers and user text in the readers' messages: one rule for decimals out of the range of
// doubles, and one way to quote what the user wrote, for every reader (WKT, disk files, radius
// specs, size tables).
//
// The rule. A decimal is read with correct rounding (std::from_chars, C locale). One whose value
// overflows to infinity ("1e400"), or that is not zero and rounds to zero ("1e-400": it underflows,
// losing the number), is refused, with the same words everywhere:
//   '1e-400' is out of the range of a double (underflows to 0)
// One that rounds to a subnormal number ("1e-310", "5e-324") is kept: it is a double (and the
// writers write such values, which must read back). "0", "-0.0" and "0e-999" are zero.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace frontpack::detail {

enum class DecimalStatus {
  ok,         ///< a double (finite, or "nan", "inf", "infinity": the callers refuse those by name)
  malformed,  ///< not one whole number
  overflow,   ///< beyond the largest double
  underflow,  ///< not zero, but below half the smallest subnormal: it would read as 0
};

struct Decimal {
  double value = 0;
  DecimalStatus status = DecimalStatus::malformed;
};

/// Reads `token`, which must be one whole number as std::from_chars reads it: an optional '-',
/// digits with an optional point, an optional exponent (no '+' in front: the formats that allow
/// one strip it first), or nan / inf / infinity.
[[nodiscard]] Decimal parse_decimal(std::string_view token) noexcept;

/// "'TOKEN' is out of the range of a double (underflows to 0)", or "(overflows to infinity)"
/// (status overflow or underflow), the token quoted by quote_text().
[[nodiscard]] std::string out_of_range(std::string_view token, DecimalStatus status);

/// How much of a token (a number, a word, a line) a message quotes.
inline constexpr std::size_t kQuotedChars = 40;

/// User text for a message: in single quotes, with control characters and bytes outside ASCII
/// escaped (\0 for NUL, \t, \xNN otherwise) so that a message never carries them raw, and at most
/// `max_chars` characters of it: a longer text is cut, followed by "..." and its length
/// ("'123456...' (200000001 characters)").
[[nodiscard]] std::string quote_text(std::string_view text, std::size_t max_chars = kQuotedChars);

}  // namespace frontpack::detail
