// The LAMMPS data, LAMMPS dump and VTK PolyData readers: round trips with the writers bit for bit,
// files as LAMMPS and VTK write them (texts taken from their output), and the errors of malformed
// files (kind, line, message). The real programs' own files are read in tests/readers/.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "frontpack/frontpack.hpp"
#include "test_support.hpp"

namespace fp = frontpack;
namespace fs = std::filesystem;
using fp::test::ScratchDir;
using Kind = fp::DiskFileError::Kind;

namespace {

std::vector<fp::Disk> real_packing(const fp::Domain& domain) {
  return fp::test::real_packing(domain, 5);
}

using fp::test::same_bits;

// Values that need all 17 digits, a subnormal radius, negative zero.
std::vector<fp::Disk> awkward_disks() {
  const double third = 1.0 / 3.0;
  return {{{0.1, third}, 0.30000000000000004},
          {{-0.0, std::nextafter(1.0, 2.0)}, std::numeric_limits<double>::denorm_min() * 4},
          {{123456789.12345678, -1e-300}, 1e100},
          {{std::nextafter(1.0, 0.0), 5e-324}, 1e-310}};
}

std::vector<fp::Disk> lammps_text(const std::string& text) {
  std::istringstream in(text);
  return fp::read_lammps(in, "t.data");
}

std::vector<fp::Disk> dump_text(const std::string& text, std::optional<std::int64_t> step = std::nullopt) {
  std::istringstream in(text);
  return fp::read_lammps_dump(in, "t.dump", step);
}

std::vector<fp::Disk> vtp_text(const std::string& text, std::string_view radius_array = {}) {
  std::istringstream in(text);
  return fp::read_vtp(in, "t.vtp", radius_array);
}

// Runs `read` and expects a DiskFileError of `kind` at `line` whose message contains `part`.
template <class Read>
void expect_error(Read read, Kind kind, std::size_t line, const std::string& part) {
  try {
    (void)read();
    ADD_FAILURE() << "no error; expected " << fp::to_string(kind) << ": " << part;
  } catch (const fp::DiskFileError& e) {
    EXPECT_EQ(fp::to_string(e.kind()), std::string(fp::to_string(kind))) << e.what();
    EXPECT_EQ(e.line(), line) << e.what();
    EXPECT_NE(std::string(e.what()).find(part), std::string::npos) << e.what();
  }
}

// LAMMPS 29 Sep 2021's write_data after 20 steps (atoms listed out of id order here, as several
// processors write them), with a comment and the header lines reordered.
const std::string kWriteData =
    "LAMMPS data file via write_data, version 29 Sep 2021, timestep = 20\n"
    "\n"
    "1 atom types\n"
    "4 atoms  # four disks\n"
    "\n"
    "0 4 xlo xhi\n"
    "-0.5 0.5 zlo zhi\n"
    "0 4 ylo yhi\n"
    "\n"
    "Atoms # sphere\n"
    "\n"
    "3 1 1 1 1 2.9998 0 0 0 0\n"
    "1 1 1 1 1 0.9998 0 0 0 0\n"
    "2 1 1 1 3 0.9998 0 0 0 0\n"
    "4 1 0.8 1 3 2.9998 0 0 0 0\n"
    "\n"
    "Velocities\n"
    "\n"
    "1 0 -0.020000000000000014 0 0 0 0\n"
    "2 0 -0.020000000000000014 0 0 0 0\n"
    "3 0 -0.020000000000000014 0 0 0 0\n"
    "4 0 -0.020000000000000014 0 0 0 0\n";

const std::vector<fp::Disk> kWriteDataDisks = {
    {{1, 0.9998}, 0.5}, {{3, 0.9998}, 0.5}, {{1, 2.9998}, 0.5}, {{3, 2.9998}, 0.4}};

const std::string kDump =
    "ITEM: TIMESTEP\n0\nITEM: NUMBER OF ATOMS\n2\nITEM: BOX BOUNDS ff ff pp\n"
    "0.0000000000000000e+00 4.0000000000000000e+00\n0.0000000000000000e+00 4.0000000000000000e+00\n"
    "-5.0000000000000000e-01 5.0000000000000000e-01\n"
    "ITEM: ATOMS id type x y z radius\n2 1 3 1 0 0.5\n1 1 1 1 0 0.25\n"
    "ITEM: TIMESTEP\n10\nITEM: NUMBER OF ATOMS\n2\nITEM: BOX BOUNDS ff ff pp\n0 4\n0 4\n-0.5 0.5\n"
    "ITEM: ATOMS radius z y x type id\n0.25 0 0.99995 1 1 1\n0.5 0 0.99995 3 1 2\n";

// vtkXMLPolyDataWriter (VTK 9.1) of three points in binary mode, uncompressed.
const std::string kVtkBinary =
    "<?xml version=\"1.0\"?>\n"
    "<VTKFile type=\"PolyData\" version=\"0.1\" byte_order=\"LittleEndian\" header_type=\"UInt32\">\n"
    "  <PolyData>\n"
    "    <Piece NumberOfPoints=\"3\" NumberOfVerts=\"0\" NumberOfLines=\"0\" NumberOfStrips=\"0\" "
    "NumberOfPolys=\"0\">\n"
    "      <PointData>\n"
    "        <DataArray type=\"Float64\" Name=\"radius\" format=\"binary\" RangeMin=\"0.05\">\n"
    "          GAAAAJqZmZmZmak/+Iqv+IqvyD/FV3zFV3zVPw==\n"
    "        </DataArray>\n"
    "      </PointData>\n"
    "      <CellData>\n"
    "      </CellData>\n"
    "      <Points>\n"
    "        <DataArray type=\"Float64\" Name=\"Points\" NumberOfComponents=\"3\" format=\"binary\">\n"
    "          "
    "SAAAAFVVVVVVVdU/ZmZmZmZm5j8AAAAAAAAAALy7u7u7u9s/ZmZmZmZm5j8AAAAAAAAAABEREREREeE/ZmZmZmZm5j8AAAAAAAAAAA==\n"
    "          <InformationKey name=\"L2_NORM_RANGE\" location=\"vtkDataArray\" length=\"2\">\n"
    "            <Value index=\"0\">\n              0.77531355664\n            </Value>\n"
    "          </InformationKey>\n"
    "        </DataArray>\n"
    "      </Points>\n"
    "    </Piece>\n"
    "  </PolyData>\n"
    "</VTKFile>\n";

const std::vector<fp::Disk> kVtkDisks = {
    {{1.0 / 3.0, 0.7}, 0.05}, {{0.1 + 1.0 / 3.0, 0.7}, 0.05 + 1.0 / 7.0}, {{0.2 + 1.0 / 3.0, 0.7}, 0.05 + 2.0 / 7.0}};

}  // namespace

TEST(DiskReaders, LammpsRoundTripIsBitIdentical) {
  const fp::Domain domain = fp::Domain::from_wkt_file(fp::test::shapes_dir() / "l_shape.wkt");
  const std::vector<fp::Disk> disks = real_packing(domain);
  ASSERT_GT(disks.size(), 100u);
  std::ostringstream out;
  fp::write_lammps(out, disks, domain.bbox());
  EXPECT_TRUE(same_bits(lammps_text(out.str()), disks));

  const std::vector<fp::Disk> awkward = awkward_disks();
  std::ostringstream hostile;
  fp::write_lammps(hostile, awkward, fp::Box{-1e101, -1e101, 2e101, 2e101});
  EXPECT_TRUE(same_bits(lammps_text(hostile.str()), awkward));
}

TEST(DiskReaders, VtpRoundTripIsBitIdentical) {
  const fp::Domain domain = fp::Domain::from_wkt_file(fp::test::shapes_dir() / "l_shape.wkt");
  for (const std::vector<fp::Disk>& disks : {real_packing(domain), awkward_disks(), std::vector<fp::Disk>{}}) {
    std::ostringstream out;
    fp::write_vtp(out, disks);
    EXPECT_TRUE(same_bits(vtp_text(out.str()), disks));
  }
}

TEST(DiskReaders, ReadDisksDispatchesByExtensionAndName) {
  const ScratchDir dir;
  const fp::Domain domain = fp::Domain::from_wkt_file(fp::test::shapes_dir() / "l_shape.wkt");
  const std::vector<fp::Disk> disks = real_packing(domain);
  for (const char* name : {"p.data", "p.lmp", "P.VTP"}) {
    const fs::path path = dir.path() / name;
    fp::write_file(path, fp::format_from_path(path), domain, disks);
    EXPECT_TRUE(same_bits(fp::read_disks(path), disks)) << name;
  }
  std::ofstream(dir.path() / "run.lammpstrj") << kDump;
  EXPECT_EQ(fp::read_disks(dir.path() / "run.lammpstrj").size(), 2u);
  // A dump named .txt is read as one when the format is named.
  std::ofstream(dir.path() / "run.txt") << kDump;
  fp::ReadOptions options;
  options.timestep = 0;
  const auto first = fp::read_disks(dir.path() / "run.txt", fp::disk_format_from_name("lammps-dump"), options);
  EXPECT_EQ(first, (std::vector<fp::Disk>{{{1, 1}, 0.25}, {{3, 1}, 0.5}}));
  EXPECT_EQ(fp::disk_format_from_path("a.dump"), fp::DiskFormat::lammps_dump);
  EXPECT_THROW((void)fp::disk_format_from_name("dump"), fp::OptionError);
  try {
    (void)fp::read_disks(dir.path() / "p.svg");
    ADD_FAILURE() << "no error";
  } catch (const fp::OptionError& e) {
    EXPECT_NE(std::string(e.what()).find("unknown disk file format '.svg'; frontpack reads .csv"), std::string::npos)
        << e.what();
  }
}

TEST(DiskReaders, LammpsWriteDataAfterARun) {
  EXPECT_EQ(lammps_text(kWriteData), kWriteDataDisks);
  // No image flags, CRLF line ends, no style hint, a Masses section.
  EXPECT_EQ(lammps_text("title\r\n2 atoms\r\n1 atom types\r\n0 1 xlo xhi\r\n0 1 ylo yhi\r\n-1 1 zlo zhi\r\n\r\n"
                        "Masses\r\n\r\n1 1\r\n\r\nAtoms\r\n\r\n2 1 0.5 1 0.5 0.5 0\r\n1 1 0.25 1 0.2 0.2 -0\r\n"),
            (std::vector<fp::Disk>{{{0.2, 0.2}, 0.125}, {{0.5, 0.5}, 0.25}}));
  EXPECT_TRUE(lammps_text("empty\n\n0 atoms\n").empty());
}

TEST(DiskReaders, LammpsErrors) {
  const std::string head = "t\n2 atoms\n0 1 xlo xhi\n0 1 ylo yhi\n-1 1 zlo zhi\nAtoms # sphere\n";
  expect_error([] { return lammps_text(""); }, Kind::empty_file, 1, "empty file");
  expect_error([] { return lammps_text("t\n0 1 xlo xhi\n"); }, Kind::missing_item, 2, "no 'N atoms' header line");
  expect_error([] { return lammps_text("t\n2 atomz\n"); }, Kind::syntax, 2, "expected a header line");
  expect_error([] { return lammps_text("t\n-2 atoms\n"); }, Kind::bad_number, 2, "the number of atoms");
  expect_error([] { return lammps_text("t\n2 atoms\nAtoms # atomic\n1 1 0 0 0\n"); }, Kind::unsupported_format, 3,
               "atom style 'atomic': frontpack reads LAMMPS data files of atom_style sphere");
  expect_error([&] { return lammps_text(head + "1 1 1 1 0.5 0.5\n"); }, Kind::field_count, 7,
               "expected 'id type diameter density x y z'");
  expect_error([&] { return lammps_text(head + "1 1 1 1 0.5 0.5 0.1\n"); }, Kind::nonzero_z, 7,
               "z must be 0 (frontpack's disks are planar), got '0.1'");
  expect_error([&] { return lammps_text(head + "1 1 0 1 0.5 0.5 0\n"); }, Kind::bad_radius, 7,
               "diameter must be > 0, got '0'");
  expect_error([&] { return lammps_text(head + "1 1 1 1 0.5 nan 0\n"); }, Kind::non_finite, 7, "y 'nan' is not finite");
  expect_error([&] { return lammps_text(head + "1 1 1 1 0.5 0.5 0\n"); }, Kind::count_mismatch, 7,
               "the Atoms section (line 6) has 1 atoms; the header declares 2");
  expect_error([&] { return lammps_text(head + "1 1 1 1 0.5 0.5 0\n2 1 1 1 0.5 0.5 0\n3 1 1 1 0.5 0.5 0\n"); },
               Kind::count_mismatch, 9, "more atoms than the 2 the header declares");
  expect_error([&] { return lammps_text(head + "1 1 1 1 0.5 0.5 0\n\n1 1 1 1 0.7 0.5 0\n"); }, Kind::duplicate_id, 9,
               "atom id 1 given twice (also on line 7)");
  expect_error([&] { return lammps_text(head + "0 1 1 1 0.5 0.5 0\n"); }, Kind::bad_number, 7, "atom id must be >= 1");
  expect_error([] { return lammps_text("t\n2 atoms\nVelocities\n1 0 0 0\n"); }, Kind::missing_item, 4,
               "no Atoms section; the header declares 2 atoms");
}

TEST(DiskReaders, LammpsDumpSnapshots) {
  // The last snapshot by default; columns by name in any order; sorted by id.
  EXPECT_EQ(dump_text(kDump), (std::vector<fp::Disk>{{{1, 0.99995}, 0.25}, {{3, 0.99995}, 0.5}}));
  EXPECT_EQ(dump_text(kDump, 0), (std::vector<fp::Disk>{{{1, 1}, 0.25}, {{3, 1}, 0.5}}));
  // Unwrapped coordinates, a diameter, no z, extra columns.
  EXPECT_EQ(dump_text("ITEM: TIMESTEP\n5\nITEM: NUMBER OF ATOMS\n1\nITEM: BOX BOUNDS pp pp pp\n0 1\n0 1\n0 1\n"
                      "ITEM: ATOMS id vx xu yu diameter\n7 0.5 0.25 0.75 0.5\n"),
            (std::vector<fp::Disk>{{{0.25, 0.75}, 0.25}}));
}

TEST(DiskReaders, LammpsDumpErrors) {
  const std::string head = "ITEM: TIMESTEP\n3\nITEM: NUMBER OF ATOMS\n2\nITEM: BOX BOUNDS ff ff pp\n0 1\n0 1\n0 1\n";
  expect_error([] { return dump_text(""); }, Kind::empty_file, 1, "empty file");
  expect_error([&] { return dump_text(kDump, 15); }, Kind::missing_item, 22,
               "no snapshot of timestep 15 (the dump has 2 snapshots: timesteps 0, 10)");
  expect_error([&] { return dump_text(head + "ITEM: ATOMS id type x y z\n"); }, Kind::missing_item, 9,
               "no radius (or diameter) column");
  expect_error([&] { return dump_text(head + "ITEM: ATOMS id type xs ys zs radius\n"); }, Kind::unsupported_format, 9,
               "scaled coordinates");
  expect_error([&] { return dump_text(head + "ITEM: ATOMS id x y radius\n1 0 0 1\n"); }, Kind::count_mismatch, 10,
               "the snapshot of timestep 3 (ATOMS on line 9) ends after 1 of its 2 atoms");
  expect_error([&] { return dump_text(head + "ITEM: ATOMS id x y z radius\n1 0 0 0 1\n2 0 0 1e-9 1\n"); },
               Kind::nonzero_z, 11, "z must be 0");
  expect_error([&] { return dump_text(head + "ITEM: ATOMS id x y radius\n1 0 0 1\n2 0 0\n"); }, Kind::field_count, 11,
               "expected 4 values as the ATOMS line names, got 3");
  expect_error([&] { return dump_text(head + "ITEM: ATOMS id x y radius\n1 0 0 1\n1 0 0 1\n"); }, Kind::duplicate_id,
               11, "atom id 1 given twice (also on line 10)");
  expect_error([&] { return dump_text(head); }, Kind::missing_item, 8, "the last snapshot has no 'ITEM: ATOMS'");
  expect_error([] { return dump_text("1 2 3\n"); }, Kind::syntax, 1, "expected an 'ITEM: ...' line");
  // Two snapshots of one timestep (a run appended to its own dump after a restart): which one is
  // meant is not the reader's guess, whichever timestep is asked for.
  const std::string again = kDump.substr(kDump.find("ITEM: TIMESTEP\n10"));
  for (const std::optional<std::int64_t> step :
       {std::optional<std::int64_t>{}, std::optional<std::int64_t>{10}, std::optional<std::int64_t>{0}}) {
    expect_error([&] { return dump_text(kDump + again, step); }, Kind::duplicate_id, 24,
                 "timestep 10 given twice: the snapshots of lines 12 and 23");
  }
}

TEST(DiskReaders, VtkBinaryAndAppendedLayouts) {
  EXPECT_EQ(vtp_text(kVtkBinary), kVtkDisks);
  // The same data appended as base64 (VTK encodes each array on its own, padding included).
  std::string appended = kVtkBinary;
  const auto replace = [&](const std::string& from, const std::string& to) {
    const std::size_t at = appended.find(from);
    ASSERT_NE(at, std::string::npos) << from;
    appended.replace(at, from.size(), to);
  };
  replace("format=\"binary\" RangeMin=\"0.05\">\n          GAAAAJqZmZmZmak/+Iqv+IqvyD/FV3zFV3zVPw==\n",
          "format=\"appended\" offset=\"0\">\n");
  replace("format=\"binary\">\n          SAAAAFVV", "format=\"appended\" offset=\"40\">\n          <!-- SAAAAFVV");
  replace("AAAAAA==\n          <Information", "AAAAAA== -->\n          <Information");
  replace("</VTKFile>",
          "  <AppendedData encoding=\"base64\">\n   _GAAAAJqZmZmZmak/+Iqv+IqvyD/FV3zFV3zVPw=="
          "SAAAAFVVVVVVVdU/ZmZmZmZm5j8AAAAAAAAAALy7u7u7u9s/ZmZmZmZm5j8AAAAAAAAAABEREREREeE/ZmZmZmZm5j8AAAAAAAAAAA=="
          "\n  </AppendedData>\n</VTKFile>");
  EXPECT_EQ(vtp_text(appended), kVtkDisks);
  // Radius arrays by other names: Radius, diameter (halved), or named by the caller.
  std::string named = kVtkBinary;
  named.replace(named.find("Name=\"radius\""), 13, "Name=\"Diameter\"");
  const std::vector<fp::Disk> halved = vtp_text(named);
  ASSERT_EQ(halved.size(), 3u);
  EXPECT_EQ(halved[1].radius, kVtkDisks[1].radius / 2);
  EXPECT_EQ(vtp_text(named, "Diameter")[1].radius, kVtkDisks[1].radius);
}

TEST(DiskReaders, VtpErrors) {
  std::string compressed = kVtkBinary;
  compressed.replace(compressed.find("header_type=\"UInt32\""), 20,
                     "header_type=\"UInt32\" compressor=\"vtkZLibDataCompressor\"");
  expect_error([&] { return vtp_text(compressed); }, Kind::unsupported_format, 13,
               "<DataArray Name='Points'>: compressed data (vtkZLibDataCompressor) is not read by frontpack");
  expect_error([&] { return vtp_text(kVtkBinary, "size"); }, Kind::missing_item, 4,
               "<Piece>: no point data array 'size' for the radii (point data arrays: 'radius')");
  std::string grid = kVtkBinary;
  grid.replace(grid.find("type=\"PolyData\""), 15, "type=\"UnstructuredGrid\"");
  expect_error([&] { return vtp_text(grid); }, Kind::unsupported_format, 2,
               "<VTKFile type='UnstructuredGrid'>: frontpack reads VTK PolyData");
  std::string bad64 = kVtkBinary;
  bad64.replace(bad64.find("GAAAAJqZ"), 1, "!");
  expect_error([&] { return vtp_text(bad64); }, Kind::bad_number, 6, "<DataArray Name='radius'>: invalid base64");
  std::string shortened = kVtkBinary;
  shortened.replace(shortened.find("NumberOfPoints=\"3\""), 18, "NumberOfPoints=\"4\"");
  expect_error([&] { return vtp_text(shortened); }, Kind::count_mismatch, 13,
               "the binary header declares 72 bytes; 12 values of 8 bytes are 96");
  expect_error([] { return vtp_text(""); }, Kind::empty_file, 1, "no <VTKFile> element");
  expect_error([&] { return vtp_text(kVtkBinary.substr(0, kVtkBinary.find("</Points>"))); }, Kind::syntax, 21,
               "the file ends inside the element 'Points'");
  // ASCII: a z that is not 0, a radius <= 0, a value too many.
  const auto ascii = [](const std::string& points, const std::string& radii) {
    return "<VTKFile type=\"PolyData\"><PolyData><Piece NumberOfPoints=\"2\">\n<PointData>\n"
           "<DataArray type=\"Float32\" Name=\"radius\" format=\"ascii\">" +
           radii + "</DataArray></PointData>\n<Points><DataArray type=\"Float64\" NumberOfComponents=\"3\" " +
           "Name=\"Points\" format=\"ascii\">" + points + "</DataArray></Points></Piece></PolyData></VTKFile>";
  };
  EXPECT_EQ(vtp_text(ascii("0 0 0 1 1 0", "0.5 0.1")),
            (std::vector<fp::Disk>{{{0, 0}, 0.5}, {{1, 1}, static_cast<double>(0.1f)}}));
  expect_error([&] { return vtp_text(ascii("0 0 0 1 1 2", "0.5 0.5")); }, Kind::nonzero_z, 4, "point 1: z must be 0");
  expect_error([&] { return vtp_text(ascii("0 0 0 1 1 0", "0.5 -1")); }, Kind::bad_radius, 3,
               "point 1: radius must be > 0, got -1");
  expect_error([&] { return vtp_text(ascii("0 0 0 1 1 0 7", "0.5 1")); }, Kind::count_mismatch, 4,
               "more than the 6 values expected");
  expect_error([&] { return vtp_text(ascii("0 0 0 1 1 0", "0.5 x")); }, Kind::bad_number, 3,
               "'x' is not a number of type Float32");
}
