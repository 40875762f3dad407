#include "io/line_reader.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <system_error>

#include "common/numbers.hpp"
#include "common/read_file.hpp"
#include "common/text.hpp"

namespace frontpack::detail {

using Kind = DiskFileError::Kind;

LineReader::LineReader(std::istream& in, std::string_view source)
    : in_(in), source_(source.empty() ? "<input>" : source) {}

bool LineReader::next() {
  // std::getline, bounded: a line past kMaxLineBytes (/dev/zero, a binary file) is refused before
  // it is kept whole.
  line_.clear();
  std::streambuf* buffer = in_.rdbuf();
  bool any = false;
  for (;;) {
    const int c = buffer->sbumpc();
    if (c == std::char_traits<char>::eof()) {
      in_.setstate(std::ios::eofbit);
      break;
    }
    any = true;
    if (c == '\n') {
      break;
    }
    if (line_.size() == kMaxLineBytes) {
      throw_too_long(source_, kMaxLineBytes, "of a line of a disk file (line " + std::to_string(number_ + 1) + ")");
    }
    line_.push_back(static_cast<char>(c));
  }
  if (!any) {
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

void LineReader::fail(Kind kind, std::string detail, std::size_t column) const {
  throw DiskFileError(kind, std::move(detail), source_, number_ == 0 ? 1 : number_, column);
}

std::size_t LineReader::column_of(std::string_view field) const {
  return static_cast<std::size_t>(field.data() - line_.data()) + 1;
}

double LineReader::number_at(std::string_view field, const char* what) const {
  const std::size_t column = column_of(field);
  if (field.empty()) {
    fail(Kind::bad_number, std::string("expected a number for ") + what + ", got nothing", column);
  }
  const Decimal d = parse_decimal(field);
  if (d.status == DecimalStatus::overflow || d.status == DecimalStatus::underflow) {
    fail(Kind::bad_number, std::string(what) + " " + out_of_range(field, d.status), column);
  }
  if (d.status != DecimalStatus::ok) {
    fail(Kind::bad_number, std::string(what) + " " + quote_text(field) + " is not a number", column);
  }
  if (!std::isfinite(d.value)) {
    fail(Kind::non_finite, std::string(what) + " " + quote_text(field) + " is not finite", column);
  }
  return d.value;
}

std::int64_t LineReader::integer_at(std::string_view field, const char* what) const {
  std::int64_t value = 0;
  const auto [end, ec] = std::from_chars(field.data(), field.data() + field.size(), value);
  if (field.empty() || ec != std::errc{} || end != field.data() + field.size()) {
    fail(Kind::bad_number, std::string("expected a whole number for ") + what + ", got " + quote_text(field),
         column_of(field));
  }
  return value;
}

std::uint64_t LineReader::count_at(std::string_view field, const char* what, std::uint64_t max) const {
  std::uint64_t value = 0;
  const bool digits = !field.empty() && field.find_first_not_of("0123456789") == std::string_view::npos;
  const auto [end, ec] = std::from_chars(field.data(), field.data() + field.size(), value);
  if (!digits || ec != std::errc{} || end != field.data() + field.size() || value > max) {
    fail(Kind::bad_number,
         std::string("expected ") + what + " (a whole number from 0 to " + std::to_string(max) + "), got " +
             quote_text(field),
         column_of(field));
  }
  return value;
}

std::string_view strip_comment(std::string_view line) {
  return trim(line.substr(0, line.find('#')), is_space_or_tab);
}

Disk make_disk(const LineReader& lines, double x, double y, double r, std::string_view field) {
  if (!(r > 0)) {
    lines.fail(Kind::bad_radius, "radius must be > 0, got " + quote_text(field), lines.column_of(field));
  }
  return Disk{{x, y}, r};
}

std::vector<Disk> disks_by_id(std::vector<Atom> atoms, const std::string& source) {
  std::stable_sort(atoms.begin(), atoms.end(), [](const Atom& a, const Atom& b) { return a.id < b.id; });
  std::vector<Disk> disks;
  disks.reserve(atoms.size());
  for (std::size_t i = 0; i < atoms.size(); ++i) {
    if (i > 0 && atoms[i].id == atoms[i - 1].id) {
      const std::size_t first = std::min(atoms[i].line, atoms[i - 1].line);
      const std::size_t second = std::max(atoms[i].line, atoms[i - 1].line);
      throw DiskFileError(
          Kind::duplicate_id,
          "atom id " + std::to_string(atoms[i].id) + " given twice (also on line " + std::to_string(first) + ")",
          source, second);
    }
    disks.push_back(atoms[i].disk);
  }
  return disks;
}

}  // namespace frontpack::detail
