// Line-by-line reading of a text disk file (LAMMPS data and dump files) with the messages every
// disk reader gives: DiskFileError naming the source, the line and the column.
#pragma once

#include <cstddef>
#include <cstdint>
#include <istream>
#include <string>
#include <string_view>
#include <vector>

#include "common/text.hpp"  // tokens()
#include "frontpack/errors.hpp"
#include "frontpack/geometry.hpp"

namespace frontpack::detail {

/// Reads lines, counting them, without their "\n" or "\r\n" and without a UTF-8 byte order mark at
/// the start of the input. Throws IoError if the stream fails other than at its end.
class LineReader {
 public:
  LineReader(std::istream& in, std::string_view source);

  /// The next line; false at the end of the input.
  bool next();
  [[nodiscard]] std::string_view text() const { return line_; }
  [[nodiscard]] std::size_t number() const { return number_; }
  [[nodiscard]] const std::string& source() const { return source_; }

  /// Throws DiskFileError at the current line (line 1 before the first), at `column` (0: none).
  [[noreturn]] void fail(DiskFileError::Kind kind, std::string detail, std::size_t column = 0) const;
  /// The 1-based column of `field`, a view into the current line.
  [[nodiscard]] std::size_t column_of(std::string_view field) const;

  /// One number, the whole field as std::from_chars reads it (common/numbers.hpp), finite;
  /// `what` names it in the message.
  [[nodiscard]] double number_at(std::string_view field, const char* what) const;
  /// A whole number (an optional '-' and digits) that fits an int64.
  [[nodiscard]] std::int64_t integer_at(std::string_view field, const char* what) const;
  /// A count: digits only, at most `max`.
  [[nodiscard]] std::uint64_t count_at(std::string_view field, const char* what, std::uint64_t max) const;

 private:
  std::istream& in_;
  std::string source_;
  std::string line_;
  std::size_t number_ = 0;
};

/// `line` without a '#' comment (LAMMPS: everything from the first '#'), trimmed of spaces and tabs.
[[nodiscard]] std::string_view strip_comment(std::string_view line);

/// The disk of centre (x, y) and radius r; throws DiskFileError bad_radius at `field` of the
/// current line unless r > 0.
[[nodiscard]] Disk make_disk(const LineReader& lines, double x, double y, double r, std::string_view field);

/// A LAMMPS atom as read: its id, its disk, and the line it was read from.
struct Atom {
  std::int64_t id = 0;
  Disk disk{};
  std::size_t line = 0;
};

/// The atoms' disks in ascending id order (LAMMPS writes atoms in the order its processors hold
/// them; the id is what names an atom). Throws DiskFileError duplicate_id naming both lines.
[[nodiscard]] std::vector<Disk> disks_by_id(std::vector<Atom> atoms, const std::string& source);

}  // namespace frontpack::detail
