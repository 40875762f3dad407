// Helpers shared by the tests.
#pragma once

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

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

}  // namespace frontpack::test
