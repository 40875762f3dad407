// Opening and reading input files, with the messages every reader gives (IoError naming the path
// and the operating system's reason), and the bounds on what an input may make the program read
// (docs/robustness.md, "Input sizes"): /dev/zero, a FIFO or a file of one endless line is refused
// at the bound rather than read until memory runs out.
#pragma once

#include <cstddef>
#include <filesystem>
#include <fstream>
#include <istream>
#include <string>
#include <string_view>

namespace frontpack::detail {

/// The most bytes of a file read whole (a WKT domain or region, a size table, a VTP file): 1 GiB,
/// about 25 million vertices of WKT or 15 million disks of VTP.
inline constexpr std::size_t kMaxInputBytes = std::size_t{1} << 30;
/// The longest line of a file read line by line (CSV, Yade, LAMMPS data and dump): 1 MiB; no line
/// of these formats is more than a few hundred bytes.
inline constexpr std::size_t kMaxLineBytes = std::size_t{1} << 20;

/// Opens `path` for reading in binary mode. Throws IoError for a directory or a file that
/// cannot be opened.
[[nodiscard]] std::ifstream open_for_reading(const std::filesystem::path& path);

/// The whole content of `in`, at most `max_bytes`: IoError naming `source` past that (without
/// reading further), or if reading fails.
[[nodiscard]] std::string read_bounded(std::istream& in, std::string_view source,
                                       std::size_t max_bytes = kMaxInputBytes);

/// The whole content of `path`, at most kMaxInputBytes. Throws IoError as open_for_reading and
/// read_bounded.
[[nodiscard]] std::string read_text_file(const std::filesystem::path& path);

/// IoError "cannot read 'SOURCE': it is longer than ..., the most frontpack reads of WHAT".
[[noreturn]] void throw_too_long(std::string_view source, std::size_t max_bytes, std::string_view what);

}  // namespace frontpack::detail
