// Helpers shared by the tests.
#pragma once

#include <gtest/gtest.h>

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <numbers>
#include <string>
#include <system_error>
#include <utility>
#include <vector>

#include "frontpack/frontpack.hpp"

namespace frontpack::test {

inline std::filesystem::path shapes_dir() {
  return FRONTPACK_SHAPES_DIR;
}
inline std::filesystem::path data_dir() {
  return FRONTPACK_TEST_DATA_DIR;
}

/// A fresh scratch directory per test, named for it, removed afterwards (permissions restored
/// first, so that a test may make a read-only directory in it).
class ScratchDir {
 public:
  ScratchDir() {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    path_ = std::filesystem::temp_directory_path() /
            ("frontpack_test_" + std::to_string(::getpid()) + "_" + info->test_suite_name() + "_" + info->name());
    std::filesystem::remove_all(path_);
    std::filesystem::create_directories(path_);
  }
  ~ScratchDir() {
    std::error_code ec;
    std::filesystem::permissions(path_, std::filesystem::perms::owner_all, std::filesystem::perm_options::add, ec);
    std::filesystem::remove_all(path_, ec);
  }
  ScratchDir(const ScratchDir&) = delete;
  ScratchDir& operator=(const ScratchDir&) = delete;
  [[nodiscard]] const std::filesystem::path& path() const { return path_; }
  [[nodiscard]] std::filesystem::path operator/(const char* name) const { return path_ / name; }
  /// The names in the directory, sorted: a temporary file left behind shows up here.
  [[nodiscard]] std::vector<std::string> entries() const {
    std::vector<std::string> names;
    for (const auto& e : std::filesystem::directory_iterator(path_)) {
      names.push_back(e.path().filename().string());
    }
    std::sort(names.begin(), names.end());
    return names;
  }

 private:
  std::filesystem::path path_;
};

/// A whole file's bytes.
inline std::string slurp(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

/// Every .wkt file in shapes/, sorted (the list is never empty: the caller asserts it).
inline std::vector<std::filesystem::path> shape_files() {
  std::vector<std::filesystem::path> files;
  for (const auto& entry : std::filesystem::directory_iterator(shapes_dir())) {
    if (entry.path().extension() == ".wkt") {
      files.push_back(entry.path());
    }
  }
  std::sort(files.begin(), files.end());
  return files;
}

/// fill() with this method, radii and seed, the other options at their defaults.
inline Packing fill(const Domain& d, Method m, Radii radii, std::uint64_t seed = 1) {
  FillOptions o;
  o.method = m;
  o.radii = std::move(radii);
  o.seed = seed;
  return frontpack::fill(d, o);
}

/// Total disk area over the domain's area.
/// Expects `run` (a fill) to throw NothingFitsError whose message contains `part`: a fill that
/// places no disk says why rather than returning an empty packing.
template <class Run>
void expect_nothing_fits(Run&& run, const std::string& part) {
  try {
    (void)run();
    ADD_FAILURE() << "no NothingFitsError; expected '" << part << "'";
  } catch (const NothingFitsError& e) {
    EXPECT_NE(std::string(e.what()).find(part), std::string::npos) << e.what();
  }
}

inline double fraction_of(const Domain& domain, const std::vector<Disk>& disks) {
  double a = 0;
  for (const Disk& d : disks) {
    a += std::numbers::pi * d.radius * d.radius;
  }
  return a / domain.area();
}

/// The packing fill() certified: decided exactly, nothing dropped, and an independent certify()
/// call on the disks finds no overlapping pair and no disk outside.
inline void expect_certified(const Domain& d, const Packing& p) {
  EXPECT_TRUE(p.certificate.exact);
  EXPECT_EQ(p.certificate.dropped, 0U) << "the generator itself produced an overlap";
  const CertifyReport again = certify(d, p.disks);
  EXPECT_TRUE(again.overlapping.empty()) << again.overlapping.size() << " overlapping pairs";
  EXPECT_TRUE(again.outside.empty()) << again.outside.size() << " disks outside";
}

/// A 100,000-vertex star-shaped ring: radius 10 with radial noise, which makes the boundary a saw
/// with teeth up to 0.12 deep and 0.0006 apart.
inline Domain hundred_thousand_vertex_ring() {
  std::vector<Point> ring;
  const int n = 100'000;
  for (int k = 0; k < n; ++k) {
    const double t = 2 * std::numbers::pi * k / n;
    const double rho = 10 + 0.3 * std::sin(37 * t) + 0.01 * ((k * 7919) % 13);
    ring.push_back({rho * std::cos(t), rho * std::sin(t)});
  }
  return Domain::from_rings(ring);
}

/// The file names of shapes/*.wkt, sorted: the parameters of the tests that run on every shape.
inline std::vector<std::string> shape_names() {
  std::vector<std::string> names;
  for (const auto& file : shape_files()) {
    names.push_back(file.filename().string());
  }
  return names;
}

/// The name of a per-shape test: the shape's file name without ".wkt".
struct ShapeTestName {
  template <class ParamInfo>
  std::string operator()(const ParamInfo& info) const {
    const std::string& name = info.param;
    return name.substr(0, name.find('.'));
  }
};

// Bit-for-bit equality of two disk lists (tells -0.0 from 0.0, unlike ==).
inline bool same_bits(const std::vector<Disk>& a, const std::vector<Disk>& b) {
  return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(Disk)) == 0);
}

// A packing of `domain` from the default method, radii uniform in [0.01, 0.05].
inline std::vector<Disk> real_packing(const Domain& domain, std::uint64_t seed) {
  FillOptions options;
  options.radii = Radii::uniform(0.01, 0.05);
  options.seed = seed;
  return frontpack::fill(domain, options).disks;
}

}  // namespace frontpack::test
