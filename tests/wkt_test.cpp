// The WKT reader: what it accepts, and where it says the text is wrong.
#include <gtest/gtest.h>

#include <limits>
#include <string>
#include <utility>

#include "frontpack/frontpack.hpp"

namespace fp = frontpack;

namespace {

fp::WktError wkt_error(const std::string& text) {
  try {
    (void)fp::Domain::from_wkt(text);
  } catch (const fp::WktError& e) {
    return e;
  }
  ADD_FAILURE() << "no WktError for: " << text;
  return fp::WktError(fp::WktError::Kind::syntax, "none", 0, 0, 0);
}

}  // namespace

TEST(Wkt, AcceptsKeywordsInAnyCaseAndAnyWhitespace) {
  const char* forms[] = {
      "POLYGON((0 0,2 0,2 1,0 1,0 0))",
      "polygon((0 0,2 0,2 1,0 1,0 0))",
      "PoLyGoN  (  ( 0 0 , 2 0 , 2 1 , 0 1 , 0 0 ) )",
      "\n\tPOLYGON\r\n(\r\n(0\t0,\n2 0,2\n1,0 1,0 0)\r\n)\r\n",
      "POLYGON((0e0 0.0,2E+0 0,2.0 1e-0,0 +1,-0 0))",
      "POLYGON((.0 0,2. 0,2 1,0 1,0 0))",
      "MULTIPOLYGON(((0 0,2 0,2 1,0 1,0 0)))",
      "multipolygon ( ( ( 0 0, 2 0, 2 1, 0 1, 0 0 ) ) )",
  };
  for (const char* text : forms) {
    SCOPED_TRACE(text);
    const fp::Domain d = fp::Domain::from_wkt(text);
    EXPECT_EQ(d.area(), 2.0);
    EXPECT_EQ(d.num_polygons(), 1U);
    EXPECT_EQ(d.num_vertices(), 4U);
  }
}

TEST(Wkt, ScientificNotationIsDecodedWithCorrectRounding) {
  const fp::Domain d =
      fp::Domain::from_wkt("POLYGON((1e-3 2.5E-4, 3e-3 2.5e-4, 3E-03 1.25e-3, 1e-3 1.25e-3, 1e-3 2.5E-4))");
  const fp::Ring& outer = d.polygons()[0].outer;
  EXPECT_EQ(outer[0].x, 0.001);
  EXPECT_EQ(outer[0].y, 0.00025);
  EXPECT_EQ(outer[2].y, 0.00125);
}

TEST(Wkt, MultipolygonWithHolesAndRepeatedVertices) {
  const fp::Domain d =
      fp::Domain::from_wkt("MULTIPOLYGON(((0 0,4 0,4 4,0 4,0 0),(1 1,1 1,1 2,2 2,2 1,1 1)),((5 0,6 0,6 0,6 1,5 0)))");
  EXPECT_EQ(d.num_polygons(), 2U);
  EXPECT_EQ(d.num_holes(), 1U);
  // Repeated consecutive vertices are removed: 4 + 4 + 3.
  EXPECT_EQ(d.num_vertices(), 11U);
  EXPECT_EQ(d.area(), 16.0 - 1.0 + 0.5);
}

TEST(Wkt, RoundTripsThroughToWkt) {
  const fp::Domain d =
      fp::Domain::from_wkt("MULTIPOLYGON(((0 0,4 0,4 4,0 4,0 0),(1 1,1 2,2 2,2 1,1 1)),((5 0,6 0,6 1,5 0.1,5 0)))");
  const fp::Domain again = fp::Domain::from_wkt(d.to_wkt());
  ASSERT_EQ(again.polygons().size(), d.polygons().size());
  for (std::size_t p = 0; p < d.polygons().size(); ++p) {
    EXPECT_EQ(again.polygons()[p].outer, d.polygons()[p].outer);
    EXPECT_EQ(again.polygons()[p].holes, d.polygons()[p].holes);
  }
  // Doubles that need 17 digits survive too.
  const fp::Domain odd = fp::Domain::from_wkt("POLYGON((0.1 0.2,0.30000000000000004 0.2,0.3 0.7,0.1 0.2))");
  EXPECT_EQ(fp::Domain::from_wkt(odd.to_wkt()).polygons()[0].outer, odd.polygons()[0].outer);
}

TEST(Wkt, SyntaxErrorsNameTheOffsetLineColumnAndExpectedToken) {
  {
    const fp::WktError e = wkt_error("POLYGON((0 0,1 0,1 1 0 0))");
    EXPECT_EQ(e.kind(), fp::WktError::Kind::dimension);  // "1 1 0" has three numbers
    EXPECT_EQ(e.offset(), 21U);
  }
  {
    const fp::WktError e = wkt_error("POLYGON((0 0,1 0,1 1,0 0)");
    EXPECT_EQ(e.kind(), fp::WktError::Kind::syntax);
    EXPECT_EQ(e.offset(), 25U);
    EXPECT_NE(std::string(e.what()).find("expected ',' or ')'"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("end of input"), std::string::npos) << e.what();
  }
  {
    const fp::WktError e = wkt_error("POLYGON(\n  (0 0,\n   1 x, 1 1, 0 0))");
    EXPECT_EQ(e.kind(), fp::WktError::Kind::syntax);
    EXPECT_EQ(e.line(), 3U);
    EXPECT_EQ(e.column(), 6U);
    EXPECT_NE(std::string(e.what()).find("expected a number, found 'x'"), std::string::npos) << e.what();
  }
  {
    const fp::WktError e = wkt_error("POLYGON((0 0,1 0,1 1,0 0)) junk");
    EXPECT_EQ(e.offset(), 27U);
    EXPECT_NE(std::string(e.what()).find("'junk'"), std::string::npos) << e.what();
  }
}

TEST(Wkt, RejectsWhatIsNotA2DPolygonWithTheRightKind) {
  using K = fp::WktError::Kind;
  const std::pair<const char*, K> cases[] = {
      {"", K::syntax},
      {"POLYGON EMPTY", K::empty_geometry},
      {"MULTIPOLYGON EMPTY", K::empty_geometry},
      {"POLYGON(EMPTY)", K::empty_geometry},
      {"POLYGON(())", K::syntax},
      {"POINT(1 2)", K::unsupported_geometry},
      {"LINESTRING(0 0,1 1)", K::unsupported_geometry},
      {"GEOMETRYCOLLECTION(POLYGON((0 0,1 0,1 1,0 0)))", K::unsupported_geometry},
      {"POLYGON Z ((0 0 0,1 0 0,1 1 0,0 0 0))", K::dimension},
      {"POLYGON M ((0 0 0,1 0 0,1 1 0,0 0 0))", K::dimension},
      {"POLYGON ZM ((0 0 0 0,1 0 0 0,1 1 0 0,0 0 0 0))", K::dimension},
      {"POLYGON((0 0 5,1 0 5,1 1 5,0 0 5))", K::dimension},
      {"POLYGON((0 0,1 0,nan 1,0 0))", K::bad_number},
      {"POLYGON((0 0,1 0,1 -inf,0 0))", K::bad_number},
      {"POLYGON((0 0,1 0,1 Infinity,0 0))", K::bad_number},
      {"POLYGON((0 0,1e400 0,1 1,0 0))", K::bad_number},
      {"POLYGON((0 0,1.2.3 0,1 1,0 0))", K::syntax},
      {"POLYGON((0 0,1e 0,1 1,0 0))", K::syntax},
      {"POLYGON((0 0,0x10 0,1 1,0 0))", K::syntax},
      {"SRID=4326;POLYGON((0 0,1 0,1 1,0 0))", K::syntax},
      {"POLYGON((0 0;1 0,1 1,0 0))", K::syntax},
  };
  for (const auto& [text, kind] : cases) {
    SCOPED_TRACE(text);
    EXPECT_EQ(wkt_error(text).kind(), kind) << wkt_error(text).what();
  }
}

TEST(Wkt, FileErrorsNameTheFile) {
  try {
    (void)fp::Domain::from_wkt_file("/nonexistent/frontpack/domain.wkt");
    FAIL() << "no IoError";
  } catch (const fp::IoError& e) {
    EXPECT_EQ(e.path(), "/nonexistent/frontpack/domain.wkt");
    EXPECT_NE(std::string(e.what()).find("No such file"), std::string::npos) << e.what();
  }
}

// One rule for decimals out of the range of doubles, in every reader (README, "Numbers"): refused
// with the token named, whether they overflow or underflow. Read as 0, "1e-400" used to move a
// vertex silently. Subnormal numbers are doubles and are kept; zero written any way is zero.
TEST(Wkt, NumbersOutOfTheDoubleRangeAreRefused) {
  const std::pair<std::string, std::string> refused[] = {
      {"POLYGON((0 0,1 0,1 1,1e-400 1,0 0))", "number '1e-400' is out of the range of a double (underflows to 0)"},
      {"POLYGON((0 0,1 0,1 1,-2.4e-324 1,0 0))",
       "number '-2.4e-324' is out of the range of a double (underflows to 0)"},
      {"POLYGON((0 0,1 0,1 1,0.0001e-320 1,0 0))",
       "number '0.0001e-320' is out of the range of a double (underflows to 0)"},
      {"POLYGON((0 0,1 0,1 1,0 1e-99999999999999999999,0 0))",
       "number '1e-99999999999999999999' is out of the range of a double (underflows to 0)"},
      {"POLYGON((0 0,+1e400 0,1 1,0 0))", "number '+1e400' is out of the range of a double (overflows to infinity)"},
      {"POLYGON((0 0,1 0,1 1,0 1e99999999999999999999,0 0))",
       "number '1e99999999999999999999' is out of the range of a double (overflows to infinity)"},
  };
  for (const auto& [text, message] : refused) {
    SCOPED_TRACE(text);
    const fp::WktError e = wkt_error(text);
    EXPECT_EQ(e.kind(), fp::WktError::Kind::bad_number);
    EXPECT_EQ(e.detail(), message);
  }
  const fp::Domain subnormal = fp::Domain::from_wkt("POLYGON((0 0,1 0,1 1,2.5e-324 1,0 0))");
  EXPECT_EQ(subnormal.polygons()[0].outer[3].x, std::numeric_limits<double>::denorm_min());
  const fp::Domain zeros = fp::Domain::from_wkt("POLYGON((0e-500 -0.0e-9999,1 0,1 1,0.000 1,0 0))");
  EXPECT_EQ(zeros.area(), 1.0);
}

// A bad token is quoted escaped and cut to 40 characters, with its length: a 200,000-digit
// number was echoed whole.
TEST(Wkt, MessagesQuoteAtMost40CharactersOfAToken) {
  const std::string digits(200000, '7');
  const fp::WktError number = wkt_error("POLYGON((0 0,1 0,1 " + digits + ",0 0))");
  EXPECT_EQ(number.detail(), "number '" + std::string(40, '7') +
                                 "...' (200000 characters) is out of the range of a double (overflows to infinity)");
  const fp::WktError word = wkt_error(std::string(100000, 'Q') + "((0 0,1 0,1 1,0 0))");
  EXPECT_EQ(word.detail(),
            "expected POLYGON or MULTIPOLYGON, found '" + std::string(40, 'Q') + "...' (100000 characters)");
  const fp::WktError junk = wkt_error("POLYGON((0 0,1 0,1 1." + std::string(5000, '5') + ".\x01,0 0))");
  EXPECT_EQ(junk.detail(), "malformed number '1." + std::string(38, '5') + "...' (5004 characters)");
  for (const fp::WktError& e : {number, word, junk}) {
    EXPECT_LT(std::string(e.what()).size(), 200U) << e.what();
  }
  const fp::WktError control = wkt_error("POLYGON((0 0,1 0,1 1\x01\x1b[2J,0 0))");
  EXPECT_NE(control.detail().find("'\\x01'"), std::string::npos) << control.detail();
}
