// frontpack: the field lists of the result structs (Certificate, CertifyReport, FillStats,
// TargetReport, Progress, PackingStats and its parts), the one description of each field that
// the tool's JSON summary and the Python module are built from.
//
// A result struct S lists its members once, in declaration order, with a one-line doc each:
//
//   struct HoleCount {
//     double radius = 0;
//     std::size_t count = 0;
//     static constexpr auto fields() {
//       return std::tuple{field("radius", &HoleCount::radius, "the radius of the disk that fits"),
//                         field("count", &HoleCount::count, "the holes where it fits")};
//     }
//   };
//
// and for_each_field<S>(f) calls f(Field) for each in that order. A field whose JSON key differs
// from its name carries the key (.json("key")), one that the JSON puts in a sub-object carries
// its name (.in("group")). fields_complete<S>() holds when the list has one entry per member
// (aggregate_members<S>() counts them), so that a member added without a field fails to compile
// where that is asserted (tools/report.cpp; tests/result_fields_test.cpp checks the JSON).
#pragma once

#include <cstddef>
#include <string_view>
#include <tuple>
#include <type_traits>
#include <utility>

namespace frontpack {

/// One member of a result struct S, of type T: its name (the C++ member's, Python's attribute or
/// dict key), the member, its one-line doc (Python's docstring), and where the JSON summary puts
/// it (the key, by default the name; the sub-object, by default none).
template <class S, class T>
struct Field {
  using Struct = S;
  using Type = T;
  std::string_view name;
  T S::*member;
  std::string_view doc;
  std::string_view json_key;
  std::string_view json_group{};

  /// The same field under another JSON key.
  [[nodiscard]] constexpr Field json(std::string_view key) const noexcept {
    Field f = *this;
    f.json_key = key;
    return f;
  }
  /// The same field in the JSON sub-object `group`.
  [[nodiscard]] constexpr Field in(std::string_view group) const noexcept {
    Field f = *this;
    f.json_group = group;
    return f;
  }
  [[nodiscard]] constexpr const T& of(const S& s) const noexcept { return s.*member; }
};

template <class S, class T>
[[nodiscard]] constexpr Field<S, T> field(std::string_view name, T S::*member, std::string_view doc) noexcept {
  return Field<S, T>{name, member, doc, name};
}

/// A struct with a field list.
template <class S>
concept HasFields = requires {
  S::fields();
};

/// Calls f(field) for each field of S, in the order of the members.
template <HasFields S, class F>
constexpr void for_each_field(F&& f) {
  std::apply([&f](const auto&... each) { (f(each), ...); }, S::fields());
}

template <HasFields S>
inline constexpr std::size_t field_count = std::tuple_size_v<decltype(S::fields())>;

namespace detail {

// Converts to a reference to anything: S{AnyMember{}...} is valid for as many initializers as
// the aggregate S has members (each member, nested aggregates included, takes one whole).
struct AnyMember {
  template <class T>
  operator T&() const&& noexcept;  // NOLINT: declared only, used unevaluated
};

template <class S, class... A>
constexpr std::size_t count_members() {
  if constexpr (requires { S{std::declval<A>()..., std::declval<AnyMember>()}; }) {
    return count_members<S, A..., AnyMember>();
  } else {
    return sizeof...(A);
  }
}

}  // namespace detail

/// The number of non-static data members of the aggregate S (without base classes).
template <class S>
[[nodiscard]] constexpr std::size_t aggregate_members() noexcept {
  return detail::count_members<S>();
}

namespace detail {

template <class A, class B>
[[nodiscard]] constexpr bool same_field(const A& a, const B& b) noexcept {
  if constexpr (std::is_same_v<decltype(a.member), decltype(b.member)>) {
    return a.member == b.member || a.name == b.name;
  } else {
    return a.name == b.name;
  }
}

}  // namespace detail

/// The field list of S names every member once and no other: as many entries as members, no
/// member and no name twice (a copy-paste slip would keep the count and lose a member).
template <HasFields S>
[[nodiscard]] constexpr bool fields_complete() noexcept {
  const std::size_t repeats = std::apply(
      [](const auto&... a) {
        const auto matches = [&a...](const auto& x) { return (std::size_t{detail::same_field(x, a)} + ...); };
        return ((matches(a) - 1) + ... + std::size_t{0});  // each entry matches itself once
      },
      S::fields());
  return field_count<S> == aggregate_members<S>() && repeats == 0;
}

}  // namespace frontpack
