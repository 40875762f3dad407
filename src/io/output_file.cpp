// OutputFile: atomic replacement of regular files, write-through for everything else
// (include/frontpack/output_file.hpp states the rules).
#include "frontpack/output_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <charconv>
#include <cstring>
#include <optional>
#include <streambuf>
#include <string>
#include <string_view>
#include <system_error>
#include <utility>

#include "frontpack/errors.hpp"

namespace frontpack {

namespace {

[[noreturn]] void throw_io(const std::filesystem::path& path, int error, const char* what = "cannot write") {
  throw IoError(std::string(what) + " '" + path.string() + "': " + std::strerror(error != 0 ? error : EIO),
                path.string());
}

// An output stream buffer on a POSIX file descriptor that remembers the first write error's errno,
// so that the error message can give the OS's reason (std::ofstream loses it).
class FdBuf : public std::streambuf {
 public:
  FdBuf() { setp(buffer_, buffer_ + sizeof buffer_); }
  FdBuf(const FdBuf&) = delete;
  FdBuf& operator=(const FdBuf&) = delete;
  ~FdBuf() override = default;

  void set_fd(int fd) noexcept { fd_ = fd; }
  [[nodiscard]] int error() const noexcept { return error_; }
  bool flush_all() { return drain() && error_ == 0; }

 protected:
  int_type overflow(int_type ch) override {
    if (!drain()) {
      return traits_type::eof();
    }
    if (!traits_type::eq_int_type(ch, traits_type::eof())) {
      *pptr() = traits_type::to_char_type(ch);
      pbump(1);
    }
    return traits_type::not_eof(ch);
  }
  int sync() override { return drain() ? 0 : -1; }

 private:
  bool drain() {
    const char* p = pbase();
    while (p < pptr() && error_ == 0) {
      const ssize_t n = ::write(fd_, p, static_cast<std::size_t>(pptr() - p));
      if (n < 0) {
        if (errno != EINTR) {
          error_ = errno;
        }
      } else {
        p += n;
      }
    }
    setp(buffer_, buffer_ + sizeof buffer_);
    return error_ == 0;
  }

  int fd_ = -1;
  int error_ = 0;
  char buffer_[1 << 16];
};

// The descriptor a path names without naming a file: /dev/stdout, /dev/stderr, /dev/fd/N,
// /proc/self/fd/N.
std::optional<int> descriptor_path(const std::filesystem::path& path) {
  const std::string s = path.lexically_normal().string();
  if (s == "/dev/stdout") {
    return 1;
  }
  if (s == "/dev/stderr") {
    return 2;
  }
  for (const std::string_view prefix : {std::string_view("/dev/fd/"), std::string_view("/proc/self/fd/")}) {
    if (s.size() > prefix.size() && s.compare(0, prefix.size(), prefix) == 0) {
      int fd = -1;
      const char* first = s.data() + prefix.size();
      const char* last = s.data() + s.size();
      const auto [end, ec] = std::from_chars(first, last, fd);
      if (ec == std::errc() && end == last && fd >= 0) {
        return fd;
      }
    }
  }
  return std::nullopt;
}

// `path` with its symlinks followed to the final name (which may not exist yet). A relative link
// is relative to the directory of the link. Throws IoError on a loop (ELOOP after 40 links).
std::filesystem::path follow_links(const std::filesystem::path& path) {
  std::filesystem::path p = path;
  for (int hops = 0; hops < 40; ++hops) {
    std::error_code ec;
    if (!std::filesystem::is_symlink(std::filesystem::symlink_status(p, ec))) {
      return p;
    }
    const std::filesystem::path to = std::filesystem::read_symlink(p, ec);
    if (ec) {
      throw_io(path, ec.value());
    }
    p = to.is_absolute() ? to : p.parent_path() / to;
  }
  throw_io(path, ELOOP);
}

}  // namespace

struct OutputFile::State {
  std::filesystem::path path;       // as given
  std::filesystem::path target;     // where an atomic output is renamed to
  std::filesystem::path temporary;  // empty unless atomic and pending
  int fd = -1;
  bool atomic = false;
  bool committed = false;
  FdBuf buf;
  std::ostream stream{&buf};

  ~State() {
    if (fd >= 0) {
      ::close(fd);
    }
    if (!temporary.empty()) {
      ::unlink(temporary.c_str());
    }
  }
};

OutputFile::OutputFile(std::filesystem::path path) : state_(std::make_unique<State>()) {
  State& s = *state_;
  s.path = std::move(path);
  if (s.path.empty() || s.path.filename().empty()) {
    throw IoError("cannot write '" + s.path.string() + "': not a file name", s.path.string());
  }
  if (const std::optional<int> fd = descriptor_path(s.path)) {
    s.fd = ::fcntl(*fd, F_DUPFD_CLOEXEC, 3);
    if (s.fd < 0) {
      throw_io(s.path, errno);
    }
    s.buf.set_fd(s.fd);
    return;
  }
  s.target = follow_links(s.path);
  struct stat st {};
  const bool exists = ::stat(s.target.c_str(), &st) == 0;
  if (exists && S_ISDIR(st.st_mode)) {
    throw IoError("cannot write '" + s.path.string() + "': it is a directory", s.path.string());
  }
  if (exists && !S_ISREG(st.st_mode)) {
    // A device, FIFO or socket: written through. (Opening a FIFO waits for its reader.)
    s.fd = ::open(s.target.c_str(), O_WRONLY | O_CLOEXEC | O_NOCTTY);
    if (s.fd < 0) {
      throw_io(s.path, errno);
    }
    s.buf.set_fd(s.fd);
    return;
  }
  // A new file beside the target (same file system, so the rename is atomic), created exclusively.
  static std::atomic<unsigned> counter{0};
  for (int attempt = 0; s.fd < 0; ++attempt) {
    std::string name(1, '.');
    name.append(s.target.filename().string())
        .append(".frontpack-")
        .append(std::to_string(::getpid()))
        .append(1, '-')
        .append(std::to_string(counter.fetch_add(1)))
        .append(".tmp");
    std::filesystem::path tmp = s.target;
    tmp.replace_filename(name);
    s.fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (s.fd >= 0) {
      s.temporary = std::move(tmp);
    } else if (errno != EEXIST || attempt >= 100) {
      throw_io(s.path, errno);
    }
  }
  if (exists) {
    // The replacement keeps the permissions (and, where we may set it, the owner) of the file it
    // replaces; a failed fchown (not root) keeps ours, as any editor's save does.
    if (::fchmod(s.fd, st.st_mode & 07777) != 0) {
      throw_io(s.path, errno);
    }
    if (::fchown(s.fd, st.st_uid, st.st_gid) != 0) {
      errno = 0;
    }
  }
  s.atomic = true;
  s.buf.set_fd(s.fd);
}

OutputFile::OutputFile(OutputFile&&) noexcept = default;
OutputFile& OutputFile::operator=(OutputFile&&) noexcept = default;
OutputFile::~OutputFile() = default;

std::ostream& OutputFile::stream() {
  return state_->stream;
}

void OutputFile::commit() {
  State& s = *state_;
  if (s.committed || s.fd < 0) {
    throw IoError("cannot write '" + s.path.string() + "': already committed or discarded", s.path.string());
  }
  if (!s.buf.flush_all() || !s.stream) {
    throw_io(s.path, s.buf.error() != 0 ? s.buf.error() : EIO);
  }
  if (s.atomic) {
    // Durable before it becomes visible: a crash after the rename must not leave an empty file.
    if (::fsync(s.fd) != 0) {
      throw_io(s.path, errno);
    }
  }
  const int fd = std::exchange(s.fd, -1);
  if (::close(fd) != 0 && errno != EINTR) {
    throw_io(s.path, errno);
  }
  if (s.atomic) {
    if (::rename(s.temporary.c_str(), s.target.c_str()) != 0) {
      throw_io(s.path, errno);
    }
    s.temporary.clear();
  }
  s.committed = true;
}

void OutputFile::discard() noexcept {
  State& s = *state_;
  if (s.fd >= 0) {
    ::close(std::exchange(s.fd, -1));
  }
  if (!s.temporary.empty()) {
    ::unlink(s.temporary.c_str());
    s.temporary.clear();
  }
}

const std::filesystem::path& OutputFile::path() const noexcept {
  return state_->path;
}

bool OutputFile::atomic() const noexcept {
  return state_->atomic;
}

const std::filesystem::path& OutputFile::temporary() const noexcept {
  return state_->temporary;
}

bool same_regular_file(const std::filesystem::path& a, const std::filesystem::path& b) {
  struct stat sa {};
  struct stat sb {};
  const bool ea = ::stat(a.c_str(), &sa) == 0;
  const bool eb = ::stat(b.c_str(), &sb) == 0;
  if (ea && eb) {
    return S_ISREG(sa.st_mode) && sa.st_dev == sb.st_dev && sa.st_ino == sb.st_ino;
  }
  if (ea || eb) {
    return false;
  }
  // Neither exists yet: the same name once links and "." / ".." are resolved.
  std::error_code ec;
  const auto name = [&ec](const std::filesystem::path& p) {
    const std::filesystem::path target = follow_links(p);
    return std::filesystem::weakly_canonical(std::filesystem::absolute(target, ec), ec);
  };
  return name(a) == name(b);
}

}  // namespace frontpack
