#include "common/memory_file.hpp"

#include <sys/mman.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "frontpack/errors.hpp"

namespace frontpack::detail {

MemoryFile::MemoryFile(std::string_view text, const std::string& source, std::string_view reader)
    : fd_(::memfd_create("frontpack-input", MFD_CLOEXEC)) {
  if (fd_ < 0) {
    throw IoError(
        "cannot make a memory file to read '" + source + "' with " + std::string(reader) + ": " + std::strerror(errno),
        source);
  }
  for (std::size_t done = 0; done < text.size();) {
    const ssize_t n = ::write(fd_, text.data() + done, text.size() - done);
    if (n < 0 && errno == EINTR) {
      continue;
    }
    if (n <= 0) {
      const int error = errno;
      ::close(fd_);
      throw IoError("cannot write a memory file to read '" + source + "' with " + std::string(reader) + ": " +
                        std::strerror(error),
                    source);
    }
    done += static_cast<std::size_t>(n);
  }
}

MemoryFile::~MemoryFile() {
  ::close(fd_);
}

std::string MemoryFile::path() const {
  return "/proc/self/fd/" + std::to_string(fd_);
}

}  // namespace frontpack::detail
