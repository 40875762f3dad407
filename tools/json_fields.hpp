// The JSON of a result struct, from its field list (frontpack/fields.hpp): one key per field, under
// the field's JSON key and in its JSON group, the value by the member's kind. What the summary
// adds or leaves out beyond that (a null band without walls, keys only when a target asks for
// them) is written beside each caller in report.cpp.
#pragma once

#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "frontpack/fields.hpp"
#include "frontpack/fill.hpp"
#include "frontpack/geometry.hpp"

namespace frontpack_tool {

using Json = nlohmann::ordered_json;

template <class T>
[[nodiscard]] Json field_value_json(const T& v);

/// The object of a struct with a field list. An empty optional gives no key; a field with a group
/// goes into the sub-object of that name, made on its first field.
template <frontpack::HasFields S>
[[nodiscard]] Json fields_json(const S& s) {
  Json j = Json::object();
  frontpack::for_each_field<S>([&j, &s](const auto& f) {
    const auto& v = f.of(s);
    if constexpr (requires { v.has_value(); }) {
      if (!v.has_value()) {
        return;
      }
    }
    Json& place = f.json_group.empty() ? j : j[std::string(f.json_group)];
    place[std::string(f.json_key)] = field_value_json(v);
  });
  return j;
}

/// A value by kind: numbers, booleans and strings as themselves (a non-finite number is written
/// null by the serialiser), a Point and a pair as [x, y], a sequence as an array, a struct with a
/// field list as an object, an optional as its value, a Phase by its name.
template <class T>
Json field_value_json(const T& v) {
  if constexpr (frontpack::HasFields<T>) {
    return fields_json(v);
  } else if constexpr (std::is_same_v<T, frontpack::Point>) {
    return Json::array({v.x, v.y});
  } else if constexpr (std::is_same_v<T, frontpack::Phase>) {
    return Json(frontpack::to_string(v));
  } else if constexpr (requires { v.has_value(); }) {
    return field_value_json(*v);
  } else if constexpr (requires {
                         v.first;
                         v.second;
                       }) {
    return Json::array({field_value_json(v.first), field_value_json(v.second)});
  } else if constexpr (requires { v.begin(); } && !std::is_same_v<T, std::string>) {
    Json a = Json::array();
    for (const auto& e : v) {
      a.push_back(field_value_json(e));
    }
    return a;
  } else {
    return Json(v);
  }
}

}  // namespace frontpack_tool
