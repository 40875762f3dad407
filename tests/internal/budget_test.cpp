// check_count (src/common/budget.hpp), the one check every derived count goes through: a count
// over max_count or over the memory limit is refused with the figure that failed, the option to
// raise and the advice for that count; a NaN or infinite estimate is refused too; 0 is no count
// limit.
#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>
#include <limits>
#include <string>

#include "common/budget.hpp"
#include "frontpack/errors.hpp"

namespace {

using frontpack::Budget;
using frontpack::LimitError;
using frontpack::detail::check_count;

// The message of the LimitError check_count throws, or "" if it throws none.
std::string refusal(const Budget& budget, double count, double bytes_each) {
  try {
    check_count(budget, count, bytes_each, "wall disks", "use a larger wall radius");
  } catch (const LimitError& e) {
    return e.what();
  }
  return "";
}

TEST(Budget, CountsWithinBothLimitsPass) {
  EXPECT_EQ(refusal(Budget{1000, 1 << 20}, 1000, 1024), "");
  EXPECT_EQ(refusal(Budget{1000, 1 << 20}, 0, 1e300), "");
  EXPECT_EQ(refusal(Budget{0, 1 << 20}, 1e6, 1), "");  // max_count 0: no count limit
}

TEST(Budget, ACountOverMaxCountIsRefusedWithTheFigures) {
  EXPECT_EQ(refusal(Budget{1000, 0}, 1001, 1),
            "the request would make about 1001 wall disks, more than max_disks = 1000; use a larger wall radius or "
            "raise max_disks (--max-disks)");
}

TEST(Budget, ACountOverTheMemoryLimitIsRefusedWithTheFigures) {
  EXPECT_EQ(refusal(Budget{1000, 1 << 20}, 1000, 1049),
            "the request would make about 1000 wall disks, needing about "
            "1049000 bytes of memory, more than the limit of 1048576 "
            "bytes; use a larger wall radius or raise memory_limit "
            "(--memory-limit)");
}

TEST(Budget, NanAndInfiniteEstimatesAreRefusedAndSaturate) {
  for (const double count : {std::nan(""), std::numeric_limits<double>::infinity()}) {
    for (const Budget& budget : {Budget{1000, 0}, Budget{0, 1 << 20}}) {
      try {
        check_count(budget, count, 8, "arc segments", "use a larger max_deviation");
        ADD_FAILURE() << count << " passed";
      } catch (const LimitError& e) {
        EXPECT_EQ(e.estimate(), std::numeric_limits<std::size_t>::max()) << e.what();
      }
    }
  }
  EXPECT_NE(refusal(Budget{0, 1 << 20}, 1e20, 1).find("about 1e+20 wall disks"), std::string::npos);
}

}  // namespace
