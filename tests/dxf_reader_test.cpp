// The DXF reader's refusals (docs/cad-gis.md, "What a DXF file must be"): a file cut short at any
// line is refused, never read as a smaller domain; every numeric group value is read by the one
// number rule (src/common/numbers.hpp) and a bad one is named with its line and text; the group
// structure (integer codes, SECTION ... ENDSEC, EOF) is checked and a broken one named; bulges
// whose arc is not representable are named as written; $INSUNITS is reported.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "frontpack/frontpack.hpp"
#include "test_support.hpp"

#if FRONTPACK_TEST_DXF
namespace {

using frontpack::DomainFileError;
using Kind = frontpack::DomainFileError::Kind;

// A square 0..4 with a bulge of 0.5 on its bottom edge (an outward arc) and a CIRCLE hole of
// radius 1 at (2, 2): 48 lines, the EOF group's value on the last.
std::string square_with_hole(const std::string& bulge = "0.5", const std::string& centre_x = "2",
                             const std::string& header = "") {
  return header +
         "  0\nSECTION\n  2\nENTITIES\n  0\nLWPOLYLINE\n  5\n2F\n  8\n0\n 90\n4\n 70\n1\n 10\n0\n 20\n0\n 42\n" +
         bulge + "\n 10\n4\n 20\n0\n 10\n4\n 20\n4\n 10\n0\n 20\n4\n  0\nCIRCLE\n  5\n30\n  8\n0\n 10\n" + centre_x +
         "\n 20\n2\n 40\n1\n  0\nENDSEC\n  0\nEOF\n";
}

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    lines.push_back(line);
  }
  return lines;
}

class DxfReaderTest : public ::testing::Test {
 protected:
  frontpack::test::ScratchDir dir_;

  std::filesystem::path write(const std::string& text, const char* name = "t.dxf") {
    const std::filesystem::path p = dir_ / name;
    std::ofstream(p, std::ios::binary) << text;
    return p;
  }
  frontpack::DomainFile read(const std::string& text) { return frontpack::read_domain_file(write(text)); }
  // The DomainFileError that `text` gives, or a failure.
  DomainFileError error(const std::string& text) {
    try {
      (void)read(text);
    } catch (const DomainFileError& e) {
      return e;
    } catch (const std::exception& e) {
      ADD_FAILURE() << "not a DomainFileError: " << e.what();
      return DomainFileError(Kind::unreadable, "", "");
    }
    ADD_FAILURE() << "no error for:\n" << text;
    return DomainFileError(Kind::unreadable, "", "");
  }
  void expect_error(const std::string& text, Kind kind, const std::vector<std::string>& parts) {
    const DomainFileError e = error(text);
    EXPECT_EQ(frontpack::to_string(e.kind()), std::string(frontpack::to_string(kind))) << e.what();
    for (const auto& part : parts) {
      EXPECT_NE(std::string(e.what()).find(part), std::string::npos) << "'" << part << "' not in: " << e.what();
    }
  }
};

bool same_domain(const frontpack::Domain& a, const frontpack::Domain& b) {
  if (a.num_polygons() != b.num_polygons()) {
    return false;
  }
  for (std::size_t i = 0; i < a.num_polygons(); ++i) {
    if (a.polygons()[i].outer != b.polygons()[i].outer || a.polygons()[i].holes != b.polygons()[i].holes) {
      return false;
    }
  }
  return true;
}

TEST_F(DxfReaderTest, TheSmallFileReadsWithItsHole) {
  const frontpack::DomainFile f = read(square_with_hole());
  EXPECT_EQ(f.domain.num_polygons(), 1u);
  EXPECT_EQ(f.domain.num_holes(), 1u);
  EXPECT_EQ(lines_of(square_with_hole()).size(), 48u);
}

// Defect: the drum cut after its bore CIRCLE's radius read as a drum without a bore.
TEST_F(DxfReaderTest, DrumCutAfterTheBoreRadiusIsRefused) {
  std::ifstream in(frontpack::test::data_dir() / "cad" / "drum.dxf", std::ios::binary);
  const std::vector<std::string> lines = lines_of(std::string(std::istreambuf_iterator<char>(in), {}));
  // The bore: the second CIRCLE (handle 30); its radius value follows its group 40.
  std::size_t cut = 0;
  for (std::size_t i = 0; i + 1 < lines.size(); ++i) {
    if (lines[i] == "CIRCLE" && lines[i + 2] == "30") {
      for (std::size_t j = i; j + 1 < lines.size(); ++j) {
        if (lines[j] == " 40") {
          cut = j + 2;  // lines 1..cut kept: the radius value is the last
          break;
        }
      }
      break;
    }
  }
  ASSERT_GT(cut, 0u);
  ASSERT_EQ(lines[cut - 1], "0.25");
  std::string text;
  for (std::size_t i = 0; i < cut; ++i) {
    text += lines[i] + "\n";
  }
  expect_error(text, Kind::truncated, {"the file ends before EOF", "line " + std::to_string(cut)});
  text.pop_back();  // and without the last newline
  expect_error(text, Kind::truncated, {"the file ends before EOF", "line " + std::to_string(cut)});
}

// Every cut of the small file, at every line, with and without the last newline: refused as cut
// short, or (cut after EOF) the same domain.
TEST_F(DxfReaderTest, EveryCutPointIsRefusedOrReadsTheSameDomain) {
  const std::string whole = square_with_hole();
  const frontpack::DomainFile full = read(whole);
  const std::vector<std::string> lines = lines_of(whole);
  for (std::size_t keep = 0; keep <= lines.size(); ++keep) {
    std::string text;
    for (std::size_t i = 0; i < keep; ++i) {
      text += lines[i] + "\n";
    }
    for (const std::string& t : {text, keep > 0 ? text.substr(0, text.size() - 1) : text}) {
      if (keep == lines.size()) {
        EXPECT_TRUE(same_domain(read(t).domain, full.domain));
      } else {
        SCOPED_TRACE("lines kept: " + std::to_string(keep));
        expect_error(t, Kind::truncated, {"the file ends before EOF"});
      }
    }
  }
}

TEST_F(DxfReaderTest, CrlfLinesAndAByteOrderMarkRead) {
  const frontpack::DomainFile plain = read(square_with_hole());
  std::string crlf;
  for (const std::string& line : lines_of(square_with_hole())) {
    crlf += line + " \r\n";
  }
  EXPECT_TRUE(same_domain(read(crlf).domain, plain.domain));
  EXPECT_TRUE(same_domain(read("\xEF\xBB\xBF" + square_with_hole()).domain, plain.domain));
}

// Defect: a comment of exactly "dxflib" made dxflib throw std::out_of_range (its version stamp
// is "dxflib X.Y.Z"); comments are not handed to dxflib.
TEST_F(DxfReaderTest, CommentsAreNotRead) {
  const frontpack::DomainFile plain = read(square_with_hole());
  for (const std::string comment : {"dxflib", "dxflib ", "dxflib x", "hello"}) {
    SCOPED_TRACE(comment);
    EXPECT_TRUE(same_domain(read("999\n" + comment + "\n" + square_with_hole()).domain, plain.domain));
  }
}

// A circle of two ARCs on one circle, from angle a to b and back.
std::string two_arcs(const std::string& a, const std::string& b) {
  const std::string arc = "  0\nARC\n 10\n1\n 20\n2\n 40\n3\n";
  return "  0\nSECTION\n  2\nENTITIES\n" + arc + " 50\n" + a + "\n 51\n" + b + "\n" + arc + " 50\n" + b + "\n 51\n" +
         a + "\n  0\nENDSEC\n  0\nEOF\n";
}

// Defect: ARC angles -1e300 and 1e300 hung the reader (the sweep reduced by subtracting 360 from
// 2e300). An angle beyond one turn is reduced modulo 360 exactly (fmod): it reads as its
// reduced angle, and angles within a turn are used as written.
TEST_F(DxfReaderTest, ArcAnglesBeyondOneTurnAreReducedExactly) {
  const frontpack::DomainFile half = read(two_arcs("0", "180"));
  EXPECT_TRUE(same_domain(read(two_arcs("720", "900")).domain, half.domain));
  EXPECT_TRUE(same_domain(read(two_arcs("1080", "-1260")).domain, read(two_arcs("0", "-180")).domain));
  // fmod(1.2345e299, 360) = 48, fmod(-7.77e300, 360) = -128.
  const frontpack::DomainFile huge = read(two_arcs("1.2345e299", "-7.77e300"));
  ASSERT_EQ(std::fmod(1.2345e299, 360.0), 48.0);
  ASSERT_EQ(std::fmod(-7.77e300, 360.0), -128.0);
  EXPECT_TRUE(same_domain(huge.domain, read(two_arcs("48", "-128")).domain));
  // 1e300 and -1e300 are 0 turns from 0: two full circles, refused as such.
  expect_error(two_arcs("-1e300", "1e300"), Kind::branching_contour, {"meets 3 other ends"});
}

TEST_F(DxfReaderTest, WhatFollowsEofIsNotRead) {
  EXPECT_TRUE(same_domain(read(square_with_hole() + "junk\n  0\n").domain, read(square_with_hole()).domain));
}

// Defect: a value that fails to parse became 0 (a straight edge, a bore moved to x = 0).
TEST_F(DxfReaderTest, EveryBadNumberIsNamedWithItsLineAndText) {
  for (const std::string bad : {"nan", "abc", "-inf", "inf", "0x10", "", "1e400", "1,5", "1.5.2", "+-1", " 1 2"}) {
    SCOPED_TRACE("bulge '" + bad + "'");
    expect_error(square_with_hole(bad), Kind::bad_number, {"line 20", "LWPOLYLINE (handle 2F, line 6)"});
  }
  for (const std::string bad : {"nan", "abc", "-inf", "0x10", ""}) {
    SCOPED_TRACE("centre '" + bad + "'");
    expect_error(square_with_hole("0.5", bad), Kind::bad_number,
                 {"line 40", "CIRCLE (handle 30, line 34)", "group 10"});
  }
  expect_error(square_with_hole("nan"), Kind::bad_number, {"'nan' is not a finite number"});
  expect_error(square_with_hole("0.5", "abc"), Kind::bad_number, {"'abc' is not a number"});
  expect_error(square_with_hole("0.5", ""), Kind::bad_number, {"expected a number, got nothing"});
  expect_error(square_with_hole("1e-400"), Kind::bad_number, {"'1e-400' is out of the range of a double"});
  // Flags and counts are whole numbers.
  std::string flags = square_with_hole();
  flags.replace(flags.find(" 70\n1\n"), 6, " 70\n1.5\n");
  expect_error(flags, Kind::bad_number, {"line 14", "'1.5' is not a whole number"});
  std::string extrusion = square_with_hole();
  extrusion.replace(extrusion.find(" 40\n1\n"), 6, " 40\n1\n230\nnan\n");
  expect_error(extrusion, Kind::bad_number, {"group 230", "'nan'"});
}

// The counts dxflib allocates by before their items arrive: a huge one would allocate gigabytes,
// and an LWPOLYLINE's 90 other than its vertices drops vertices or adds (0, 0) ones.
TEST_F(DxfReaderTest, CountsMatchWhatTheyCount) {
  std::string more = square_with_hole();
  more.replace(more.find(" 90\n4\n"), 7, " 90\n5\n");
  expect_error(more, Kind::bad_number,
               {"LWPOLYLINE (handle 2F, line 6)", "group 90 (line 12)", "'5' vertices, but the LWPOLYLINE has 4"});
  std::string fewer = square_with_hole();
  fewer.replace(fewer.find(" 90\n4\n"), 7, " 90\n3\n");
  expect_error(fewer, Kind::bad_number, {"'3' vertices, but the LWPOLYLINE has 4"});
  std::string huge = square_with_hole();
  huge.replace(huge.find(" 90\n4\n"), 7, " 90\n2147483647\n");
  expect_error(huge, Kind::bad_number, {"'2147483647' is not a whole number from 0 to"});
  std::string none = square_with_hole();
  none.erase(none.find(" 90\n4\n"), 7);
  expect_error(none, Kind::bad_structure, {"LWPOLYLINE (handle 2F, line 6): no group 90"});
  // In a block too, where nothing is read: a SPLINE's knot count.
  const std::string blocks = "  0\nSECTION\n  2\nBLOCKS\n  0\nSPLINE\n 72\n2000000000\n  0\nENDSEC\n";
  expect_error(blocks + square_with_hole(), Kind::bad_number, {"SPLINE (line 6)", "group 72 (line 8)"});
}

// Defect: an empty value line shifted the parse. An empty string value is a value.
TEST_F(DxfReaderTest, AnEmptyValueLineIsAValue) {
  std::string text = square_with_hole();
  text.replace(text.find("  8\n0\n 10\n2\n"), 6, "  8\n\n");  // the CIRCLE's layer name empty
  const frontpack::DomainFile f = read(text);
  EXPECT_EQ(f.domain.num_holes(), 1u);
}

// Defect: broken structure was reported with a group code as the entity name ("'  5' (line 1086)").
TEST_F(DxfReaderTest, BrokenStructureIsNamed) {
  std::string lost_value = square_with_hole();
  lost_value.erase(lost_value.find("2F\n"), 3);  // the handle's value line gone: the pairs shift
  expect_error(lost_value, Kind::bad_structure, {"line 10", "group 0", "'90' is not a name"});
  std::string code = square_with_hole();
  code.replace(code.find(" 90\n"), 4, "9O\n");
  expect_error(code, Kind::bad_structure, {"line 11", "'9O' is not a group code"});
  std::string no_endsec = square_with_hole();
  no_endsec.erase(no_endsec.find("  0\nENDSEC\n"), 11);
  expect_error(no_endsec, Kind::bad_structure, {"section 'ENTITIES' (line 4)", "ENDSEC", "line 46"});
  expect_error("  0\nLINE\n  0\nEOF\n", Kind::bad_structure, {"line 2", "expected SECTION or EOF"});
}

// Defect: extreme bulges gave a vertex at (-4.45e-308, 6.09e-19), "radius inf", "radius -nan".
TEST_F(DxfReaderTest, ExtremeBulgesAreNamedAsWritten) {
  for (const std::string bad : {"-1e-300", "1e-310", "1e308", "-1e13", "1e-13"}) {
    SCOPED_TRACE(bad);
    expect_error(square_with_hole(bad), Kind::bad_curve,
                 {"LWPOLYLINE (handle 2F, line 6)", "vertex 0", "bulge '" + bad + "' (line 20)"});
  }
  for (const std::string good : {"1e-12", "-1e-12", "-0", "0", "1", "-0.1"}) {
    SCOPED_TRACE(good);
    EXPECT_EQ(read(square_with_hole(good)).domain.num_holes(), 1u);
  }
}

TEST_F(DxfReaderTest, InsunitsIsReported) {
  const std::string header = "  0\nSECTION\n  2\nHEADER\n  9\n$INSUNITS\n 70\n4\n  0\nENDSEC\n";
  EXPECT_EQ(read(square_with_hole("0.5", "2", header)).units, "millimeters");
  EXPECT_EQ(read(square_with_hole()).units, "");
  const std::string unitless = "  0\nSECTION\n  2\nHEADER\n  9\n$INSUNITS\n 70\n0\n  0\nENDSEC\n";
  EXPECT_EQ(read(square_with_hole("0.5", "2", unitless)).units, "unitless");
  const std::string bad = "  0\nSECTION\n  2\nHEADER\n  9\n$INSUNITS\n 70\n99\n  0\nENDSEC\n";
  expect_error(square_with_hole("0.5", "2", bad), Kind::bad_number, {"$INSUNITS", "'99'", "line 8"});
  const std::string word = "  0\nSECTION\n  2\nHEADER\n  9\n$INSUNITS\n 70\nmm\n  0\nENDSEC\n";
  expect_error(square_with_hole("0.5", "2", word), Kind::bad_number, {"'mm'", "line 8"});
}

}  // namespace
#endif  // FRONTPACK_TEST_DXF
