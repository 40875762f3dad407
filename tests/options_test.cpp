// The fill options' one description (frontpack/options.hpp): every FillOptions field described
// (fill_options.cpp also refuses to compile otherwise), defaults taken from FillOptions{}, one
// message shape for text and for values, and every option check made by the library itself, so
// that C++ and Python callers are refused as the tool is.
#include <gtest/gtest.h>

#include <cstdint>
#include <limits>
#include <set>
#include <string>

#include "frontpack/frontpack.hpp"

namespace fp = frontpack;

namespace {

const fp::Domain& unit_square() {
  static const fp::Domain d = fp::Domain::from_wkt("POLYGON((0 0,1 0,1 1,0 1,0 0))");
  return d;
}

// The OptionError message of check_options(domain, o), or "" if it accepts them.
std::string refusal(const fp::Domain& domain, const fp::FillOptions& o) {
  try {
    fp::check_options(domain, o);
  } catch (const fp::OptionError& e) {
    return e.what();
  }
  return {};
}

std::string parse_refusal(std::string_view name, std::string_view text) {
  const fp::OptionInfo& info = fp::fill_option(name);
  try {
    (void)fp::parse_option(info, text, fp::flag_name(info));
  } catch (const fp::OptionError& e) {
    return e.what();
  }
  return {};
}

TEST(OptionsTest, EveryOptionIsDescribedOnceWithHelpAndAccessors) {
  std::set<std::string> names;
  std::set<std::string> flags;
  for (const fp::OptionInfo& info : fp::fill_option_list()) {
    EXPECT_TRUE(names.insert(std::string(info.name)).second) << info.name;
    EXPECT_TRUE(flags.insert(fp::flag_name(info)).second) << info.name;
    EXPECT_FALSE(info.help.empty()) << info.name;
    EXPECT_NE(info.get, nullptr) << info.name;
    EXPECT_NE(info.set, nullptr) << info.name;
    EXPECT_FALSE(fp::expected_text(info).empty()) << info.name;
  }
  // Every FillOptions field but `stop` (not a user option): fill_options.cpp counts the fields.
  EXPECT_EQ(names.size(), fp::fill_option_list().size());
  EXPECT_EQ(names.count("stop"), 0u);
  EXPECT_EQ(names.count("radius"), 1u);
  EXPECT_THROW((void)fp::fill_option("stop"), fp::OptionError);
}

TEST(OptionsTest, FlagsFollowTheOneRule) {
  EXPECT_EQ(fp::flag_name(fp::fill_option("window")), "--window");
  EXPECT_EQ(fp::flag_name(fp::fill_option("max_disks")), "--max-disks");
  EXPECT_EQ(fp::flag_name(fp::fill_option("fill_voids")), "--no-voids");  // on by default
  EXPECT_EQ(fp::flag_name(fp::fill_option("jam")), "--jam");              // off by default
  EXPECT_EQ(fp::option_label(fp::fill_option("start")), "start (--start)");
}

TEST(OptionsTest, DefaultsAreFillOptionsDefaults) {
  EXPECT_EQ(fp::default_text(fp::fill_option("window")), std::to_string(fp::FillOptions{}.window));
  EXPECT_EQ(fp::default_text(fp::fill_option("max_disks")), std::to_string(fp::Budget{}.max_count));
  EXPECT_EQ(fp::default_text(fp::fill_option("method")), "boundary");
  EXPECT_EQ(fp::default_text(fp::fill_option("start")), "none");
  EXPECT_EQ(fp::default_text(fp::fill_option("fill_voids")), "true");
  // The default radii and the spec the tool and Python show for them are the same distribution.
  const fp::Radii spec = fp::parse_radii(fp::default_text(fp::fill_option("radius")));
  EXPECT_EQ(spec.describe(), fp::FillOptions{}.radii.describe());
  // Each default read back from its text (what the help shows) is the default.
  for (const char* name : {"method", "seed", "window", "clearance", "max_disks", "memory_limit", "count"}) {
    const fp::OptionInfo& info = fp::fill_option(name);
    fp::FillOptions o;
    o.window = 77;
    o.seed = 77;
    o.max_disks = 77;
    o.memory_limit = 77;
    o.method = fp::Method::open;
    o.clearance = 1;
    o.count = 77;
    const std::string text = fp::default_text(info);
    if (name == std::string("clearance") || name == std::string("count")) {
      EXPECT_NE(parse_refusal(name, text), "") << name;  // 0 means "not given": refused as text
      continue;
    }
    fp::set_option(o, info, fp::parse_option(info, text, fp::flag_name(info)));
    EXPECT_EQ(fp::value_text(info, info.get(o)), text) << name;
  }
}

TEST(OptionsTest, TextIsRefusedWithOneMessageShape) {
  EXPECT_EQ(parse_refusal("window", "-2"), "--window '-2': expected a whole number from 0 to 4294967296 (digits only)");
  EXPECT_EQ(parse_refusal("window", "4294967297"),
            "--window '4294967297': too large; expected a whole number from 0 to 4294967296");
  EXPECT_EQ(parse_refusal("count", "0"), "--count '0': expected a whole number from 1 to 18446744073709551615");
  EXPECT_EQ(parse_refusal("clearance", "-1"),
            "--clearance '-1': expected a gap > 0 between tangent disks (leave it out for the automatic one)");
  EXPECT_EQ(parse_refusal("fraction", "1.5"),
            "--fraction '1.5': expected a packing fraction (disk area / domain area) strictly between 0 and 1");
  EXPECT_EQ(parse_refusal("start", "0.5"), "--start '0.5': expected two numbers X,Y, e.g. 0.5,0.25");
  EXPECT_EQ(parse_refusal("method", "diagonal"), "--method 'diagonal': expected closed, open or boundary");
  EXPECT_EQ(parse_refusal("height", "x"), "--height 'x': expected a finite number, e.g. 0.5 or -2e-3");
  EXPECT_EQ(parse_refusal("memory_limit", "12Q").rfind("--memory-limit '12Q': expected a number of bytes", 0), 0u);
  try {
    (void)fp::parse_method("spiral");
    ADD_FAILURE() << "spiral accepted";
  } catch (const fp::OptionError& e) {
    EXPECT_STREQ(e.what(), "method 'spiral': expected closed, open or boundary");
  }
  EXPECT_EQ(fp::parse_method("closed"), fp::Method::closed);
}

TEST(OptionsTest, ValuesOutOfRangeAreRefusedByTheLibrary) {
  fp::FillOptions o;
  o.window = (std::size_t{1} << 32) + 1;
  EXPECT_EQ(refusal(unit_square(), o), "window 4294967297: expected a whole number from 0 to 4294967296");
  o = {};
  o.clearance = -1;
  EXPECT_EQ(refusal(unit_square(), o),
            "clearance -1: expected a gap > 0 between tangent disks (leave it out for the automatic one)");
  o = {};
  o.fraction = 1.5;
  EXPECT_EQ(refusal(unit_square(), o),
            "fraction 1.5: expected a packing fraction (disk area / domain area) strictly between 0 and 1");
  o = {};
  o.method = fp::Method::closed;
  o.start = fp::Point{std::numeric_limits<double>::infinity(), 0};
  EXPECT_EQ(refusal(unit_square(), o), "start inf,0: expected two numbers X,Y, e.g. 0.5,0.25");
  o = {};
  o.clearance = 1e-300;  // given, but below the floor the coordinates need
  EXPECT_NE(refusal(unit_square(), o).find("clearance must be 0 (automatic) or a finite number >= "),
            std::string::npos);
  EXPECT_EQ(refusal(unit_square(), fp::FillOptions{}), "");  // the defaults, "not given" included
}

TEST(OptionsTest, StartOnlyWithTheClosedFormAndOnePolygon) {
  fp::FillOptions o;
  o.radii = fp::Radii::constant(0.1);
  o.start = fp::Point{0.5, 0.5};
  for (const fp::Method m : {fp::Method::open, fp::Method::boundary}) {
    o.method = m;
    EXPECT_EQ(refusal(unit_square(), o),
              "start (--start) is where the closed form (method closed) places its first "
              "disks; the " +
                  std::string(fp::to_string(m)) + " form has no start point");
    // fill() refuses it too: Python and C++ callers get what the tool gets.
    EXPECT_THROW((void)fp::fill(unit_square(), o), fp::OptionError);
  }
  o.method = fp::Method::closed;
  EXPECT_EQ(refusal(unit_square(), o), "");
  const fp::Domain two = fp::Domain::from_wkt("MULTIPOLYGON(((0 0,1 0,1 1,0 1,0 0)),((2 0,3 0,3 1,2 1,2 0)))");
  EXPECT_EQ(refusal(two, o),
            "start (--start): the domain has 2 polygons, each filled from its own start (the centre "
            "of its bounding box); a start point takes a domain of one polygon");
  EXPECT_THROW((void)fp::fill(two, o), fp::OptionError);
}

TEST(OptionsTest, CombinationsAreCheckedOnce) {
  fp::FillOptions o;
  o.jam = true;
  o.fraction = 0.5;
  EXPECT_NE(refusal(unit_square(), o).find("jam makes the packing as dense as it gets"), std::string::npos);
  o = {};
  o.count = 10;
  EXPECT_NE(refusal(unit_square(), o).find("count: the boundary method"), std::string::npos);
  o.method = fp::Method::open;
  o.max_disks = 5;
  EXPECT_EQ(refusal(unit_square(), o), "count 10 exceeds max_disks = 5");
  o = {};
  o.fill_voids = false;
  EXPECT_NE(refusal(unit_square(), o).find("boundary method keeps its voids"), std::string::npos);
  o.method = fp::Method::closed;
  EXPECT_EQ(refusal(unit_square(), o), "");
  const fp::Domain cell = fp::Domain::periodic(fp::Box{0, 0, 1, 1}, fp::Periodicity::xy);
  o = {};
  o.method = fp::Method::open;
  EXPECT_NE(refusal(cell, o).find("the open form does not wrap around a cell"), std::string::npos);
  o.method = fp::Method::closed;
  o.start = fp::Point{2, 0.5};
  EXPECT_EQ(refusal(cell, o), "the start point must lie in the periodic cell");
  o = {};
  o.height = 0.5;
  EXPECT_NE(refusal(cell, o).find("height: a periodic cell has no level"), std::string::npos);
}

TEST(OptionsTest, SetOptionRefusesAValueOfAnotherKind) {
  fp::FillOptions o;
  EXPECT_THROW(fp::set_option(o, fp::fill_option("window"), 0.5), fp::OptionError);
  EXPECT_THROW(fp::set_option(o, fp::fill_option("window"), std::monostate{}), fp::OptionError);
  fp::set_option(o, fp::fill_option("window"), std::uint64_t{9});
  EXPECT_EQ(o.window, 9u);
  o.height = 2;
  fp::set_option(o, fp::fill_option("height"), std::monostate{});
  EXPECT_FALSE(o.height.has_value());
}

}  // namespace
