#include "common/read_file.hpp"

#include <cerrno>
#include <cstring>
#include <system_error>

#include "frontpack/errors.hpp"

namespace frontpack::detail {

namespace {

std::string source_name(std::string_view source) {
  return source.empty() ? std::string("<input>") : std::string(source);
}

// "1 GiB" for a power of two of at least 1 KiB, else the bytes.
std::string bytes_text(std::size_t bytes) {
  const char* units[] = {"KiB", "MiB", "GiB", "TiB"};
  std::size_t unit = 1024;
  for (const char* u : units) {
    if (bytes % unit == 0 && bytes / unit < 1024) {
      return std::to_string(bytes / unit) + ' ' + u;
    }
    unit *= 1024;
  }
  return std::to_string(bytes) + " bytes";
}

}  // namespace

void throw_too_long(std::string_view source, std::size_t max_bytes, std::string_view what) {
  const std::string name = source_name(source);
  throw IoError("cannot read '" + name + "': it is longer than " + bytes_text(max_bytes) +
                    ", the most frontpack reads " + std::string(what) + " (docs/robustness.md, \"Input sizes\")",
                name);
}

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

std::string read_bounded(std::istream& in, std::string_view source, std::size_t max_bytes) {
  std::string text;
  char buffer[1 << 16];
  // A device or a FIFO has no size to check first: each chunk is counted before it is kept.
  while (in.read(buffer, sizeof buffer) || in.gcount() > 0) {
    const auto got = static_cast<std::size_t>(in.gcount());
    if (got > max_bytes - text.size()) {
      throw_too_long(source, max_bytes, "of an input file");
    }
    text.append(buffer, got);
  }
  if (in.bad()) {
    const std::string name = source_name(source);
    throw IoError("cannot read '" + name + "'", name);
  }
  return text;
}

std::string read_text_file(const std::filesystem::path& path) {
  std::ifstream in = open_for_reading(path);
  std::error_code ec;
  // A regular file too large is refused without reading it.
  if (std::filesystem::is_regular_file(path, ec) && std::filesystem::file_size(path, ec) > kMaxInputBytes && !ec) {
    throw_too_long(path.string(), kMaxInputBytes, "of an input file");
  }
  return read_bounded(in, path.string());
}

}  // namespace frontpack::detail
