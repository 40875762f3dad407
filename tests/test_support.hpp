// Helpers shared by the tests.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <string>
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

/// The packing fill() certified: decided exactly, nothing dropped, and an independent certify()
/// call on the disks finds no overlapping pair and no disk outside.
inline void expect_certified(const Domain& d, const Packing& p) {
  EXPECT_TRUE(p.certificate.exact);
  EXPECT_EQ(p.certificate.dropped, 0U) << "the generator itself produced an overlap";
  const CertifyReport again = certify(d, p.disks);
  EXPECT_TRUE(again.overlapping.empty()) << again.overlapping.size() << " overlapping pairs";
  EXPECT_TRUE(again.outside.empty()) << again.outside.size() << " disks outside";
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

}  // namespace frontpack::test
