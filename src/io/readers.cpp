// Readers of disk files: CSV and Yade text, strict, exact (std::from_chars), locale-independent.
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <istream>
#include <limits>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

#include "common/numbers.hpp"
#include "common/read_file.hpp"
#include "common/text.hpp"
#include "frontpack/io.hpp"
#include "io/line_reader.hpp"

namespace frontpack {

namespace {

using Kind = DiskFileError::Kind;

constexpr auto is_blank = detail::is_space_or_tab;

std::string_view trim(std::string_view s) {
  return detail::trim(s, is_blank);
}

// The offending text as quoted in a message: escaped (a NUL byte shows as \0) and shortened if
// long (common/numbers.hpp).
std::string quote(std::string_view s) {
  return detail::quote_text(s);
}

using Lines = detail::LineReader;

Disk make_disk(const Lines& lines, std::string_view x, std::string_view y, std::string_view r) {
  Disk d{{lines.number_at(x, "x"), lines.number_at(y, "y")}, lines.number_at(r, "radius")};
  if (!(d.radius > 0)) {
    lines.fail(Kind::bad_radius, "radius must be > 0, got " + quote(r), lines.column_of(r));
  }
  return d;
}

// Fields of a line split at `separator`, trimmed of spaces and tabs (views into the line).
std::vector<std::string_view> split(std::string_view line, char separator) {
  std::vector<std::string_view> fields = detail::split(line, separator);
  for (std::string_view& field : fields) {
    field = trim(field);
  }
  return fields;
}

using detail::tokens;

// A type: a whole number >= 1 (CSV) or a Yade matId >= 0 (then type = matId + 1), digits only.
std::uint32_t parse_type(const Lines& lines, std::string_view field, std::uint32_t base, const char* what) {
  std::uint32_t value = 0;
  const auto [end, ec] = std::from_chars(field.data(), field.data() + field.size(), value);
  const bool digits = !field.empty() && field.find_first_not_of("0123456789") == std::string_view::npos;
  if (!digits || ec != std::errc{} || end != field.data() + field.size() || value + base < 1 ||
      value == std::numeric_limits<std::uint32_t>::max()) {
    lines.fail(Kind::bad_number,
               std::string(what) + " " + quote(field) + " is not a whole number >= " + (base == 0 ? "1" : "0"),
               lines.column_of(field));
  }
  return value + base;
}

}  // namespace

std::vector<Disk> read_csv(std::istream& in, std::string_view source_name) {
  std::vector<std::uint32_t> types;
  return read_csv(in, source_name, types);
}

std::vector<Disk> read_yade(std::istream& in, std::string_view source_name) {
  std::vector<std::uint32_t> types;
  return read_yade(in, source_name, types);
}

std::vector<Disk> read_csv(std::istream& in, std::string_view source_name, std::vector<std::uint32_t>& types) {
  types.clear();
  Lines lines(in, source_name);
  if (!lines.next()) {
    lines.fail(Kind::empty_file, "empty file (expected the header line 'x,y,r')");
  }
  const std::vector<std::string_view> header = split(lines.text(), ',');
  const bool typed = header.size() == 4 && header[3] == "type";
  if ((header.size() != 3 && !typed) || header[0] != "x" || header[1] != "y" || header[2] != "r") {
    lines.fail(Kind::missing_header, "expected the header line 'x,y,r', got " + quote(lines.text()) +
                                         " (or 'x,y,r,type' with a type column)");
  }
  const std::size_t columns = typed ? 4 : 3;
  std::vector<Disk> disks;
  while (lines.next()) {
    if (trim(lines.text()).empty()) {
      lines.fail(Kind::blank_line, "blank line (a disk file has none)");
    }
    const std::vector<std::string_view> f = split(lines.text(), ',');
    if (f.size() != columns) {
      lines.fail(Kind::field_count,
                 "expected " + std::to_string(columns) + " comma-separated numbers, got " + quote(lines.text()));
    }
    disks.push_back(make_disk(lines, f[0], f[1], f[2]));
    if (typed) {
      types.push_back(parse_type(lines, f[3], 0, "type"));
    }
  }
  return disks;
}

std::vector<Disk> read_yade(std::istream& in, std::string_view source_name, std::vector<std::uint32_t>& types) {
  types.clear();
  bool typed = false;
  Lines lines(in, source_name);
  std::vector<Disk> disks;
  bool any = false;
  while (lines.next()) {
    any = true;
    const std::vector<std::string_view> t = tokens(lines.text());
    if (t.empty()) {
      lines.fail(Kind::blank_line, "blank line (Yade's ymport.textExt fails on it)");
    }
    if (t[0] == "#format") {
      if (t.size() < 2 || (t[1] != "x_y_z_r" && t[1] != "x_y_z_r_matId") ||
          (typed != (t[1] != "x_y_z_r") && !disks.empty())) {
        lines.fail(Kind::unsupported_format,
                   "unsupported " + quote(lines.text()) +
                       " (frontpack reads '#format x_y_z_r' and '#format x_y_z_r_matId', before the first disk)",
                   lines.column_of(t[0]));
      }
      typed = t[1] == "x_y_z_r_matId";
      continue;
    }
    if (t[0].front() == '#') {
      continue;  // a comment, as for textExt
    }
    if (t.size() != (typed ? 5U : 4U)) {
      lines.fail(Kind::field_count,
                 std::string(typed ? "expected 5 numbers 'x y z r matId'" : "expected 4 numbers 'x y z r'") +
                     " separated by spaces, got " + quote(lines.text()));
    }
    if (lines.number_at(t[2], "z") != 0) {
      lines.fail(Kind::nonzero_z, "z must be 0 (frontpack's disks are planar), got " + quote(t[2]),
                 lines.column_of(t[2]));
    }
    disks.push_back(make_disk(lines, t[0], t[1], t[3]));
    if (typed) {
      types.push_back(parse_type(lines, t[4], 1, "matId"));
    }
  }
  if (!any) {
    lines.fail(Kind::empty_file, "empty file (expected '#format x_y_z_r' and lines 'x y 0 r')");
  }
  return disks;
}

std::vector<Disk> read_disks(const std::filesystem::path& path) {
  return read_disks(path, disk_format_from_path(path));
}

}  // namespace frontpack
