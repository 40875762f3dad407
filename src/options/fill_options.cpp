// The fill options' one description (frontpack/options.hpp): the table, and the text of names,
// defaults and values made from it.
#include <algorithm>
#include <array>
#include <limits>
#include <string>
#include <type_traits>
#include <utility>

#include "common/format.hpp"
#include "common/numbers.hpp"
#include "frontpack/fields.hpp"
#include "frontpack/options.hpp"

namespace frontpack {

namespace {

// A field's value as the variant's alternative of its kind, and back.
template <class T>
OptionValue to_value(const T& field) {
  if constexpr (std::is_same_v<T, std::size_t>) {
    return std::uint64_t{field};
  } else {
    return field;
  }
}

template <class T>
OptionValue to_value(const std::optional<T>& field) {
  return field ? OptionValue(*field) : OptionValue(std::monostate{});
}

template <class T>
void from_value(const OptionValue& value, T& field) {
  if constexpr (std::is_same_v<T, std::size_t>) {
    field = static_cast<std::size_t>(std::get<std::uint64_t>(value));
  } else {
    field = std::get<T>(value);
  }
}

template <class T>
void from_value(const OptionValue& value, std::optional<T>& field) {
  if (std::holds_alternative<std::monostate>(value)) {
    field.reset();
  } else {
    field = std::get<T>(value);
  }
}

template <auto Member>
OptionValue get_field(const FillOptions& o) {
  return to_value(o.*Member);
}

template <auto Member>
void set_field(FillOptions& o, const OptionValue& value) {
  from_value(value, o.*Member);
}

template <class T>
struct IsOptional : std::false_type {};
template <class T>
struct IsOptional<std::optional<T>> : std::true_type {};

template <auto Member>
OptionInfo field(std::string_view name, OptionKind kind, std::string_view help) {
  OptionInfo info;
  info.name = name;
  info.kind = kind;
  info.optional = IsOptional<std::remove_cvref_t<decltype(std::declval<FillOptions>().*Member)>>::value;
  info.help = help;
  info.get = &get_field<Member>;
  info.set = &set_field<Member>;
  return info;
}

// The table, in FillOptions' order. Each help sentence is what the flag's help and the Python
// docstring say; FillOptions' comments (frontpack/fill.hpp) say the rest.
auto make_table() {
  using K = OptionKind;
  auto t = std::to_array<OptionInfo>({
      field<&FillOptions::method>("method", K::method,
                                  "closed (Sec. 2), open (Sec. 3) or boundary (the domain's edges as walls)"),
      field<&FillOptions::radii>("radius", K::radii,
                                 "radius distribution: uniform:RMIN,RMAX | constant:R | normal:MEAN,SD[,LO,HI] | "
                                 "lognormal:MEDIAN,GSD[,LO,HI] | discrete:S1:F1,S2:F2,...[@area] | curve:FILE.csv "
                                 "(sizes.hpp)"),
      field<&FillOptions::seed>("seed", K::count, "64-bit seed (same seed, same packing)"),
      field<&FillOptions::window>("window", K::count,
                                  "front check window M of the paper's forms (Sec. 2.4.3): front disks examined on "
                                  "each side; 0: the whole front"),
      field<&FillOptions::start>("start", K::point,
                                 "X,Y: where the closed form places its first three disks (none: the centre of each "
                                 "polygon's bounding box)"),
      field<&FillOptions::clearance>("clearance", K::real,
                                     "gap between tangent disks, at least 16 ulps of the coordinates (0: automatic, a "
                                     "few ulps; docs/robustness.md)"),
      field<&FillOptions::fill_voids>("fill_voids", K::flag,
                                      "fill the voids the front leaves behind; off: the paper's forms as published "
                                      "(refused by the boundary method)"),
      field<&FillOptions::max_disks>("max_disks", K::count,
                                     "the most items of each kind a call may make (disks, wall disks, curve segments, "
                                     "sample points): refused up front when estimated beyond; a fill stops a run that "
                                     "reaches it (truncated; the tool exits 9); 0: no limit"),
      field<&FillOptions::memory_limit>("memory_limit", K::bytes,
                                        "bytes a call may take, e.g. 512M or 2G (K, M, G, T: powers of 1024); refused "
                                        "up front or stopped before it would take more; 0: three quarters of the "
                                        "machine's memory"),
      field<&FillOptions::fraction>("fraction", K::real,
                                    "F: a packing fraction below the method's dense one, within 0.002, the radii as "
                                    "requested (no contacts: docs/fraction.md)"),
      field<&FillOptions::count>("count", K::count,
                                 "N: stop after N disks, a compact region: the open form fills from the bottom, the "
                                 "closed form from the start point"),
      field<&FillOptions::height>("height", K::real, "H: fill only the part of the domain below y = H"),
      field<&FillOptions::jam>("jam", K::flag,
                               "after the front, insert disks and relax the overlaps away until the packing jams: "
                               "denser (bidisperse 1:1.4: about 0.837 instead of 0.815; little change at wide size "
                               "ranges); costs minutes per 100,000 disks (docs/jam.md)"),
  });
  auto named = [&t](std::string_view name) -> OptionInfo& {
    return *std::find_if(t.begin(), t.end(), [name](const OptionInfo& i) { return i.name == name; });
  };
  named("window").count_max = std::uint64_t{1} << 32;
  named("clearance").real_min = 0;
  named("clearance").real_min_open = true;
  named("clearance").expected = "a gap > 0 between tangent disks (leave it out for the automatic one)";
  named("max_disks").budget = true;
  named("memory_limit").budget = true;
  named("fraction").real_min = 0;
  named("fraction").real_max = 1;
  named("fraction").real_min_open = true;
  named("fraction").real_max_open = true;
  named("fraction").expected = "a packing fraction (disk area / domain area) strictly between 0 and 1";
  named("count").count_min = 1;
  return t;
}

// Every FillOptions member is described but `stop` (not a user option): a member added to
// FillOptions fails this until the table describes it.
static_assert(std::tuple_size_v<decltype(make_table())> + 1 == aggregate_members<FillOptions>(),
              "describe every FillOptions member in the table");

}  // namespace

std::span<const OptionInfo> fill_option_list() noexcept {
  static const auto table = make_table();
  return table;
}

const OptionInfo& fill_option(std::string_view name) {
  const auto list = fill_option_list();
  const auto it = std::find_if(list.begin(), list.end(), [name](const OptionInfo& i) { return i.name == name; });
  if (it == list.end()) {
    std::string names;
    for (const OptionInfo& i : list) {
      names += (names.empty() ? "" : ", ") + std::string(i.name);
    }
    throw OptionError("no fill option is named " + detail::quote_text(name) + "; the options are " + names);
  }
  return *it;
}

const char* to_string(OptionKind kind) noexcept {
  switch (kind) {
    case OptionKind::method: return "method";
    case OptionKind::radii: return "radii";
    case OptionKind::count: return "count";
    case OptionKind::bytes: return "bytes";
    case OptionKind::real: return "real";
    case OptionKind::point: return "point";
    case OptionKind::flag: return "flag";
  }
  return "unknown";
}

std::string flag_name(const OptionInfo& info) {
  std::string name(info.name);
  std::replace(name.begin(), name.end(), '_', '-');
  if (info.kind == OptionKind::flag && std::get<bool>(default_value(info))) {
    return "--no-" + name.substr(name.rfind('-') + 1);
  }
  return "--" + name;
}

std::string option_label(const OptionInfo& info) {
  return std::string(info.name) + " (" + flag_name(info) + ")";
}

OptionValue default_value(const OptionInfo& info) {
  return info.get(FillOptions{});
}

std::string value_text(const OptionInfo& info, const OptionValue& value) {
  (void)info;
  struct Text {
    std::string operator()(std::monostate) const { return "none"; }
    std::string operator()(bool b) const { return b ? "true" : "false"; }
    std::string operator()(std::uint64_t n) const { return std::to_string(n); }
    std::string operator()(double x) const { return detail::format_double(x); }
    std::string operator()(Point p) const { return detail::format_double(p.x) + "," + detail::format_double(p.y); }
    std::string operator()(Method m) const { return to_string(m); }
    std::string operator()(const Radii& r) const { return r.describe(); }
  };
  return std::visit(Text{}, value);
}

std::string default_text(const OptionInfo& info) {
  // The default Radii as the spec that makes them (fill.hpp: default_radius_spec).
  return info.kind == OptionKind::radii ? std::string(default_radius_spec) : value_text(info, default_value(info));
}

}  // namespace frontpack
