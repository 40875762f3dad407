// A fill option's value read from text, set in FillOptions, and what it must be
// (frontpack/options.hpp).
#include <string>

#include "common/format.hpp"
#include "frontpack/options.hpp"

namespace frontpack {

namespace {

using option_text::given_value;

// The index of the variant's alternative a kind takes.
std::size_t alternative(OptionKind kind) {
  switch (kind) {
    case OptionKind::flag: return 1;
    case OptionKind::count:
    case OptionKind::bytes: return 2;
    case OptionKind::real: return 3;
    case OptionKind::point: return 4;
    case OptionKind::method: return 5;
    case OptionKind::radii: return 6;
  }
  return 0;
}

// Whether a real lies in the option's range.
bool in_range(const OptionInfo& info, double x) {
  const bool above = info.real_min_open ? x > info.real_min : x >= info.real_min;
  const bool below = info.real_max_open ? x < info.real_max : x <= info.real_max;
  return above && below;
}

OptionValue parse_real(const OptionInfo& info, std::string_view text, std::string_view who) {
  const double x = option_text::parse_double(who, text);
  if (!in_range(info, x)) {
    throw OptionError(given_value(who, text) + ": expected " + expected_text(info));
  }
  return x;
}

OptionValue parse_point(const OptionInfo& info, std::string_view text, std::string_view who) {
  const std::string expected = expected_text(info);
  const std::vector<double> xy = option_text::finite_numbers(who, text, expected);
  if (xy.size() != 2) {
    throw OptionError(given_value(who, text) + ": expected " + expected);
  }
  return Point{xy[0], xy[1]};
}

OptionValue parse_flag(const OptionInfo& info, std::string_view text, std::string_view who) {
  if (text != "true" && text != "false") {
    throw OptionError(given_value(who, text) + ": expected " + expected_text(info));
  }
  return text == "true";
}

}  // namespace

std::string expected_text(const OptionInfo& info) {
  if (!info.expected.empty()) {
    return std::string(info.expected);
  }
  switch (info.kind) {
    case OptionKind::method: return "closed, open or boundary";
    case OptionKind::radii: return "a radius spec, e.g. " + std::string(default_radius_spec);
    case OptionKind::count:
      return "a whole number from " + std::to_string(info.count_min) + " to " + std::to_string(info.count_max);
    case OptionKind::bytes: return std::string(option_text::bytes_expected);
    case OptionKind::real:
      if (info.real_min == OptionInfo{}.real_min && info.real_max == OptionInfo{}.real_max) {
        return "a finite number, e.g. 0.5 or -2e-3";
      }
      return std::string("a finite number ") + (info.real_min_open ? "above " : "from ") +
             detail::format_double(info.real_min) + (info.real_max_open ? " and below " : " to ") +
             detail::format_double(info.real_max);
    case OptionKind::point: return "two numbers X,Y, e.g. 0.5,0.25";
    case OptionKind::flag: return "true or false";
  }
  return {};
}

Method parse_method(std::string_view text, std::string_view who) {
  for (const Method method : {Method::closed, Method::open, Method::boundary}) {
    if (text == to_string(method)) {
      return method;
    }
  }
  throw OptionError(given_value(who, text) + ": expected closed, open or boundary");
}

OptionValue parse_option(const OptionInfo& info, std::string_view text, std::string_view who) {
  switch (info.kind) {
    case OptionKind::method: return parse_method(text, who);
    case OptionKind::radii: return parse_radii(text);
    case OptionKind::count: return option_text::parse_count(who, text, info.count_max, info.count_min);
    case OptionKind::bytes: return std::uint64_t{option_text::parse_bytes(who, text)};
    case OptionKind::real: return parse_real(info, text, who);
    case OptionKind::point: return parse_point(info, text, who);
    case OptionKind::flag: return parse_flag(info, text, who);
  }
  return {};
}

void set_option(FillOptions& options, const OptionInfo& info, const OptionValue& value) {
  const bool none = std::holds_alternative<std::monostate>(value);
  if (none ? !info.optional : value.index() != alternative(info.kind)) {
    throw OptionError(std::string(info.name) + ": expected a value of kind " + to_string(info.kind) +
                      (info.optional ? " or none" : "") + " (" + expected_text(info) + ")");
  }
  info.set(options, value);
}

}  // namespace frontpack
