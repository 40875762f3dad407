#include "common/budget.hpp"

#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <limits>

#include "frontpack/errors.hpp"

namespace frontpack::detail {

namespace {

// Physical memory in bytes, or 0 if the system does not say.
double physical_memory() {
  const long pages = ::sysconf(_SC_PHYS_PAGES);
  const long page = ::sysconf(_SC_PAGESIZE);
  return pages > 0 && page > 0 ? static_cast<double>(pages) * static_cast<double>(page) : 0;
}

// A count as a size_t, saturated (an estimate can exceed every integer: 1e600 disks for radii
// of 1e-300 is infinity).
std::size_t saturated(double count) {
  return count >= 0 && count < 0x1p63 ? static_cast<std::size_t>(count) : std::numeric_limits<std::size_t>::max();
}

}  // namespace

double memory_allowed(const Budget& budget) {
  return budget.memory_limit != 0 ? static_cast<double>(budget.memory_limit) : 0.75 * physical_memory();
}

std::string format_count(double count) {
  if (count >= 0 && count < 1e15) {
    return std::to_string(static_cast<std::uint64_t>(count));
  }
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g", count);
  return buf;
}

void check_count(const Budget& budget, double count, double bytes_each, std::string_view what,
                 std::string_view advice) {
  const std::string head = "the request would make about " + format_count(count) + " " + std::string(what);
  // Written so that a NaN fails each check.
  if (budget.max_count != 0 && !(count <= static_cast<double>(budget.max_count))) {
    throw LimitError(head + ", more than max_disks = " + std::to_string(budget.max_count) + "; " + std::string(advice) +
                         " or raise max_disks (--max-disks)",
                     saturated(count));
  }
  const double limit = memory_allowed(budget);
  const double memory = count * bytes_each;
  if (limit > 0 && !(memory <= limit)) {
    throw LimitError(head + ", needing about " + format_count(memory) + " bytes of memory, more than the limit of " +
                         format_count(limit) + " bytes; " + std::string(advice) +
                         " or raise memory_limit (--memory-limit)",
                     saturated(count));
  }
}

}  // namespace frontpack::detail
