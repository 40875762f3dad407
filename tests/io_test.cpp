// File formats: bit-identical round trips (CSV, Yade) on real packings and hostile doubles; every
// malformed-line case names its line; atomic write_file (no partial file, no temporary left, old
// readers keep the old file); the LAMMPS and VTK writers' structure, parsed back.
#include <gtest/gtest.h>

#include <signal.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <limits>
#include <sstream>
#include <string>
#include <system_error>
#include <utility>
#include <vector>

#include "frontpack/frontpack.hpp"
#include "test_support.hpp"

namespace fp = frontpack;
namespace fs = std::filesystem;
using fp::test::ScratchDir;
using fp::test::slurp;

namespace {

std::vector<fp::Disk> real_packing(const fp::Domain& domain) {
  return fp::test::real_packing(domain, 7);
}

using fp::test::same_bits;

fp::Domain l_shape() {
  return fp::Domain::from_wkt_file(fp::test::shapes_dir() / "l_shape.wkt");
}

// Values that need all 17 digits, subnormals, extremes, negative zero.
std::vector<fp::Disk> hostile_disks() {
  const double values[] = {0.1,
                           1.0 / 3.0,
                           0.30000000000000004,
                           std::nextafter(1.0, 2.0),
                           std::nextafter(1.0, 0.0),
                           123456789.12345678,
                           1e300,
                           -1e300,
                           1e100,
                           std::numeric_limits<double>::denorm_min(),
                           std::numeric_limits<double>::min(),
                           std::nextafter(std::numeric_limits<double>::min(), 0.0),
                           std::numeric_limits<double>::max(),
                           -0.0,
                           0.0,
                           -2.5e-320,
                           9007199254740991.0,
                           5e-324};
  std::vector<fp::Disk> disks;
  const std::size_t n = std::size(values);
  for (std::size_t i = 0; i < n; ++i) {
    const double r = std::abs(values[(i + 5) % n]);
    disks.push_back({{values[i], values[(i + 3) % n]}, r > 0 ? r : 0.5});
  }
  return disks;
}

std::string csv_text(const std::vector<fp::Disk>& disks) {
  std::ostringstream out;
  fp::write_csv(out, disks);
  return out.str();
}

std::vector<fp::Disk> read_csv_text(const std::string& text, std::string_view name = "disks.csv") {
  std::istringstream in(text);
  return fp::read_csv(in, name);
}

std::vector<fp::Disk> read_yade_text(const std::string& text, std::string_view name = "disks.txt") {
  std::istringstream in(text);
  return fp::read_yade(in, name);
}

double parse_double(std::string_view s) {
  double v = 0;
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  EXPECT_TRUE(ec == std::errc{} && end == s.data() + s.size()) << "not a number: '" << s << "'";
  return v;
}

std::vector<std::string> words(const std::string& line) {
  std::istringstream in(line);
  std::vector<std::string> out;
  for (std::string w; in >> w;) {
    out.push_back(w);
  }
  return out;
}

// ---------------------------------------------------------------- round trips

TEST(IoRoundTrip, CsvAndYadeOfARealPackingAreBitIdentical) {
  const fp::Domain domain = l_shape();
  const std::vector<fp::Disk> disks = real_packing(domain);
  ASSERT_GT(disks.size(), 100u);
  EXPECT_TRUE(same_bits(read_csv_text(csv_text(disks)), disks));
  std::ostringstream yade;
  fp::write_yade(yade, disks);
  EXPECT_TRUE(same_bits(read_yade_text(yade.str()), disks));
}

TEST(IoRoundTrip, CertificateHoldsForTheFile) {
  const fp::Domain domain = l_shape();
  const std::vector<fp::Disk> back = read_csv_text(csv_text(real_packing(domain)));
  const fp::CertifyReport report = fp::certify(domain, back);
  EXPECT_TRUE(report.outside.empty());
  EXPECT_TRUE(report.overlapping.empty());
}

TEST(IoRoundTrip, HostileValuesAreBitIdentical) {
  const std::vector<fp::Disk> disks = hostile_disks();
  const std::vector<fp::Disk> csv = read_csv_text(csv_text(disks));
  EXPECT_TRUE(same_bits(csv, disks));
  std::ostringstream yade;
  fp::write_yade(yade, disks);
  EXPECT_TRUE(same_bits(read_yade_text(yade.str()), disks));
  // -0.0 survives with its sign.
  ASSERT_EQ(csv[13].centre.x, 0.0);
  EXPECT_TRUE(std::signbit(csv[13].centre.x));
}

TEST(IoRoundTrip, WriteFileAndReadDisks) {
  const ScratchDir dir;
  const fp::Domain domain = l_shape();
  const std::vector<fp::Disk> disks = real_packing(domain);
  for (const char* name : {"p.csv", "p.txt", "p.yade", "P.CSV"}) {
    const fs::path path = dir.path() / name;
    fp::write_file(path, fp::format_from_path(path), domain, disks);
    EXPECT_TRUE(same_bits(fp::read_disks(path), disks)) << name;
  }
  // The file holds exactly what the stream writer writes.
  std::ostringstream expected;
  fp::write_yade(expected, disks);
  EXPECT_EQ(slurp(dir.path() / "p.txt"), expected.str());
}

TEST(IoRoundTrip, EmptyPackings) {
  EXPECT_TRUE(read_csv_text(csv_text({})).empty());
  std::ostringstream yade;
  fp::write_yade(yade, {});
  EXPECT_EQ(yade.str(), "#format x_y_z_r\n");
  EXPECT_TRUE(read_yade_text(yade.str()).empty());
}

// ---------------------------------------------------------------- lenient where harmless

TEST(IoRead, CsvToleratesCrlfSpacesBomAndNoFinalNewline) {
  const std::vector<fp::Disk> want = {{{1, 2}, 0.5}, {{-3, 4e-3}, 0.25}};
  EXPECT_TRUE(same_bits(read_csv_text("x,y,r\r\n1,2,0.5\r\n-3,4e-3,0.25\r\n"), want));
  EXPECT_TRUE(same_bits(read_csv_text(" x , y , r\n 1 ,\t2, 0.5 \n-3,4e-3,0.25"), want));
  EXPECT_TRUE(same_bits(read_csv_text("\xEF\xBB\xBFx,y,r\n1,2,0.5\n-3,4e-3,0.25\n"), want));
}

TEST(IoRead, YadeCommentsTabsAndFormatLine) {
  const std::vector<fp::Disk> want = {{{1, 2}, 0.5}, {{-3, 4e-3}, 0.25}};
  EXPECT_TRUE(
      same_bits(read_yade_text("# made by hand\n#format x_y_z_r\n1 2 0 0.5\n  #x y z r\n-3\t4e-3  -0 0.25\r\n"), want));
  EXPECT_TRUE(same_bits(read_yade_text("1 2 0 0.5\n-3 4e-3 0 0.25"), want));
}

// ---------------------------------------------------------------- malformed input

struct Bad {
  const char* text;
  fp::DiskFileError::Kind kind;
  std::size_t line;
  std::size_t column;
  const char* message;  // a part of what()
};

void expect_error(bool yade, const Bad& b) {
  SCOPED_TRACE(std::string("input: ") + b.text);
  try {
    if (yade) {
      (void)read_yade_text(b.text);
    } else {
      (void)read_csv_text(b.text);
    }
    ADD_FAILURE() << "no error";
  } catch (const fp::DiskFileError& e) {
    EXPECT_EQ(fp::to_string(e.kind()), std::string(fp::to_string(b.kind)));
    EXPECT_EQ(e.line(), b.line);
    EXPECT_EQ(e.column(), b.column);
    EXPECT_EQ(e.source(), yade ? "disks.txt" : "disks.csv");
    EXPECT_NE(std::string(e.what()).find(b.message), std::string::npos) << e.what();
  }
}

TEST(IoRead, MalformedCsvNamesTheLine) {
  using K = fp::DiskFileError::Kind;
  std::string seventeen = "x,y,r\n";
  for (int i = 0; i < 15; ++i) {
    seventeen += "0.5,0.5,0.1\n";
  }
  seventeen += "abc,1\n0,0,1\n";
  const Bad cases[] = {
      {seventeen.c_str(), K::field_count, 17, 0, "disks.csv:17: expected 3 comma-separated numbers, got 'abc,1'"},
      {"", K::empty_file, 1, 0, "disks.csv:1: empty file (expected the header line 'x,y,r')"},
      {"1,2,3\n", K::missing_header, 1, 0, "expected the header line 'x,y,r', got '1,2,3'"},
      {"x,y\n1,2\n", K::missing_header, 1, 0, "got 'x,y'"},
      {"x,y,r,z\n", K::missing_header, 1, 0, "got 'x,y,r,z'"},
      {"x,y,r\n1,2,3\n\n4,5,6\n", K::blank_line, 3, 0, "disks.csv:3: blank line"},
      {"x,y,r\n1,2,3\n1,2,3,4\n", K::field_count, 3, 0, "got '1,2,3,4'"},
      {"x,y,r\n1,2,3\nabc,1,2\n", K::bad_number, 3, 1, "disks.csv:3:1: x 'abc' is not a number"},
      {"x,y,r\n1, 2x,3\n", K::bad_number, 2, 4, "disks.csv:2:4: y '2x' is not a number"},
      {"x,y,r\n1,2,0.5e\n", K::bad_number, 2, 5, "radius '0.5e' is not a number"},
      {"x,y,r\n+1,2,3\n", K::bad_number, 2, 1, "x '+1' is not a number"},
      {"x,y,r\n1,,3\n", K::bad_number, 2, 3, "expected a number for y, got nothing"},
      {"x,y,r\n1e400,2,3\n", K::bad_number, 2, 1, "x '1e400' is out of the range of a double"},
      {"x,y,r\n1,2,1e-400\n", K::bad_number, 2, 5, "out of the range"},
      {"x,y,r\nnan,2,3\n", K::non_finite, 2, 1, "x 'nan' is not finite"},
      {"x,y,r\n1,inf,3\n", K::non_finite, 2, 3, "y 'inf' is not finite"},
      {"x,y,r\n1,2,-inf\n", K::non_finite, 2, 5, "not finite"},
      {"x,y,r\n1,2,-1\n", K::bad_radius, 2, 5, "disks.csv:2:5: radius must be > 0, got '-1'"},
      {"x,y,r\n1,2,0\n", K::bad_radius, 2, 5, "radius must be > 0, got '0'"},
      {"x,y,r\n1,2,-0\n", K::bad_radius, 2, 5, "radius must be > 0, got '-0'"},
      {"x,y,r\r\n1,2,3\r\n4;5;6\r\n", K::field_count, 3, 0, "got '4;5;6'"},
  };
  for (const Bad& b : cases) {
    expect_error(false, b);
  }
}

TEST(IoRead, MalformedYadeNamesTheLine) {
  using K = fp::DiskFileError::Kind;
  const Bad cases[] = {
      {"", K::empty_file, 1, 0, "disks.txt:1: empty file"},
      {"#format x_y_z_r_attrs\n1 2 0 3 1\n", K::unsupported_format, 1, 1, "frontpack reads '#format x_y_z_r' and"},
      {"#format x_y_z_r_matId\n1 2 0 3 -1\n", K::bad_number, 2, 9, "matId '-1' is not a whole number >= 0"},
      {"#format x_y_z_r_matId\n1 2 0 3\n", K::field_count, 2, 0, "expected 5 numbers 'x y z r matId'"},
      {"#format\n", K::unsupported_format, 1, 1, "unsupported"},
      {"#format x_y_z_r\n1 2 0 0.5\n1 2 0\n", K::field_count, 3, 0,
       "disks.txt:3: expected 4 numbers 'x y z r' separated by spaces, got '1 2 0'"},
      {"1 2 0 0.5 7\n", K::field_count, 1, 0, "got '1 2 0 0.5 7'"},
      {"1,2,0,0.5\n", K::field_count, 1, 0, "got '1,2,0,0.5'"},
      {"1 2 0 0.5\n\n", K::blank_line, 2, 0, "disks.txt:2: blank line (Yade's ymport.textExt fails on it)"},
      {"1 2 0 0.5\n   \n1 2 0 0.5\n", K::blank_line, 2, 0, "blank line"},
      {"1 2 0.5 0.5\n", K::nonzero_z, 1, 5, "disks.txt:1:5: z must be 0 (frontpack's disks are planar), got '0.5'"},
      {"1 2 0 -0.5\n", K::bad_radius, 1, 7, "radius must be > 0, got '-0.5'"},
      {"1 2 nan 0.5\n", K::non_finite, 1, 5, "z 'nan' is not finite"},
      {"1 y 0 0.5\n", K::bad_number, 1, 3, "y 'y' is not a number"},
  };
  for (const Bad& b : cases) {
    expect_error(true, b);
  }
}

TEST(IoRead, UnnamedSource) {
  std::istringstream in("x,y,r\n1,2\n");
  try {
    (void)fp::read_csv(in, "");
    ADD_FAILURE() << "no error";
  } catch (const fp::DiskFileError& e) {
    EXPECT_EQ(std::string(e.what()), "<input>:2: expected 3 comma-separated numbers, got '1,2'");
  }
}

TEST(IoRead, ReadDisksErrors) {
  const ScratchDir dir;
  try {
    (void)fp::read_disks(dir.path() / "missing.csv");
    ADD_FAILURE() << "no error";
  } catch (const fp::IoError& e) {
    EXPECT_NE(std::string(e.what()).find("missing.csv': No such file or directory"), std::string::npos) << e.what();
  }
  fs::create_directory(dir.path() / "d.csv");
  EXPECT_THROW((void)fp::read_disks(dir.path() / "d.csv"), fp::IoError);
  EXPECT_THROW((void)fp::read_disks(dir.path() / "p.svg"), fp::OptionError);
  EXPECT_THROW((void)fp::read_disks(dir.path() / "p.xyz"), fp::OptionError);
  std::ofstream(dir.path() / "bad.csv") << "x,y,r\n1,2,3\n1,2\n";
  try {
    (void)fp::read_disks(dir.path() / "bad.csv");
    ADD_FAILURE() << "no error";
  } catch (const fp::DiskFileError& e) {
    EXPECT_EQ(e.source(), (dir.path() / "bad.csv").string());
    EXPECT_EQ(e.line(), 3u);
  }
}

// ---------------------------------------------------------------- formats by name

TEST(IoFormat, FromPathAndName) {
  EXPECT_EQ(fp::format_from_path("a/b.csv"), fp::Format::csv);
  EXPECT_EQ(fp::format_from_path("b.TXT"), fp::Format::yade);
  EXPECT_EQ(fp::format_from_path("b.yade"), fp::Format::yade);
  EXPECT_EQ(fp::format_from_path("b.data"), fp::Format::lammps);
  EXPECT_EQ(fp::format_from_path("b.lmp"), fp::Format::lammps);
  EXPECT_EQ(fp::format_from_path("b.vtp"), fp::Format::vtp);
  EXPECT_EQ(fp::format_from_path("b.svg"), fp::Format::svg);
  for (const fp::Format f : {fp::Format::csv, fp::Format::yade, fp::Format::lammps, fp::Format::vtp, fp::Format::svg}) {
    EXPECT_EQ(fp::format_from_name(fp::to_string(f)), f);
  }
  const auto message = [](auto&& call) {
    try {
      call();
    } catch (const fp::OptionError& e) {
      return std::string(e.what());
    }
    return std::string("no OptionError");
  };
  EXPECT_NE(message([] { (void)fp::format_from_path("out.xyz"); }).find("unknown format '.xyz'; use .csv"),
            std::string::npos);
  EXPECT_NE(message([] { (void)fp::format_from_path("out.png"); }).find("PNG pictures are drawn by the frontpack tool"),
            std::string::npos);
  EXPECT_NE(message([] { (void)fp::format_from_path("out"); }).find("no file extension"), std::string::npos);
  EXPECT_NE(message([] { (void)fp::format_from_name("vtk"); }).find("unknown format 'vtk'; expected csv, yade"),
            std::string::npos);
}

// ---------------------------------------------------------------- atomic files

TEST(IoWriteFile, ReplacesAtomicallyAndLeavesNoTemporary) {
  const ScratchDir dir;
  const fp::Domain domain = l_shape();
  const std::vector<fp::Disk> disks = real_packing(domain);
  const fs::path target = dir.path() / "p.csv";
  std::ofstream(target) << "old contents\n";
  std::ifstream old_reader(target);  // opened before the replacement
  fp::write_file(target, fp::Format::csv, domain, disks);
  EXPECT_EQ(slurp(target), csv_text(disks));
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"p.csv"});
  // A reader of the old file still sees the whole old file: the new one was renamed over it,
  // not written into it.
  std::string line;
  std::getline(old_reader, line);
  EXPECT_EQ(line, "old contents");
}

TEST(IoWriteFile, NewFileGetsTheUmaskPermissions) {
  const ScratchDir dir;
  const mode_t old_mask = ::umask(022);
  fp::write_file(dir.path() / "p.csv", fp::Format::csv, l_shape(), {});
  ::umask(old_mask);
  struct stat st {};
  ASSERT_EQ(::stat((dir.path() / "p.csv").c_str(), &st), 0);
  EXPECT_EQ(st.st_mode & 0777, 0644u);
}

TEST(IoWriteFile, UnwritableDirectoryNamesThePathAndReason) {
  const ScratchDir dir;
  const fp::Domain domain = l_shape();
  const std::vector<fp::Disk> disks = real_packing(domain);
  std::ofstream(dir.path() / "file") << "x";
  struct Case {
    fs::path path;
    const char* reason;
  };
  std::vector<Case> cases = {{dir.path() / "missing" / "p.csv", "No such file or directory"},
                             {dir.path() / "file" / "p.csv", "Not a directory"}};
  if (::geteuid() != 0) {  // root writes anywhere
    fs::create_directory(dir.path() / "ro");
    fs::permissions(dir.path() / "ro", fs::perms::owner_read | fs::perms::owner_exec);
    cases.push_back({dir.path() / "ro" / "p.csv", "Permission denied"});
  }
  for (const Case& c : cases) {
    try {
      fp::write_file(c.path, fp::Format::csv, domain, disks);
      ADD_FAILURE() << "no error for " << c.path;
    } catch (const fp::IoError& e) {
      EXPECT_EQ(std::string(e.what()), "cannot write '" + c.path.string() + "': " + c.reason);
      EXPECT_EQ(e.path(), c.path.string());
    }
  }
  std::vector<std::string> expected = {"file"};
  if (::geteuid() != 0) {
    expected.emplace_back("ro");
    EXPECT_TRUE(fs::is_empty(dir.path() / "ro"));
  }
  EXPECT_EQ(dir.entries(), expected);
}

TEST(IoWriteFile, FailureInTheMiddleLeavesTheOldFileAndNoTemporary) {
  // A file size limit makes write() fail with EFBIG part-way through the file.
  const ScratchDir dir;
  const fp::Domain domain = l_shape();
  std::vector<fp::Disk> disks = real_packing(domain);
  for (int copies = 0; copies < 3; ++copies) {
    disks.insert(disks.end(), disks.begin(), disks.end());
  }
  ASSERT_GT(csv_text(disks).size(), 200000u);  // several times the writer's buffer
  const fs::path target = dir.path() / "p.csv";
  std::ofstream(target) << "old contents\n";
  rlimit old_limit{};
  ASSERT_EQ(::getrlimit(RLIMIT_FSIZE, &old_limit), 0);
  void (*old_handler)(int) = ::signal(SIGXFSZ, SIG_IGN);
  rlimit small = old_limit;
  small.rlim_cur = 4096;
  ASSERT_EQ(::setrlimit(RLIMIT_FSIZE, &small), 0);
  std::string message;
  try {
    fp::write_file(target, fp::Format::csv, domain, disks);
  } catch (const fp::IoError& e) {
    message = e.what();
  }
  ::setrlimit(RLIMIT_FSIZE, &old_limit);
  ::signal(SIGXFSZ, old_handler);
  EXPECT_EQ(message, "cannot write '" + target.string() + "': File too large");
  EXPECT_EQ(slurp(target), "old contents\n");
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"p.csv"});
}

TEST(IoWriteFile, WriterErrorLeavesNoFile) {
  const ScratchDir dir;
  const std::vector<fp::Disk> outside = {{{5, 5}, 1}};  // not in the domain's bounding box
  EXPECT_THROW(fp::write_file(dir.path() / "p.data", fp::Format::lammps, l_shape(), outside), fp::OptionError);
  EXPECT_TRUE(dir.entries().empty());
}

// One validation for every writer: a disk with a non-finite coordinate, or a radius that is not a
// finite number > 0, is refused before a byte is written, naming the disk's index and values, by
// the stream writers and write_file alike (the disk readers would refuse such a file).
TEST(IoWriteFile, EveryWriterRefusesADiskWithBadValues) {
  const ScratchDir dir;
  const fp::Domain domain = l_shape();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  const std::vector<std::pair<fp::Disk, std::string>> bad = {
      {{{0.5, 0.5}, -0.1}, "disk 1 (centre (0.5 0.5), radius -0.1)"},
      {{{0.5, 0.5}, 0.0}, "disk 1 (centre (0.5 0.5), radius 0)"},
      {{{0.5, 0.5}, inf}, "disk 1 (centre (0.5 0.5), radius inf)"},
      {{{0.5, 0.5}, nan}, "disk 1 (centre (0.5 0.5), radius nan)"},
      {{{nan, 0.5}, 0.1}, "disk 1 (centre (nan 0.5), radius 0.1)"},
      {{{0.5, -inf}, 0.1}, "disk 1 (centre (0.5 -inf), radius 0.1)"},
  };
  for (const auto& [disk, named] : bad) {
    const std::vector<fp::Disk> disks = {{{0.25, 0.25}, 0.1}, disk};
    for (const fp::Format f :
         {fp::Format::csv, fp::Format::yade, fp::Format::lammps, fp::Format::vtp, fp::Format::svg}) {
      std::ostringstream out;
      try {
        fp::write(out, f, domain, disks);
        ADD_FAILURE() << fp::to_string(f) << " wrote " << named;
      } catch (const fp::OptionError& e) {
        EXPECT_NE(std::string(e.what()).find(named), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("a finite"), std::string::npos) << e.what();
      }
      EXPECT_EQ(out.str(), "") << fp::to_string(f);
      EXPECT_THROW(fp::write_file(dir.path() / (std::string("p.") + fp::to_string(f)), f, domain, disks),
                   fp::OptionError);
      EXPECT_TRUE(dir.entries().empty()) << fp::to_string(f);
    }
  }
}

TEST(IoWriteFile, EveryFormatMatchesItsStreamWriter) {
  const ScratchDir dir;
  const fp::Domain domain = l_shape();
  const std::vector<fp::Disk> disks = real_packing(domain);
  for (const fp::Format f : {fp::Format::csv, fp::Format::yade, fp::Format::lammps, fp::Format::vtp, fp::Format::svg}) {
    const fs::path path = dir.path() / (std::string("p.") + fp::to_string(f));
    fp::write_file(path, f, domain, disks);
    std::ostringstream expected;
    switch (f) {
      case fp::Format::csv: fp::write_csv(expected, disks); break;
      case fp::Format::yade: fp::write_yade(expected, disks); break;
      case fp::Format::lammps: fp::write_lammps(expected, disks, domain.bbox()); break;
      case fp::Format::vtp: fp::write_vtp(expected, disks); break;
      case fp::Format::svg: fp::write_svg(expected, domain, disks); break;
    }
    EXPECT_EQ(slurp(path), expected.str()) << fp::to_string(f);
  }
}

// ---------------------------------------------------------------- LAMMPS

struct LammpsFile {
  std::string title;
  std::size_t atoms = 0;
  long types = 0;
  double box[3][2] = {};
  std::vector<std::vector<std::string>> rows;
};

LammpsFile parse_lammps(const std::string& text) {
  LammpsFile f;
  std::istringstream in(text);
  std::getline(in, f.title);
  bool in_atoms = false;
  for (std::string line; std::getline(in, line);) {
    const std::vector<std::string> w = words(line);
    if (w.empty()) {
      continue;
    }
    if (in_atoms) {
      f.rows.push_back(w);
    } else if (w.size() == 2 && w[1] == "atoms") {
      f.atoms = std::stoul(w[0]);
    } else if (w.size() == 3 && w[1] == "atom" && w[2] == "types") {
      f.types = std::stol(w[0]);
    } else if (w.size() == 4 && w[2].size() == 3 && w[2][0] >= 'x' && w[2][0] <= 'z' && w[2].substr(1) == "lo" &&
               w[3] == w[2].substr(0, 1) + "hi") {
      const auto k = static_cast<std::size_t>(w[2][0] - 'x');
      f.box[k][0] = parse_double(w[0]);
      f.box[k][1] = parse_double(w[1]);
    } else if (line == "Atoms # sphere") {
      in_atoms = true;
    } else {
      ADD_FAILURE() << "unexpected header line '" << line << "'";
    }
  }
  return f;
}

TEST(IoLammps, StructureAndExactValues) {
  const fp::Domain domain = l_shape();
  const std::vector<fp::Disk> disks = real_packing(domain);
  std::ostringstream out;
  fp::write_lammps(out, disks, domain.bbox());
  const LammpsFile f = parse_lammps(out.str());
  EXPECT_NE(f.title.find("frontpack"), std::string::npos);
  EXPECT_EQ(f.atoms, disks.size());
  EXPECT_EQ(f.types, 1);
  const fp::Box b = domain.bbox();
  EXPECT_EQ(f.box[0][0], b.xmin);
  EXPECT_EQ(f.box[0][1], b.xmax);
  EXPECT_EQ(f.box[1][0], b.ymin);
  EXPECT_EQ(f.box[1][1], b.ymax);
  EXPECT_LT(f.box[2][0], 0.0);  // 2D: the z range straddles 0
  EXPECT_GT(f.box[2][1], 0.0);
  ASSERT_EQ(f.rows.size(), disks.size());
  for (std::size_t i = 0; i < disks.size(); ++i) {
    const auto& w = f.rows[i];
    ASSERT_EQ(w.size(), 7u) << "row " << i;
    EXPECT_EQ(w[0], std::to_string(i + 1));
    EXPECT_EQ(w[1], "1");
    EXPECT_EQ(parse_double(w[2]) / 2, disks[i].radius);  // diameter, exactly 2 r
    EXPECT_EQ(parse_double(w[3]), 1.0);
    EXPECT_EQ(parse_double(w[4]), disks[i].centre.x);
    EXPECT_EQ(parse_double(w[5]), disks[i].centre.y);
    EXPECT_EQ(w[6], "0");
  }
}

TEST(IoLammps, OptionsAndBoxChecks) {
  const std::vector<fp::Disk> disks = {{{0.5, 0.4}, 0.4}, {{0.25, 0.75}, 0.125}};
  const fp::Box unit{0, 0, 1, 1};
  std::ostringstream out;
  fp::write_lammps(out, disks, unit, {2.5, 3});
  const LammpsFile f = parse_lammps(out.str());
  EXPECT_EQ(f.types, 3);
  EXPECT_EQ(f.box[2][0], -0.4);  // the largest radius
  EXPECT_EQ(f.box[2][1], 0.4);
  ASSERT_EQ(f.rows.size(), 2u);
  EXPECT_EQ(f.rows[1][1], "3");
  EXPECT_EQ(f.rows[1][2], "0.25");
  EXPECT_EQ(f.rows[1][3], "2.5");

  std::ostringstream sink;
  EXPECT_THROW(fp::write_lammps(sink, disks, unit, {0.0, 1}), fp::OptionError);
  EXPECT_THROW(fp::write_lammps(sink, disks, unit, {std::nan(""), 1}), fp::OptionError);
  EXPECT_THROW(fp::write_lammps(sink, disks, unit, {1.0, 0}), fp::OptionError);
  EXPECT_THROW(fp::write_lammps(sink, disks, fp::Box{}, {}), fp::OptionError);
  try {
    fp::write_lammps(sink, disks, fp::Box{0, 0, 1, 0.85}, {});  // disk 1 reaches y = 0.875
    ADD_FAILURE() << "no error";
  } catch (const fp::OptionError& e) {
    EXPECT_NE(std::string(e.what()).find("does not contain disk 1 (centre (0.25 0.75), radius 0.125)"),
              std::string::npos)
        << e.what();
  }
  // Touching the box is inside.
  EXPECT_NO_THROW(fp::write_lammps(sink, disks, fp::Box{0, 0, 1, 0.875}, {}));
  // No disks: a unit z range.
  std::ostringstream empty;
  fp::write_lammps(empty, {}, unit);
  const LammpsFile e = parse_lammps(empty.str());
  EXPECT_EQ(e.atoms, 0u);
  EXPECT_EQ(e.box[2][1], 0.5);
}

// ---------------------------------------------------------------- VTK

// The contents of the DataArray named `name` (or the Points array), as words.
std::vector<std::string> vtp_array(const std::string& xml, const std::string& name, std::string* attributes = nullptr) {
  const std::size_t at = xml.find("Name=\"" + name + "\"");
  EXPECT_NE(at, std::string::npos) << name;
  if (at == std::string::npos) {
    return {};
  }
  const std::size_t open = xml.rfind("<DataArray", at);
  const std::size_t start = xml.find('>', at) + 1;
  const std::size_t end = xml.find("</DataArray>", start);
  if (attributes != nullptr) {
    *attributes = xml.substr(open, start - open);
  }
  return words(xml.substr(start, end - start));
}

TEST(IoVtp, StructureAndExactValues) {
  const fp::Domain domain = l_shape();
  const std::vector<fp::Disk> disks = real_packing(domain);
  std::ostringstream out;
  fp::write_vtp(out, disks);
  const std::string xml = out.str();
  const std::string n = std::to_string(disks.size());
  EXPECT_NE(xml.find("<VTKFile type=\"PolyData\""), std::string::npos);
  EXPECT_NE(xml.find("NumberOfPoints=\"" + n + "\" NumberOfVerts=\"" + n + "\""), std::string::npos);
  EXPECT_NE(xml.find("<PointData Scalars=\"radius\">"), std::string::npos);
  std::string attributes;
  const auto radius = vtp_array(xml, "radius", &attributes);
  EXPECT_NE(attributes.find("type=\"Float64\""), std::string::npos);
  const auto id = vtp_array(xml, "id", &attributes);
  EXPECT_NE(attributes.find("type=\"Int64\""), std::string::npos);
  const auto points = vtp_array(xml, "Points", &attributes);
  EXPECT_NE(attributes.find("NumberOfComponents=\"3\""), std::string::npos);
  const auto connectivity = vtp_array(xml, "connectivity");
  const auto offsets = vtp_array(xml, "offsets");
  ASSERT_EQ(radius.size(), disks.size());
  ASSERT_EQ(id.size(), disks.size());
  ASSERT_EQ(points.size(), 3 * disks.size());
  ASSERT_EQ(connectivity.size(), disks.size());
  ASSERT_EQ(offsets.size(), disks.size());
  for (std::size_t i = 0; i < disks.size(); ++i) {
    EXPECT_EQ(parse_double(radius[i]), disks[i].radius);
    EXPECT_EQ(id[i], std::to_string(i));
    EXPECT_EQ(parse_double(points[3 * i]), disks[i].centre.x);
    EXPECT_EQ(parse_double(points[3 * i + 1]), disks[i].centre.y);
    EXPECT_EQ(points[3 * i + 2], "0");
    EXPECT_EQ(connectivity[i], std::to_string(i));
    EXPECT_EQ(offsets[i], std::to_string(i + 1));
  }
}

}  // namespace

// A line's text in a message is escaped: a NUL byte shows as \0, other control characters as
// \xNN (a terminal printing the message must not receive them raw), and cut to 40 characters.
TEST(IoRead, ControlCharactersInALineAreShownEscaped) {
  const auto what = [](const std::string& text, bool yade) {
    std::istringstream in(text);
    try {
      (void)(yade ? fp::read_yade(in, "d") : fp::read_csv(in, "d"));
    } catch (const fp::DiskFileError& e) {
      return std::string(e.what());
    }
    return std::string("(no DiskFileError)");
  };
  std::string nul = "x,y,r\n1,2";
  nul += '\0';
  nul += ",3\n";
  EXPECT_EQ(what(nul, false), "d:2:3: y '2\\0' is not a number");
  std::string nul_line = "x,y,r\n1,2";
  nul_line += '\0';
  nul_line += "3\n";
  EXPECT_EQ(what(nul_line, false), "d:2: expected 3 comma-separated numbers, got '1,2\\03'");
  EXPECT_EQ(what("0 0 0 1\x01\n", true), "d:1:7: radius '1\\x01' is not a number");
  EXPECT_EQ(what("#format x_y_z_r\n0 0 0 1\x1b[2J\n", true), "d:2:7: radius '1\\x1B[2J' is not a number");
  const std::string long_field(1000, '9');
  EXPECT_EQ(what("x,y,r\n1,2," + long_field + "x\n", false),
            "d:2:5: radius '" + std::string(40, '9') + "...' (1001 characters) is not a number");
  for (const std::string& m : {what(nul, false), what(nul_line, false), what("0 0 0 1\x01\n", true)}) {
    for (const char c : m) {
      EXPECT_GE(static_cast<unsigned char>(c), 0x20) << m;
    }
  }
}

// One rule for decimals out of the range of doubles, with the same words in every reader: WKT,
// disk files, radius specs and size tables (src/common/numbers.hpp, README "Numbers"). Subnormal numbers
// are kept: they round-trip through the writers (FormatsRoundTripEveryDouble).
TEST(Numbers, OneRuleAndOneWordingInEveryReader) {
  const auto what = [](const std::function<void()>& read) {
    try {
      read();
    } catch (const fp::Error& e) {
      return std::string(e.what());
    }
    return std::string("(no error)");
  };
  for (const auto& entry : {std::pair<std::string, std::string>{"1e-400", "(underflows to 0)"},
                            std::pair<std::string, std::string>{"1e400", "(overflows to infinity)"}}) {
    // Plain variables, not structured bindings: Clang 14 cannot capture those in the lambdas.
    const std::string& token = entry.first;
    const std::string& words = entry.second;
    const std::string phrase = "'" + token + "' is out of the range of a double " + words;
    const std::string messages[] = {
        what([&] { (void)fp::Domain::from_wkt("POLYGON((0 0,1 0,1 1," + token + " 1,0 0))"); }),
        what([&] {
          std::istringstream in("x,y,r\n0," + token + ",1\n");
          (void)fp::read_csv(in, "d.csv");
        }),
        what([&] {
          std::istringstream in("0 0 0 " + token + "\n");
          (void)fp::read_yade(in, "d.txt");
        }),
        what([&] { (void)fp::parse_radii("constant:" + token); }),
        what([&] { (void)fp::parse_radii("uniform:0.1," + token); }),
        what([&] { (void)fp::parse_radii("discrete:" + token + ":1"); }),
        what([&] { (void)fp::parse_radii("curve:1:0," + token + ":1"); }),
        what([&] { (void)fp::parse_size_table("diameter,passing\n1,0\n" + token + ",1\n", "sieve.csv"); }),
    };
    for (const std::string& m : messages) {
      EXPECT_NE(m.find(phrase), std::string::npos) << m;
    }
  }
  std::istringstream in("x,y,r\n1e-310,5e-324,2.5e-324\n");
  const std::vector<fp::Disk> d = fp::read_csv(in, "d.csv");
  ASSERT_EQ(d.size(), 1U);
  EXPECT_EQ(d[0].centre.x, 1e-310);
  EXPECT_EQ(d[0].centre.y, std::numeric_limits<double>::denorm_min());
  EXPECT_EQ(d[0].radius, std::numeric_limits<double>::denorm_min());
}
