// One number rule for every reader (README "Numbers", src/common/numbers.hpp): a value that is not
// a finite number in the range of a double is refused, with an error naming the file, the line and
// the text written. One table of bad values, fed to every reader at a known line; DXF and GeoJSON
// when the build reads them (GeoJSON's numbers are checked before GDAL parses the JSON, which
// read 1e-400 as 0 and '1.5.5' as a number and named neither the line nor the text; an empty
// value is a JSON syntax error, which GDAL reports).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <regex>
#include <string>
#include <vector>

#include "frontpack/frontpack.hpp"
#include "test_support.hpp"

namespace fp = frontpack;
namespace fs = std::filesystem;

namespace {

// The bad values: not numbers, not finite, out of range, malformed, glued to text.
const std::vector<std::string> kBad = {"nan",   "inf",    "-inf",  "abc", "0x10", "",
                                       "1e400", "1e-400", "1.5.5", "+-1", "1abc"};

struct Reader {
  const char* name;
  const char* file;  // the file name: some readers choose by extension
  // The file's text with the value `v` at line `line`.
  std::function<std::string(const std::string& v)> text;
  std::size_t line;
  std::function<void(const fs::path&)> read;
  // Where an empty value is reported: its own line, or (VTP, where an empty value is no value)
  // the line of the element that lacks it.
  std::size_t empty_line = 0;
};

std::vector<Reader> readers() {
  const auto disks = [](fp::DiskFormat f) { return [f](const fs::path& p) { (void)fp::read_disks(p, f); }; };
  std::vector<Reader> r = {
      {"WKT", "d.wkt", [](const std::string& v) { return "POLYGON((0 0,1 0,\n1 " + v + ",0 1,0 0))\n"; }, 2,
       [](const fs::path& p) { (void)fp::Domain::from_wkt_file(p); }},
      {"CSV", "d.csv", [](const std::string& v) { return "x,y,r\n0.5," + v + ",0.1\n"; }, 2,
       disks(fp::DiskFormat::csv)},
      {"Yade", "d.txt", [](const std::string& v) { return "0.5 0.5 0 0.1\n0.5 0.5 0 " + v + "\n"; }, 2,
       disks(fp::DiskFormat::yade)},
      {"LAMMPS data", "d.data",
       [](const std::string& v) {
         return "title\n\n1 atoms\n1 atom types\n\n0 1 xlo xhi\n0 1 ylo yhi\n-0.5 0.5 zlo zhi\n\nAtoms # sphere\n\n1 1 "
                "0.2 1 0.5 " +
                v + " 0\n";
       },
       12, disks(fp::DiskFormat::lammps)},
      {"LAMMPS dump", "d.dump",
       [](const std::string& v) {
         return "ITEM: TIMESTEP\n0\nITEM: NUMBER OF ATOMS\n1\nITEM: BOX BOUNDS ff ff pp\n0 1\n0 1\n-0.5 0.5\n"
                "ITEM: ATOMS id type x y z radius\n1 1 0.5 " +
                v + " 0 0.1\n";
       },
       10, disks(fp::DiskFormat::lammps_dump)},
      {"VTP", "d.vtp",
       [](const std::string& v) {
         return "<?xml version=\"1.0\"?>\n<VTKFile type=\"PolyData\" version=\"1.0\" byte_order=\"LittleEndian\">\n"
                "<PolyData>\n<Piece NumberOfPoints=\"1\" NumberOfVerts=\"1\">\n<PointData Scalars=\"radius\">\n"
                "<DataArray type=\"Float64\" Name=\"radius\" format=\"ascii\">\n" +
                v +
                "\n</DataArray>\n</PointData>\n<Points>\n<DataArray type=\"Float64\" NumberOfComponents=\"3\" "
                "format=\"ascii\">\n0.5 0.5 0\n</DataArray>\n</Points>\n</Piece>\n</PolyData>\n</VTKFile>\n";
       },
       7, disks(fp::DiskFormat::vtp), 6},
      {"size table", "sizes.csv", [](const std::string& v) { return "diameter,passing\n0.1,0\n" + v + ",1\n"; }, 3,
       [](const fs::path& p) { (void)fp::read_size_table(p); }},
      {"curve", "curve.csv", [](const std::string& v) { return "diameter,passing\n0.1,0\n0.2," + v + "\n"; }, 3,
       [](const fs::path& p) { (void)fp::parse_radii("curve:" + p.string()); }},
  };
  if (fp::has_dxf_reader()) {
    // A CIRCLE's centre x at line 10 (a DXF group is a code line, then a value line).
    r.push_back({"DXF", "d.dxf",
                 [](const std::string& v) {
                   return "0\nSECTION\n2\nENTITIES\n0\nCIRCLE\n8\n0\n10\n" + v +
                          "\n20\n0.5\n40\n0.25\n0\nENDSEC\n0\nEOF\n";
                 },
                 10, [](const fs::path& p) { (void)fp::read_domain_file(p); }});
  }
  if (fp::has_gis_reader()) {
    // The second vertex's y at line 4.
    r.push_back({"GeoJSON", "d.geojson",
                 [](const std::string& v) {
                   return "{\"type\": \"Polygon\", \"coordinates\": [[\n[0, 0], [1, 0],\n[1, 1],\n[0, " + v +
                          "],\n[0, 0]]]}\n";
                 },
                 4, [](const fs::path& p) { (void)fp::read_domain_file(p); }});
  }
  return r;
}

}  // namespace

TEST(NumberRule, EveryReaderRefusesEveryBadNumberNamingFileLineAndText) {
  const fp::test::ScratchDir dir;
  for (const Reader& reader : readers()) {
    for (const std::string& bad : kBad) {
      if (bad.empty() && std::string(reader.name) == "GeoJSON") {
        continue;  // '[0, ]' is a JSON syntax error, GDAL's to report
      }
      SCOPED_TRACE(std::string(reader.name) + " with '" + bad + "'");
      const fs::path path = dir.path() / reader.file;
      std::ofstream(path, std::ios::binary) << reader.text(bad);
      try {
        reader.read(path);
        ADD_FAILURE() << "accepted";
      } catch (const fp::Error& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find(path.string()), std::string::npos) << "file not named: " << what;
        const std::size_t n = bad.empty() && reader.empty_line != 0 ? reader.empty_line : reader.line;
        const std::regex line("(:" + std::to_string(n) + "[:\\s]|line " + std::to_string(n) + "\\b)");
        EXPECT_TRUE(std::regex_search(what, line)) << "line " << n << " not named: " << what;
        if (!bad.empty()) {
          EXPECT_NE(what.find("'" + bad + "'"), std::string::npos) << "text not quoted: " << what;
        }
      }
    }
  }
}
