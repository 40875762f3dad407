// Output files that appear whole or not at all: written to a temporary file beside the target,
// flushed to disk, then renamed over it in one step.
#pragma once

#include <cstdio>
#include <filesystem>

namespace frontpack_tool {

class AtomicFile {
 public:
  /// Creates the temporary file (".NAME.XXXXXX" in the target's directory). Throws
  /// frontpack::IoError naming the target and the OS's reason.
  explicit AtomicFile(std::filesystem::path target);
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;
  /// Removes the temporary file unless commit() succeeded.
  ~AtomicFile();

  [[nodiscard]] std::FILE* file() const noexcept { return file_; }
  /// Flushes, syncs, closes and renames the temporary file over the target. Throws IoError.
  void commit();

 private:
  [[noreturn]] void fail(const char* what, int err);

  std::filesystem::path target_;
  std::filesystem::path temp_;
  std::FILE* file_ = nullptr;
  bool committed_ = false;
};

}  // namespace frontpack_tool
