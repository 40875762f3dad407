// The table of file formats (frontpack/formats.hpp): every name, extension and list the library
// and the tool use comes from it, so walking the table checks them all.
#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include "test_support.hpp"

namespace fp = frontpack;
namespace fs = std::filesystem;

namespace {

using fp::test::same_bits;

constexpr std::array kUses = {fp::FormatUse::library_writes, fp::FormatUse::disk_reader, fp::FormatUse::domain_reader,
                              fp::FormatUse::tool_writes, fp::FormatUse::tool_pictures};

std::string with_case(std::string_view s, bool up) {
  std::string out(s);
  for (char& c : out) {
    if (up && c >= 'a' && c <= 'z') {
      c = static_cast<char>(c - 'a' + 'A');
    } else if (!up && c >= 'A' && c <= 'Z') {
      c = static_cast<char>(c - 'A' + 'a');
    }
  }
  return out;
}

std::string message_of(auto&& call) {
  try {
    call();
  } catch (const fp::OptionError& e) {
    return e.what();
  }
  return "no OptionError";
}

TEST(FormatTable, RowsAreWellFormed) {
  std::set<std::string_view> names;
  for (const fp::FileFormat& f : fp::file_formats()) {
    EXPECT_TRUE(names.insert(f.name).second) << "two rows named " << f.name;
    EXPECT_FALSE(f.extensions.empty()) << f.name;
    for (const std::string_view ext : f.extensions) {
      EXPECT_TRUE(ext.size() > 1 && ext[0] == '.' && ext == with_case(ext, false)) << f.name << ": " << ext;
    }
    EXPECT_TRUE(f.written_as || f.read_as || f.domain_as || f.tool_writes) << f.name << " serves nothing";
    EXPECT_EQ(f.read_as.has_value() && f.holds != fp::FileKind::disks, false) << f.name;
    EXPECT_EQ(f.domain_as.has_value(), f.holds == fp::FileKind::domain) << f.name;
    // The tool writes a format by the library's writer or draws it as a picture.
    EXPECT_TRUE(!f.tool_writes || f.written_as || f.holds == fp::FileKind::picture) << f.name;
  }
}

// Every extension and every name (and alias), in any case, maps back to its row for every use the
// row serves; the enums' names are the rows' names.
TEST(FormatTable, EveryExtensionAndNameMapsBackToItsRow) {
  for (const fp::FileFormat& f : fp::file_formats()) {
    for (const fp::FormatUse use : kUses) {
      if (!fp::serves(f, use)) {
        EXPECT_NE(fp::find_format_by_name(f.name, use), &f) << f.name;
        continue;
      }
      for (const std::string_view ext : f.extensions) {
        for (const bool up : {false, true}) {
          std::string name("dir.x/file");
          const fs::path path = name.append(with_case(ext, up));
          EXPECT_EQ(fp::find_format_by_extension(path, use), &f) << f.name << " " << path;
          if (f.written_as && use == fp::FormatUse::library_writes) {
            EXPECT_EQ(fp::format_from_path(path), *f.written_as) << path;
          }
          if (f.read_as && use == fp::FormatUse::disk_reader) {
            EXPECT_EQ(fp::disk_format_from_path(path), *f.read_as) << path;
          }
          if (f.domain_as && use == fp::FormatUse::domain_reader) {
            EXPECT_EQ(fp::domain_format_of(path), *f.domain_as) << path;
          }
        }
      }
      EXPECT_EQ(fp::find_format_by_name(with_case(f.name, true), use), &f) << f.name;
      for (const std::string_view alias : f.aliases) {
        EXPECT_EQ(fp::find_format_by_name(alias, use), &f) << alias;
      }
    }
    if (f.written_as) {
      EXPECT_EQ(fp::to_string(*f.written_as), f.name);
      EXPECT_EQ(fp::format_from_name(f.name), *f.written_as);
    }
    if (f.read_as) {
      EXPECT_EQ(fp::to_string(*f.read_as), f.name);
      EXPECT_EQ(fp::disk_format_from_name(f.name), *f.read_as);
    }
    if (f.domain_as) {
      EXPECT_EQ(fp::to_string(*f.domain_as), f.name);
      EXPECT_EQ(fp::parse_domain_format(f.name), *f.domain_as);
    }
  }
}

// Every value of the three enums has its row (the enums list 5, 5 and 4 formats).
TEST(FormatTable, EveryEnumValueHasARow) {
  for (int k = 0; k < 5; ++k) {
    EXPECT_STRNE(fp::to_string(static_cast<fp::Format>(k)), "unknown") << k;
    EXPECT_STRNE(fp::to_string(static_cast<fp::DiskFormat>(k)), "unknown") << k;
  }
  for (int k = 1; k < 5; ++k) {
    EXPECT_STRNE(fp::to_string(static_cast<fp::DomainFormat>(k)), "unknown") << k;
  }
  EXPECT_STREQ(fp::to_string(fp::DomainFormat::automatic), "auto");
  EXPECT_STREQ(fp::to_string(static_cast<fp::Format>(99)), "unknown");
}

// The messages list what the table lists.
TEST(FormatTable, MessagesListTheTable) {
  EXPECT_EQ(fp::format_names(fp::FormatUse::library_writes), "csv, yade, lammps, vtp or svg");
  EXPECT_EQ(fp::format_names(fp::FormatUse::disk_reader), "csv, yade, lammps, lammps-dump or vtp");
  EXPECT_EQ(fp::format_names(fp::FormatUse::domain_reader), "wkt, dxf, geojson or shapefile");
  EXPECT_EQ(fp::format_names(fp::FormatUse::tool_writes), "csv, yade, lammps, vtp, png, svg or pdf");
  EXPECT_EQ(fp::format_extensions(fp::FormatUse::tool_pictures), ".png, .svg or .pdf");
  EXPECT_EQ(fp::format_extensions(fp::FormatUse::disk_reader),
            ".csv, .txt or .yade (Yade), .data or .lmp (LAMMPS data), .dump or .lammpstrj (LAMMPS dump) or "
            ".vtp (ParaView)");
  const std::string writes = fp::format_extensions(fp::FormatUse::library_writes);
  EXPECT_NE(message_of([] { (void)fp::format_from_path("a.xyz"); }).find("unknown format '.xyz'; use " + writes),
            std::string::npos);
  EXPECT_NE(
      message_of([] { (void)fp::format_from_path("a.pdf"); }).find("PDF pictures are drawn by the frontpack tool"),
      std::string::npos);
  EXPECT_NE(message_of([] {
              (void)fp::disk_format_from_name("xyz");
            }).find("expected " + fp::format_names(fp::FormatUse::disk_reader)),
            std::string::npos);
  EXPECT_NE(message_of([] {
              (void)fp::parse_domain_format("svg");
            }).find("expected auto, " + fp::format_names(fp::FormatUse::domain_reader)),
            std::string::npos);
  EXPECT_EQ(fp::parse_domain_format("AUTO"), fp::DomainFormat::automatic);
  EXPECT_EQ(fp::domain_format_of("plate.anything"), fp::DomainFormat::wkt);
  EXPECT_EQ(fp::domain_format_of("plate"), fp::DomainFormat::wkt);
  EXPECT_EQ(fp::find_format_by_extension("noextension", fp::FormatUse::disk_reader), nullptr);
}

// Every format the library both writes and reads round-trips by every one of its extensions:
// write_file and read_disks choose the same row, and the reader gets back the very bits.
TEST(FormatTable, EveryWritableDiskFormatRoundTripsByItsExtensions) {
  const fp::test::ScratchDir dir;
  const fp::Domain domain = fp::Domain::from_wkt_file(fp::test::shapes_dir() / "l_shape.wkt");
  const std::vector<fp::Disk> disks = fp::test::real_packing(domain, 7);
  ASSERT_GT(disks.size(), 10u);
  int rows = 0;
  for (const fp::FileFormat& f : fp::file_formats()) {
    if (!f.written_as || f.holds != fp::FileKind::disks) {
      continue;
    }
    ASSERT_TRUE(f.read_as) << f.name << " is written and cannot be read back";
    ++rows;
    for (const std::string_view ext : f.extensions) {
      std::string name("p");
      const fs::path path = dir.path() / name.append(ext);
      fp::write_file(path, fp::format_from_path(path), domain, disks);
      EXPECT_TRUE(same_bits(fp::read_disks(path), disks)) << path;
    }
  }
  EXPECT_EQ(rows, 4);
}

#ifdef FRONTPACK_TOOL
// `s` in single quotes for the shell (built by append: GCC 12 warns, -Wrestrict, on "'" + string).
std::string shell_quoted(std::string_view s) {
  std::string out(1, '\'');
  out.append(s).append(1, '\'');
  return out;
}

// The tool's output of a command (stdout and stderr).
std::string run_tool(const std::string& args) {
  std::string command = shell_quoted(FRONTPACK_TOOL);
  command.append(" ").append(args).append(" 2>&1");
  std::unique_ptr<FILE, int (*)(FILE*)> pipe(::popen(command.c_str(), "r"), ::pclose);
  std::string out;
  char buf[4096];
  while (pipe && std::fgets(buf, sizeof buf, pipe.get()) != nullptr) {
    out += buf;
  }
  return out;
}

// The help of an option: from its name to the next option's (CLI11 may put the text on the next
// line).
std::string help_of(const std::string& help, const std::string& option) {
  std::string key("\n  ");
  const std::size_t at = help.find(key.append(option).append(" "));
  return at == std::string::npos ? std::string() : help.substr(at, help.find("\n  -", at + 1) - at);
}

// The tool's --format help names every format the tool writes, and its -o help every extension.
TEST(FormatTable, ToolHelpNamesEveryToolFormat) {
  for (const bool pictures : {false, true}) {
    const std::string help = run_tool(pictures ? "render --help" : "fill --help");
    const std::string format = help_of(help, "--format");
    const std::string output = help_of(help, "-o,--output");
    ASSERT_FALSE(format.empty()) << help;
    ASSERT_FALSE(output.empty()) << help;
    int named = 0;
    for (const fp::FileFormat& f : fp::file_formats()) {
      if (!fp::serves(f, pictures ? fp::FormatUse::tool_pictures : fp::FormatUse::tool_writes)) {
        std::string word(" ");
        EXPECT_EQ(format.find(word.append(f.name).append(",")), std::string::npos) << f.name << ": " << format;
        continue;
      }
      ++named;
      EXPECT_NE(format.find(std::string(f.name)), std::string::npos) << f.name << ": " << format;
      for (const std::string_view ext : f.extensions) {
        EXPECT_NE(output.find(std::string(ext)), std::string::npos) << ext << ": " << output;
      }
    }
    EXPECT_GE(named, 3);
  }
}

// The tool writes every format it names, chosen by each extension, in one run.
TEST(FormatTable, ToolWritesEveryToolFormatByExtension) {
  const fp::test::ScratchDir dir;
  std::string args = "fill ";
  args.append(shell_quoted((fp::test::shapes_dir() / "unit_square.wkt").string())).append(" --radius constant:0.1");
  std::vector<fs::path> paths;
  for (const fp::FileFormat& f : fp::file_formats()) {
    if (f.tool_writes) {
      for (const std::string_view ext : f.extensions) {
        std::string name(f.name);
        paths.push_back(dir.path() / name.append(ext));
        args.append(" -o ").append(shell_quoted(paths.back().string()));
      }
    }
  }
  const std::string out = run_tool(args);
  for (const fs::path& p : paths) {
    EXPECT_TRUE(fs::is_regular_file(p) && fs::file_size(p) > 0) << p << "\n" << out;
  }
}
#endif

}  // namespace
