// Shortest round-trip decimal text for doubles and points (common/format.hpp).
#include "common/format.hpp"

#include <array>
#include <charconv>
#include <string>
#include <system_error>

namespace frontpack::detail {

std::string format_double(double value) {
  std::array<char, 32> buffer{};
  const auto [end, ec] = std::to_chars(buffer.data(), buffer.data() + buffer.size(), value);
  if (ec != std::errc{}) {
    return "?";  // unreachable: 32 characters hold any double
  }
  return {buffer.data(), end};
}

std::string format_point(Point p) {
  std::string out(1, '(');
  out.append(format_double(p.x)).append(1, ' ').append(format_double(p.y)).append(1, ')');
  return out;
}

}  // namespace frontpack::detail
