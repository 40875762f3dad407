// Every member of every result struct has its field (a member added without one fails to compile
// tools/report.cpp, built into this test and the tool), and the tool's JSON writer (tools/report.cpp) emits a key for
// every field, at the JSON key and in the group the field list names, nested structs and sequences of them included.
// python/tests/test_result_fields.py checks the Python side against the same lists.
#include <gtest/gtest.h>

#include <limits>
#include <string>
#include <type_traits>
#include <vector>

#include "frontpack/certify.hpp"
#include "frontpack/fields.hpp"
#include "frontpack/fill.hpp"
#include "frontpack/stats.hpp"
#include "report.hpp"

namespace {

using frontpack::fields_complete;
using frontpack_tool::Json;

// Every list is asserted complete where the JSON is written (tools/report.cpp, compiled in here
// as in the tool).
// The check itself catches what it is meant to: a list one member short, or naming one twice.
struct TwoMembers {
  double a = 0;
  double b = 0;
};
struct Short {
  double a = 0;
  double b = 0;
  static constexpr auto fields() { return std::tuple{frontpack::field("a", &Short::a, "a")}; }
};
struct Twice {
  double a = 0;
  double b = 0;
  static constexpr auto fields() {
    return std::tuple{frontpack::field("a", &Twice::a, "a"), frontpack::field("b", &Twice::a, "b")};
  }
};
static_assert(frontpack::aggregate_members<TwoMembers>() == 2);
static_assert(!fields_complete<Short>());
static_assert(!fields_complete<Twice>());

template <class T>
struct IsVector : std::false_type {};
template <class T>
struct IsVector<std::vector<T>> : std::true_type {};

// Every field of s has its key in j; nested structs, and the first element of a sequence of them,
// are walked the same way. Sequences of structs must be non-empty in s.
template <frontpack::HasFields S>
void expect_every_field(const Json& j, const S& s, const std::string& path) {
  frontpack::for_each_field<S>([&j, &s, &path](const auto& f) {
    using T = typename std::decay_t<decltype(f)>::Type;
    const std::string group(f.json_group);
    const std::string key(f.json_key);
    const std::string where = path + "/" + (group.empty() ? "" : group + "/") + key + " (" + std::string(f.name) + ")";
    const Json& in = group.empty() ? j : j.value(group, Json::object());
    ASSERT_TRUE(in.contains(key)) << where;
    if constexpr (frontpack::HasFields<T>) {
      expect_every_field(in.at(key), f.of(s), where);
    } else if constexpr (IsVector<T>::value) {
      if constexpr (frontpack::HasFields<typename T::value_type>) {
        ASSERT_FALSE(f.of(s).empty()) << where << ": give the test one element";
        ASSERT_FALSE(in.at(key).empty()) << where;
        expect_every_field(in.at(key).at(0), f.of(s).front(), where + "[0]");
      }
    }
  });
}

frontpack::PackingStats full_stats() {
  frontpack::PackingStats s;
  s.disks = 2;
  s.sizes.rmax = 0.05;
  s.sizes.compared = true;
  s.sizes.requested = "uniform(0.01, 0.05)";
  s.sizes.classes = {frontpack::SizeClassRow{.radius = 0.05}};
  s.sizes.histogram = {frontpack::HistogramBin{.lo = 0.01, .hi = 0.05, .count = 2}};
  s.largest_empty_circle.computed = true;
  s.holes = {frontpack::HoleCount{.radius = 0.03, .count = 1}};
  s.coverage_unit = 0.05;
  s.coverage_profile = {frontpack::CoverageBin{.from = 0, .to = std::numeric_limits<double>::infinity()}};
  s.cell_coverage.nx = 1;
  s.cell_coverage.ny = 1;
  s.cell_coverage.map = {0.5};
  return s;
}

TEST(ResultFields, StatsJsonHasEveryField) {
  const frontpack::PackingStats s = full_stats();
  const Json j = frontpack_tool::stats_json(s);
  expect_every_field(j, s, "");
  EXPECT_EQ(j.at("largest_empty_circle").at("radius_over_rmax"), 0.0);
  EXPECT_EQ(j.at("coverage_profile").at(0).at("to").dump(), "null");
}

TEST(ResultFields, StatsJsonLeavesOutWhatWasNotComputedOrAsked) {
  frontpack::PackingStats s = full_stats();
  s.walls = false;
  s.sizes.compared = false;
  s.largest_empty_circle.computed = false;
  const Json j = frontpack_tool::stats_json(s);
  EXPECT_FALSE(j.contains("largest_empty_circle"));
  EXPECT_FALSE(j.at("radius").contains("requested"));
  EXPECT_FALSE(j.at("radius").contains("ks_by_area"));
  EXPECT_TRUE(j.at("band_fraction").is_null());
  EXPECT_TRUE(j.at("segregation_ks_by_area").is_null());
}

TEST(ResultFields, FillJsonHasEveryField) {
  const frontpack::Certificate c{.generated = 3, .culled = 1};
  expect_every_field(frontpack_tool::certificate_json(c), c, "certificate");
  EXPECT_EQ(frontpack_tool::certificate_json(c).at("certified"), true);
  const frontpack::FillStats stats{.jam_rounds = 2};
  expect_every_field(frontpack_tool::fill_stats_json(stats, true), stats, "");
  EXPECT_FALSE(frontpack_tool::fill_stats_json(stats, false).contains("jam"));
}

TEST(ResultFields, TargetJsonHasEveryFieldAskedFor) {
  const frontpack::TargetReport t{.fraction_requested = 0.7, .count_requested = 10, .height = 0.5};
  expect_every_field(frontpack_tool::target_json(t), t, "target");
  const Json level = frontpack_tool::target_json(frontpack::TargetReport{.height = 0.5});
  EXPECT_FALSE(level.contains("fraction_requested"));
  EXPECT_FALSE(level.contains("count_requested"));
  EXPECT_FALSE(frontpack_tool::target_json(frontpack::TargetReport{}).contains("height"));
}

TEST(ResultFields, CertifyJsonHasEveryField) {
  frontpack::CertifyReport r;
  r.outside = {4, 7};
  r.overlapping = {{0, 1}};
  r.deepest_overlap = {{0, 1}};
  r.farthest_outside = 7;
  r.farthest_outside_by = std::numeric_limits<double>::infinity();
  const Json j = frontpack_tool::certify_json(r);
  expect_every_field(j, r, "");
  EXPECT_EQ(j.at("outside"), 2);
  EXPECT_EQ(j.at("overlapping_pairs"), 1);
  EXPECT_EQ(j.at("deepest_overlap").at("disks").dump(), "[0,1]");
  EXPECT_EQ(j.at("farthest_outside").at("by").dump(), "null");
  EXPECT_FALSE(frontpack_tool::certify_json(frontpack::CertifyReport{}).contains("deepest_overlap"));
}

}  // namespace
