// Text handed to a library that reads only by path (dxflib, GDAL): an anonymous memory file
// (memfd_create) holding exactly the text frontpack read and checked, so that the library sees
// what was checked and nothing else, whatever the input was (a file changed since, a FIFO, a
// device).
#pragma once

#include <string>
#include <string_view>

namespace frontpack::detail {

class MemoryFile {
 public:
  /// A memory file holding `text`. Throws IoError naming `source` (the input the text came from)
  /// and `reader` (who reads it: "dxflib") if the file cannot be made or written.
  MemoryFile(std::string_view text, const std::string& source, std::string_view reader);
  MemoryFile(const MemoryFile&) = delete;
  MemoryFile& operator=(const MemoryFile&) = delete;
  ~MemoryFile();

  /// The path that opens it (/proc/self/fd/N) while this object lives.
  [[nodiscard]] std::string path() const;

 private:
  int fd_ = -1;
};

}  // namespace frontpack::detail
