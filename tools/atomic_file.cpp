#include "atomic_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <string>
#include <utility>
#include <vector>

#include "frontpack/errors.hpp"

namespace frontpack_tool {

AtomicFile::AtomicFile(std::filesystem::path target) : target_(std::move(target)) {
  std::filesystem::path dir = target_.parent_path();
  if (dir.empty()) {
    dir = ".";
  }
  // A hidden name in the same directory: rename() is atomic only within one file system.
  std::string hidden(".");
  hidden.append(target_.filename().string()).append(".XXXXXX");
  const std::string pattern = (dir / hidden).string();
  std::vector<char> name(pattern.begin(), pattern.end());
  name.push_back('\0');
  const int fd = ::mkstemp(name.data());
  if (fd < 0) {
    fail("cannot create a file in the directory of", errno);
  }
  temp_ = name.data();
  ::fchmod(fd, 0644);  // mkstemp's 0600 would surprise: a normal output file is world-readable
  file_ = ::fdopen(fd, "wb");
  if (file_ == nullptr) {
    const int err = errno;
    ::close(fd);
    fail("cannot write", err);
  }
}

AtomicFile::~AtomicFile() {
  if (file_ != nullptr) {
    std::fclose(file_);
  }
  if (!committed_ && !temp_.empty()) {
    std::error_code ignored;
    std::filesystem::remove(temp_, ignored);
  }
}

void AtomicFile::commit() {
  if (std::fflush(file_) != 0 || std::ferror(file_) != 0) {
    fail("cannot write", errno);
  }
  if (::fsync(::fileno(file_)) != 0) {
    fail("cannot write", errno);
  }
  std::FILE* f = std::exchange(file_, nullptr);
  if (std::fclose(f) != 0) {
    fail("cannot write", errno);
  }
  if (std::rename(temp_.c_str(), target_.c_str()) != 0) {
    fail("cannot write", errno);
  }
  committed_ = true;
}

void AtomicFile::fail(const char* what, int err) {
  std::string message(what);
  message.append(" '").append(target_.string()).append("': ").append(std::strerror(err != 0 ? err : EIO));
  throw frontpack::IoError(message, target_.string());
}

}  // namespace frontpack_tool
