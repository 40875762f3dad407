// Number and point formatting shared by messages and writers: shortest round-trip decimal.
#pragma once

#include <string>

#include "frontpack/geometry.hpp"

namespace frontpack::detail {

/// Shortest decimal text that reads back as exactly the same double.
[[nodiscard]] std::string format_double(double value);
/// "(x y)" with format_double for each coordinate.
[[nodiscard]] std::string format_point(Point p);

}  // namespace frontpack::detail
