// The Python side of the result structs' field lists (frontpack/fields.hpp): attribute classes
// bound field by field, dicts keyed by the field names, docstrings from the field docs, and the
// listing `_core._result_fields` that python/tests/test_result_fields.py checks the module and
// the stubs against.
#pragma once

#include <pybind11/stl.h>

#include <cctype>
#include <optional>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

#include "bind.hpp"

namespace frontpack::python {

/// A field doc as a docstring: a capital first letter and a full stop.
[[nodiscard]] inline std::string docstring(std::string_view doc) {
  std::string s(doc);
  if (!s.empty()) {
    s[0] = static_cast<char>(std::toupper(static_cast<unsigned char>(s[0])));
    if (s.back() != '.') {
      s += '.';
    }
  }
  return s;
}

template <HasFields S>
[[nodiscard]] py::dict fields_dict(const S& s);

/// A value by kind: a struct with a field list as a dict, a Point and a pair as a tuple, an
/// optional as None or its value, a Phase by its name, a sequence as a list, the rest as pybind11
/// casts it.
template <class T>
[[nodiscard]] py::object field_value(const T& v) {
  if constexpr (HasFields<T>) {
    return fields_dict(v);
  } else if constexpr (std::is_same_v<T, Point>) {
    return py::make_tuple(v.x, v.y);
  } else if constexpr (std::is_same_v<T, Phase>) {
    return py::str(to_string(v));
  } else if constexpr (requires { v.has_value(); }) {
    return v ? field_value(*v) : py::object(py::none());
  } else if constexpr (requires {
                         v.first;
                         v.second;
                       }) {
    return py::make_tuple(field_value(v.first), field_value(v.second));
  } else if constexpr (requires { v.begin(); } && !std::is_same_v<T, std::string>) {
    py::list list;
    for (const auto& e : v) {
      list.append(field_value(e));
    }
    return list;
  } else {
    return py::cast(v);
  }
}

/// Every field of s under its name.
template <HasFields S>
py::dict fields_dict(const S& s) {
  py::dict d;
  for_each_field<S>([&d, &s](const auto& f) { d[py::str(std::string(f.name))] = field_value(f.of(s)); });
  return d;
}

/// Binds every field of S as a read-only attribute with the field's doc: the member itself when
/// pybind11 returns it as it is (numbers, booleans, bound classes), else converted by kind.
template <HasFields S, class... Extra>
void bind_fields(py::class_<S, Extra...>& cls) {
  for_each_field<S>([&cls](const auto& f) {
    using T = typename std::decay_t<decltype(f)>::Type;
    const std::string name(f.name);
    const std::string doc = docstring(f.doc);
    if constexpr (std::is_arithmetic_v<T> || HasFields<T>) {
      cls.def_readonly(name.c_str(), f.member, doc.c_str());
    } else {
      const auto member = f.member;
      cls.def_property_readonly(
          name.c_str(), [member](const S& s) { return field_value(s.*member); }, doc.c_str());
    }
  });
}

/// The doc of S's field `name` as a docstring (empty when S has no such field).
template <HasFields S>
[[nodiscard]] std::string field_doc(std::string_view name) {
  std::string doc;
  for_each_field<S>([&doc, name](const auto& f) {
    if (f.name == name) {
      doc = docstring(f.doc);
    }
  });
  return doc;
}

/// {"name": [field names]} for `_core._result_fields`.
template <HasFields S>
void list_fields(py::dict& listing, const char* name) {
  py::list names;
  for_each_field<S>([&names](const auto& f) { names.append(py::str(std::string(f.name))); });
  listing[name] = names;
}

}  // namespace frontpack::python
