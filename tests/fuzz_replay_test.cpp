// Replays every committed fuzz input (seed corpora and regressions) through its fuzz target in
// every build, so that a fixed crash stays fixed without Clang or libFuzzer (issue #7).
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "fuzz_targets.hpp"

namespace {

namespace fs = std::filesystem;

std::vector<fs::path> inputs(const std::string& kind, const std::string& target) {
  std::vector<fs::path> files;
  const fs::path dir = fs::path(FRONTPACK_FUZZ_DIR) / kind / target;
  if (fs::is_directory(dir)) {
    for (const auto& entry : fs::directory_iterator(dir)) {
      if (entry.is_regular_file() && entry.path().filename() != "README.md") {
        files.push_back(entry.path());
      }
    }
  }
  std::sort(files.begin(), files.end());
  return files;
}

std::vector<std::uint8_t> bytes(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

template <class Target>
std::size_t replay(const std::string& target, Target run) {
  std::size_t n = 0;
  for (const std::string kind : {"corpus", "regressions"}) {
    for (const fs::path& file : inputs(kind, target)) {
      SCOPED_TRACE(file.string());
      const std::vector<std::uint8_t> data = bytes(file);
      run(data.data(), data.size());  // aborts, with the broken guarantee named, on a failure
      ++n;
    }
  }
  return n;
}

TEST(FuzzReplay, WktCorpusAndRegressions) {
  EXPECT_GE(replay("wkt", frontpack::fuzz::wkt), 50U) << "the committed WKT corpus went missing";
}

TEST(FuzzReplay, FillCorpusAndRegressions) {
  EXPECT_GE(replay("fill", frontpack::fuzz::fill), 20U) << "the committed fill corpus went missing";
}

TEST(FuzzReplay, DiskFileCorpusAndRegressions) {
  EXPECT_GE(replay("disks", frontpack::fuzz::disks), 10U) << "the committed disk-file corpus went missing";
}

#if FRONTPACK_TEST_DXF
TEST(FuzzReplay, DxfCorpusAndRegressions) {
  EXPECT_GE(replay("dxf", frontpack::fuzz::dxf), 20U) << "the committed DXF corpus went missing";
}
#endif

}  // namespace
