// Outputs go where the user pointed and nothing else is touched (frontpack::OutputFile): symlinks
// followed, devices, FIFOs and descriptors written through, regular files replaced atomically
// with their permissions kept; same_regular_file's identity rules; and cancellation through a
// std::stop_token at every stage (fill, certify, measure, write), leaving no file behind.
#include <gtest/gtest.h>

#include <fcntl.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <stop_token>
#include <string>
#include <thread>
#include <vector>

#include "frontpack/frontpack.hpp"
#include "test_support.hpp"

namespace fp = frontpack;
namespace fs = std::filesystem;
using fp::test::ScratchDir;
using fp::test::slurp;

namespace {

fp::Domain square() {
  return fp::Domain::from_wkt("POLYGON((0 0,1 0,1 1,0 1,0 0))");
}

std::vector<fp::Disk> some_disks() {
  return {{{0.25, 0.25}, 0.125}, {{0.75, 0.75}, 0.25}};
}

std::string csv_of(const std::vector<fp::Disk>& disks) {
  std::ostringstream out;
  fp::write_csv(out, disks);
  return out.str();
}

std::stop_token stopped() {
  static std::stop_source source;
  source.request_stop();
  return source.get_token();
}

}  // namespace

TEST(OutputFile, SymlinkStaysALinkAndItsTargetGetsTheData) {
  const ScratchDir dir;
  std::ofstream(dir / "real.csv") << "old\n";
  fs::create_symlink("real.csv", dir / "link.csv");
  fp::write_file(dir / "link.csv", fp::Format::csv, square(), some_disks());
  EXPECT_TRUE(fs::is_symlink(dir / "link.csv"));
  EXPECT_EQ(fs::read_symlink(dir / "link.csv"), fs::path("real.csv"));
  EXPECT_EQ(slurp(dir / "real.csv"), csv_of(some_disks()));
  EXPECT_EQ(dir.entries(), (std::vector<std::string>{"link.csv", "real.csv"}));
}

TEST(OutputFile, DanglingSymlinkCreatesItsTarget) {
  const ScratchDir dir;
  fs::create_directory(dir / "sub");
  fs::create_symlink("sub/new.csv", dir / "link.csv");
  fp::write_file(dir / "link.csv", fp::Format::csv, square(), some_disks());
  EXPECT_TRUE(fs::is_symlink(dir / "link.csv"));
  EXPECT_EQ(slurp(dir / "sub" / "new.csv"), csv_of(some_disks()));
  EXPECT_EQ(dir.entries(), (std::vector<std::string>{"link.csv", "sub"}));
}

TEST(OutputFile, SymlinkLoopIsAnIoError) {
  const ScratchDir dir;
  fs::create_symlink("b", dir / "a");
  fs::create_symlink("a", dir / "b");
  try {
    fp::OutputFile out(dir / "a");
    ADD_FAILURE() << "no error for a symlink loop";
  } catch (const fp::IoError& e) {
    EXPECT_NE(std::string(e.what()).find("Too many levels of symbolic links"), std::string::npos) << e.what();
  }
}

TEST(OutputFile, ReplacementKeepsThePermissionsOfTheFileItReplaces) {
  const ScratchDir dir;
  std::ofstream(dir / "p.csv") << "old\n";
  fs::permissions(dir / "p.csv", fs::perms::owner_read | fs::perms::owner_write);
  fp::write_file(dir / "p.csv", fp::Format::csv, square(), some_disks());
  EXPECT_EQ(fs::status(dir / "p.csv").permissions() & fs::perms::all, fs::perms::owner_read | fs::perms::owner_write);
  EXPECT_EQ(slurp(dir / "p.csv"), csv_of(some_disks()));
}

TEST(OutputFile, FifoIsWrittenThroughNotReplaced) {
  const ScratchDir dir;
  const fs::path fifo = dir / "p.csv";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  std::string received;
  std::thread reader([&] { received = slurp(fifo); });
  fp::write_file(fifo, fp::Format::csv, square(), some_disks());
  reader.join();
  EXPECT_EQ(received, csv_of(some_disks()));
  EXPECT_TRUE(fs::is_fifo(fifo));
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"p.csv"});
}

TEST(OutputFile, DescriptorPathWritesToTheOpenDescriptor) {
  int fds[2];
  ASSERT_EQ(::pipe(fds), 0);
  {
    fp::OutputFile out("/dev/fd/" + std::to_string(fds[1]));
    EXPECT_FALSE(out.atomic());
    EXPECT_TRUE(out.temporary().empty());
    out.stream() << "through the pipe\n";
    out.commit();
  }
  ::close(fds[1]);
  char buf[64] = {};
  const ssize_t n = ::read(fds[0], buf, sizeof buf - 1);
  ::close(fds[0]);
  EXPECT_EQ(std::string(buf, n > 0 ? static_cast<std::size_t>(n) : 0), "through the pipe\n");
}

TEST(OutputFile, ClosedDescriptorIsAnIoError) {
  EXPECT_THROW(fp::OutputFile("/proc/self/fd/987654"), fp::IoError);
}

// Device files made in the test's own directory (mknod needs root): /dev/null's and /dev/full's
// numbers (1, 3) and (1, 7).
TEST(OutputFile, DevicesAreWrittenThroughAndAFullDeviceFails) {
  if (::geteuid() != 0) {
    GTEST_SKIP() << "mknod needs root";
  }
  const ScratchDir dir;
  ASSERT_EQ(::mknod((dir / "null").c_str(), S_IFCHR | 0666, makedev(1, 3)), 0);
  ASSERT_EQ(::mknod((dir / "full").c_str(), S_IFCHR | 0666, makedev(1, 7)), 0);
  fp::write_file(dir / "null", fp::Format::csv, square(), some_disks());
  EXPECT_TRUE(fs::is_character_file(dir / "null"));
  try {
    fp::write_file(dir / "full", fp::Format::csv, square(), some_disks());
    ADD_FAILURE() << "writing to a full device succeeded";
  } catch (const fp::IoError& e) {
    EXPECT_EQ(std::string(e.what()), "cannot write '" + (dir / "full").string() + "': No space left on device");
  }
  EXPECT_TRUE(fs::is_character_file(dir / "full"));
  EXPECT_EQ(dir.entries(), (std::vector<std::string>{"full", "null"}));
}

TEST(OutputFile, DiscardedOutputLeavesTheTargetAsItWas) {
  const ScratchDir dir;
  std::ofstream(dir / "p.csv") << "old\n";
  {
    fp::OutputFile out(dir / "p.csv");
    EXPECT_TRUE(out.atomic());
    EXPECT_EQ(out.temporary().parent_path(), dir.path());
    EXPECT_TRUE(fs::exists(out.temporary()));
    out.stream() << "new\n";
  }
  EXPECT_EQ(slurp(dir / "p.csv"), "old\n");
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"p.csv"});
}

TEST(OutputFile, DirectoryIsRefused) {
  const ScratchDir dir;
  try {
    fp::OutputFile out(dir.path());
    ADD_FAILURE() << "a directory was accepted";
  } catch (const fp::IoError& e) {
    EXPECT_NE(std::string(e.what()).find("it is a directory"), std::string::npos) << e.what();
  }
}

TEST(SameRegularFile, IdentityFollowsLinksAndNames) {
  const ScratchDir dir;
  std::ofstream(dir / "a.csv") << "a\n";
  std::ofstream(dir / "b.csv") << "b\n";
  fs::create_symlink("a.csv", dir / "link.csv");
  fs::create_hard_link(dir / "a.csv", dir / "hard.csv");
  EXPECT_TRUE(fp::same_regular_file(dir / "a.csv", dir / "a.csv"));
  EXPECT_TRUE(fp::same_regular_file(dir / "a.csv", dir / "link.csv"));
  EXPECT_TRUE(fp::same_regular_file(dir / "a.csv", dir / "hard.csv"));
  EXPECT_TRUE(fp::same_regular_file(dir / "a.csv", dir.path() / "." / "a.csv"));
  EXPECT_FALSE(fp::same_regular_file(dir / "a.csv", dir / "b.csv"));
  // Not yet existing: the same name once "." and ".." are resolved.
  EXPECT_TRUE(fp::same_regular_file(dir / "new.csv", dir.path() / "x" / ".." / "new.csv"));
  EXPECT_FALSE(fp::same_regular_file(dir / "new.csv", dir / "other.csv"));
  EXPECT_FALSE(fp::same_regular_file(dir / "new.csv", dir / "a.csv"));
  // Devices given twice are written through in order: not a clobbering pair.
  EXPECT_FALSE(fp::same_regular_file("/dev/null", "/dev/null"));
}

// ---------------------------------------------------------------- cancellation

TEST(Cancellation, WriteFileLeavesTheTargetAndNoTemporary) {
  const ScratchDir dir;
  std::ofstream(dir / "p.csv") << "old\n";
  std::vector<fp::Disk> many(20000, fp::Disk{{0.5, 0.5}, 0.1});
  fp::WriteOptions options;
  options.stop = stopped();
  for (const fp::Format f : {fp::Format::csv, fp::Format::yade, fp::Format::vtp, fp::Format::svg}) {
    EXPECT_THROW(fp::write_file(dir / "p.csv", f, square(), many, options), fp::CancelledError) << fp::to_string(f);
  }
  EXPECT_EQ(slurp(dir / "p.csv"), "old\n");
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"p.csv"});
}

TEST(Cancellation, FillCertifyAndMeasureThrow) {
  const fp::Domain domain = square();
  for (const fp::Method m : {fp::Method::closed, fp::Method::open, fp::Method::boundary}) {
    fp::FillOptions options;
    options.method = m;
    options.radii = fp::Radii::uniform(0.002, 0.004);
    options.stop = stopped();
    EXPECT_THROW((void)fp::fill(domain, options), fp::CancelledError) << fp::to_string(m);
  }
  const std::vector<fp::Disk> disks = some_disks();
  EXPECT_THROW((void)fp::certify(domain, disks, stopped()), fp::CancelledError);
  fp::StatsOptions stats;
  stats.stop = stopped();
  EXPECT_THROW((void)fp::measure(domain, disks, stats), fp::CancelledError);
}

// A stop requested from another thread while the fill runs ends it early, well before the run
// would end by itself, and a run whose token is never requested is the run without one.
TEST(Cancellation, StopFromAnotherThreadEndsARunningFill) {
  const fp::Domain domain = square();
  fp::FillOptions options;
  options.radii = fp::Radii::uniform(0.0005, 0.001);  // about 500,000 disks
  std::stop_source source;
  options.stop = source.get_token();
  std::size_t seen = 0;
  fp::Generator generator(domain, options);
  generator.on_progress([&](const fp::Progress& p) {
    seen = p.disks;
    if (p.disks >= 50000) {
      source.request_stop();
    }
    return true;
  });
  EXPECT_THROW((void)generator.run(), fp::CancelledError);
  EXPECT_LT(seen, 100000u);

  fp::FillOptions small;
  small.radii = fp::Radii::uniform(0.02, 0.04);
  small.seed = 5;
  std::stop_source unused;
  fp::FillOptions with_token = small;
  with_token.stop = unused.get_token();
  const fp::Packing a = fp::fill(domain, small);
  const fp::Packing b = fp::fill(domain, with_token);
  ASSERT_EQ(a.disks.size(), b.disks.size());
  EXPECT_EQ(csv_of(a.disks), csv_of(b.disks));
}
