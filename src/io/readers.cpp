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

// Reads lines, counting them, without their "\n" or "\r\n" and without a UTF-8 byte order mark at
// the start of the file.
class Lines {
 public:
  Lines(std::istream& in, std::string_view source) : in_(in), source_(source.empty() ? "<input>" : source) {}

  bool next() {
    if (!std::getline(in_, line_)) {
      if (in_.bad()) {
        throw IoError("cannot read '" + source_ + "'", source_);
      }
      return false;
    }
    ++number_;
    if (!line_.empty() && line_.back() == '\r') {
      line_.pop_back();
    }
    if (number_ == 1 && line_.starts_with("\xEF\xBB\xBF")) {
      line_.erase(0, 3);
    }
    return true;
  }
  [[nodiscard]] std::string_view text() const { return line_; }
  [[nodiscard]] std::size_t number() const { return number_; }
  [[nodiscard]] const std::string& source() const { return source_; }

  [[noreturn]] void fail(Kind kind, std::string detail, std::size_t column = 0) const {
    throw DiskFileError(kind, std::move(detail), source_, number_ == 0 ? 1 : number_, column);
  }
  // Column (1-based) of a field that is a view into the current line.
  [[nodiscard]] std::size_t column_of(std::string_view field) const {
    return static_cast<std::size_t>(field.data() - line_.data()) + 1;
  }

 private:
  std::istream& in_;
  std::string source_;
  std::string line_;
  std::size_t number_ = 0;
};

// One number: the whole field, exactly as std::from_chars reads it, finite; out of the range of
// doubles (overflowing, or underflowing to 0) it is refused, as by every reader (common/numbers.hpp).
double parse_number(const Lines& lines, std::string_view field, const char* what) {
  const std::size_t column = lines.column_of(field);
  if (field.empty()) {
    lines.fail(Kind::bad_number, std::string("expected a number for ") + what + ", got nothing", column);
  }
  const detail::Decimal d = detail::parse_decimal(field);
  const double value = d.value;
  if (d.status == detail::DecimalStatus::overflow || d.status == detail::DecimalStatus::underflow) {
    lines.fail(Kind::bad_number, std::string(what) + " " + detail::out_of_range(field, d.status), column);
  }
  if (d.status != detail::DecimalStatus::ok) {
    lines.fail(Kind::bad_number, std::string(what) + " " + quote(field) + " is not a number", column);
  }
  if (!std::isfinite(value)) {
    lines.fail(Kind::non_finite, std::string(what) + " " + quote(field) + " is not finite", column);
  }
  return value;
}

Disk make_disk(const Lines& lines, std::string_view x, std::string_view y, std::string_view r) {
  Disk d{{parse_number(lines, x, "x"), parse_number(lines, y, "y")}, parse_number(lines, r, "radius")};
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
    if (parse_number(lines, t[2], "z") != 0) {
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
