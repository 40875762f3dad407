// Every input read is bounded (docs/robustness.md, "Input sizes"): a file read whole stops at 1 GiB,
// a line of a disk file at 1 MiB, and an endless input (/dev/zero, a FIFO that never closes) is
// refused with an IoError naming it, not read until memory runs out.
#include <gtest/gtest.h>

#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "frontpack/frontpack.hpp"
#include "test_support.hpp"

namespace fp = frontpack;
namespace fs = std::filesystem;

namespace {

// Every reader of a file by its path, each given `path`.
std::vector<std::pair<std::string, std::function<void(const fs::path&)>>> readers() {
  return {
      {"WKT domain", [](const fs::path& p) { (void)fp::Domain::from_wkt_file(p); }},
      {"domain file", [](const fs::path& p) { (void)fp::read_domain_file(p, {.format = fp::DomainFormat::wkt}); }},
      {"region", [](const fs::path& p) { (void)fp::parse_type_rule("region:" + p.string()); }},
      {"size table", [](const fs::path& p) { (void)fp::read_size_table(p); }},
      // A size table is named *.csv in a radius spec: through a link of that name.
      {"curve",
       [](const fs::path& p) {
         const fs::path link = fs::temp_directory_path() / ("frontpack_sizes_" + std::to_string(::getpid()) + ".csv");
         fs::remove(link);
         fs::create_symlink(p, link);
         struct Unlink {
           fs::path path;
           ~Unlink() { fs::remove(path); }
         } unlink{link};
         try {
           (void)fp::parse_radii("curve:" + link.string());
         } catch (const fp::IoError& e) {
           // The message names the link; the path is the one the caller gave.
           EXPECT_EQ(e.path(), link.string());
           throw fp::IoError(e.what(), p.string());
         }
       }},
      {"csv", [](const fs::path& p) { (void)fp::read_disks(p, fp::DiskFormat::csv); }},
      {"yade", [](const fs::path& p) { (void)fp::read_disks(p, fp::DiskFormat::yade); }},
      {"lammps", [](const fs::path& p) { (void)fp::read_disks(p, fp::DiskFormat::lammps); }},
      {"lammps dump", [](const fs::path& p) { (void)fp::read_disks(p, fp::DiskFormat::lammps_dump); }},
      {"vtp", [](const fs::path& p) { (void)fp::read_disks(p, fp::DiskFormat::vtp); }},
  };
}

void expect_refused(const std::string& reader, const std::function<void(const fs::path&)>& read, const fs::path& path) {
  try {
    read(path);
    ADD_FAILURE() << reader << " read " << path << " to its end";
  } catch (const fp::IoError& e) {
    EXPECT_EQ(e.path(), path.string()) << reader;
    EXPECT_NE(std::string(e.what()).find("it is longer than 1 "), std::string::npos) << reader << ": " << e.what();
  } catch (const std::exception& e) {
    ADD_FAILURE() << reader << ": not an IoError: " << e.what();
  }
}

}  // namespace

TEST(InputBounds, DevZeroIsRefusedByEveryReader) {
  for (const auto& [name, read] : readers()) {
    expect_refused(name, read, "/dev/zero");
  }
}

// A FIFO whose writer never stops (a child process writing zeros until the reader closes it).
TEST(InputBounds, AnEndlessFifoIsRefusedByEveryReader) {
  const fp::test::ScratchDir dir;
  for (const auto& [name, read] : readers()) {
    const fs::path fifo = dir.path() / "endless";
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    const pid_t child = ::fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
      ::signal(SIGPIPE, SIG_DFL);
      const int fd = ::open(fifo.c_str(), O_WRONLY);
      static const char zeros[1 << 16] = {};
      while (fd >= 0 && ::write(fd, zeros, sizeof zeros) > 0) {
      }
      ::_exit(0);
    }
    expect_refused(name, read, fifo);
    ::kill(child, SIGKILL);  // were the FIFO never opened, the child would wait in open()
    int status = 0;
    ASSERT_EQ(::waitpid(child, &status, 0), child);
    fs::remove(fifo);
  }
}
