// One check for every derived count (include/frontpack/budget.hpp): the estimate of how many items
// a step is about to make, against the count and memory a Budget allows, before anything is made.
#pragma once

#include <string>
#include <string_view>

#include "frontpack/budget.hpp"

namespace frontpack::detail {

/// The bytes `budget` allows: memory_limit, or three quarters of the physical memory if that is 0
/// (0, no limit, if the system does not say).
[[nodiscard]] double memory_allowed(const Budget& budget);

/// Throws LimitError unless `count` items of `bytes_each` bytes fit `budget`: count <= max_count
/// (unless 0) and count * bytes_each <= memory_allowed(budget). A NaN count fails. The message says
/// "the request would make about COUNT WHAT, more than max_count = M (--max-disks); ADVICE or
/// raise ..." with the figure that failed, e.g. what = "wall disks", advice = "use a larger wall
/// radius". LimitError::estimate() is the count, saturated.
void check_count(const Budget& budget, double count, double bytes_each, std::string_view what, std::string_view advice);

/// A count for a message: an integer below 1e15, else in scientific notation ("1.23e+20").
[[nodiscard]] std::string format_count(double count);

}  // namespace frontpack::detail
