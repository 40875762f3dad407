// Every fill option described once: its name, kind, default, range and help sentence, how its
// value is read from text, and every check that involves options alone (check_options()). The
// `frontpack fill` flags, the Python keywords of frontpack.fill, their help texts and docstrings
// are made from this description, and tests fail when one of them drifts from it.
//
//   frontpack::FillOptions o;
//   const frontpack::OptionInfo& window = frontpack::fill_option("window");
//   frontpack::set_option(o, window, frontpack::parse_option(window, "8", "--window"));
//   frontpack::check_options(domain, o);  // fill() calls it too
//
// Names. An option's name is its Python keyword (the FillOptions field, except `radius` for
// FillOptions::radii). Its command-line flag is "--" and the name with '_' as '-' (flag_name()),
// except for a flag that is on by default: that one is turned off by "--no-" and the last word of
// its name (fill_voids: --no-voids).
//
// Defaults come from FillOptions{} (default_value()); none is written twice.
//
// Values and ranges. A value read from text must lie in the option's range; a value set directly
// (C++, Python) must lie in the range or be the default, which means "not given" (count 0: no
// count; clearance 0: automatic). Every refusal is an OptionError of one shape,
// "WHO 'TEXT': expected WHAT" for text and "NAME VALUE: expected WHAT" for a value, WHAT being
// expected_text().
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "frontpack/domain.hpp"
#include "frontpack/fill.hpp"
#include "frontpack/geometry.hpp"
#include "frontpack/sizes.hpp"

namespace frontpack {

enum class OptionKind : std::uint8_t {
  method,  ///< a Method, by name (parse_method())
  radii,   ///< a radius spec (parse_radii())
  count,   ///< a whole number in [count_min, count_max]
  bytes,   ///< a number of bytes: digits with an optional suffix K, M, G or T (powers of 1024)
  real,    ///< a finite number in [real_min, real_max] (each end excluded if *_open)
  point,   ///< two finite numbers X,Y
  flag,    ///< on or off
};

/// "method", "radii", "count", "bytes", "real", "point" or "flag".
[[nodiscard]] const char* to_string(OptionKind kind) noexcept;

/// An option's value: the alternative of its kind (count and bytes: std::uint64_t), or
/// std::monostate for an optional option not given.
using OptionValue = std::variant<std::monostate, bool, std::uint64_t, double, Point, Method, Radii>;

/// One fill option, described.
struct OptionInfo {
  std::string_view name;  ///< the Python keyword; the flag derives from it (flag_name())
  OptionKind kind = OptionKind::count;
  bool optional = false;  ///< std::optional in FillOptions: none by default
  /// Also the Budget of every call (frontpack/budget.hpp): every command of the tool takes it.
  bool budget = false;
  std::string_view help;  ///< one sentence, without the default
  std::uint64_t count_min = 0;
  std::uint64_t count_max = UINT64_MAX;
  double real_min = -1.7976931348623157e308;
  double real_max = 1.7976931348623157e308;
  bool real_min_open = false;
  bool real_max_open = false;
  /// What a value must be, when the kind and range do not say it well (else empty).
  std::string_view expected;
  OptionValue (*get)(const FillOptions&) = nullptr;
  void (*set)(FillOptions&, const OptionValue&) = nullptr;
};

/// Every FillOptions field but `stop` (not a user option), in FillOptions' order.
[[nodiscard]] std::span<const OptionInfo> fill_option_list() noexcept;
/// The option of this name; OptionError naming the names if there is none.
[[nodiscard]] const OptionInfo& fill_option(std::string_view name);

/// The command-line flag: "--window", "--no-voids" (the rule at the top of this file).
[[nodiscard]] std::string flag_name(const OptionInfo& info);
/// "NAME (FLAG)": how a message names an option for both the library's and the tool's users.
[[nodiscard]] std::string option_label(const OptionInfo& info);
/// The value in FillOptions{}.
[[nodiscard]] OptionValue default_value(const OptionInfo& info);
/// A value as text: whole numbers in decimal, reals shortest round trip, a point "X,Y", a method
/// by name, flags "true" or "false", none "none"; the default Radii as default_radius_spec, any
/// other Radii as Radii::describe().
[[nodiscard]] std::string value_text(const OptionInfo& info, const OptionValue& value);
/// value_text() of the default.
[[nodiscard]] std::string default_text(const OptionInfo& info);
/// What a value must be: "a whole number from 0 to 4294967296", "closed, open or boundary", ...
[[nodiscard]] std::string expected_text(const OptionInfo& info);

/// Reads the option's value from text, in its range; `who` names it in the message (the tool
/// passes the flag). Radii: parse_radii(), with its own messages. Throws OptionError.
[[nodiscard]] OptionValue parse_option(const OptionInfo& info, std::string_view text, std::string_view who);
/// Sets the field. OptionError "NAME: expected a value of kind KIND" if the value is of another
/// kind (std::monostate for an option that is not optional included). Ranges: check_options().
void set_option(FillOptions& options, const OptionInfo& info, const OptionValue& value);

/// "closed", "open" or "boundary"; else OptionError "WHO 'TEXT': expected closed, open or boundary".
[[nodiscard]] Method parse_method(std::string_view text, std::string_view who = "method");

/// Every check of the options and of their combinations with the domain, one message each; fill()
/// calls it before any work. Throws OptionError: a value out of its range (above); an empty Radii;
/// fraction or count with jam, fraction with count, count with the boundary method, count above
/// max_disks, height with a periodic cell; fill_voids false with the boundary method; start with
/// another form than the closed one, with a domain of several polygons, or outside a periodic
/// cell; a clearance given below the floor the domain's coordinates need (FillOptions::clearance),
/// or a domain and radii too small for any clearance; the open form in a periodic cell, and a cell
/// under 10 times the larger of rmax and the clearance across a periodic direction.
void check_options(const Domain& domain, const FillOptions& options);

/// Option values from text, for the tool's own options as for the fill options: each refused with
/// an OptionError "OPTION 'TEXT': expected ..." that names the option and the value given.
namespace option_text {

/// "OPTION 'TEXT'", TEXT cut to 80 characters: how an error message names an option's value.
[[nodiscard]] std::string given_value(std::string_view option, std::string_view text);
/// A whole number in [min, max]: digits only (no sign, no exponent, no fraction), so that "-1" or
/// "1e23" is refused rather than wrapped or truncated; every value out of range gets the one
/// message "expected a whole number from MIN to MAX".
[[nodiscard]] std::uint64_t parse_count(std::string_view option, std::string_view text, std::uint64_t max,
                                        std::uint64_t min = 0);
/// What parse_bytes() reads, as its message says it.
inline constexpr std::string_view bytes_expected =
    "a number of bytes, with an optional suffix K, M, G or T (powers of 1024), e.g. 512M or 2G; 0 for three "
    "quarters of the machine's memory";
/// Bytes: a whole number with an optional suffix K, M, G or T (powers of 1024: 512M, 2G).
[[nodiscard]] std::size_t parse_bytes(std::string_view option, std::string_view text);
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
[[nodiscard]] std::vector<double> finite_numbers(std::string_view option, std::string_view text,
                                                 std::string_view expected);

}  // namespace option_text

}  // namespace frontpack
