// Opening and reading input files, with the messages every reader gives (IoError naming the path
// and the operating system's reason).
#pragma once

#include <filesystem>
#include <fstream>
#include <string>

namespace frontpack::detail {

/// Opens `path` for reading in binary mode. Throws IoError for a directory or a file that
/// cannot be opened.
[[nodiscard]] std::ifstream open_for_reading(const std::filesystem::path& path);

/// The whole content of `path`. Throws IoError as open_for_reading, or if reading fails.
[[nodiscard]] std::string read_text_file(const std::filesystem::path& path);

}  // namespace frontpack::detail
