#include "common/read_file.hpp"

#include <cerrno>
#include <cstring>
#include <iterator>
#include <system_error>

#include "frontpack/errors.hpp"

namespace frontpack::detail {

std::ifstream open_for_reading(const std::filesystem::path& path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) {
    throw IoError("cannot read '" + path.string() + "': it is a directory", path.string());
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    throw IoError("cannot open '" + path.string() + "': " + std::strerror(errno), path.string());
  }
  return in;
}

std::string read_text_file(const std::filesystem::path& path) {
  std::ifstream in = open_for_reading(path);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (in.bad()) {
    throw IoError("cannot read '" + path.string() + "'", path.string());
  }
  return text;
}

}  // namespace frontpack::detail
