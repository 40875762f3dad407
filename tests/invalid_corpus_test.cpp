// The golden corpus of invalid domains: every file in tests/data/invalid/ must be rejected with
// exactly the error type, kind and message fragment that tests/data/invalid/expected.tsv gives.
//
// Each manifest row is its own test case (InvalidCorpus/Rejects.<file name>); the test
// InvalidCorpusManifest.MatchesTheCorpusDirectory checks that the manifest and the directory agree.
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cstddef>
#include <exception>
#include <filesystem>
#include <fstream>
#include <map>
#include <ostream>
#include <set>
#include <string>
#include <system_error>
#include <vector>

#include "frontpack/frontpack.hpp"
#include "test_support.hpp"

namespace fp = frontpack;

namespace {

constexpr const char* wkt_error_type = "WktError";
constexpr const char* invalid_domain_error_type = "InvalidDomainError";

/// One manifest row.
struct CorpusCase {
  std::string file;      ///< file name inside the corpus directory
  std::string type;      ///< "WktError" or "InvalidDomainError"
  std::string kind;      ///< to_string of the expected kind
  std::string fragment;  ///< must appear in what()
  std::size_t line = 0;  ///< line of the row in the manifest, for messages
};

// Shown in test failures and in --gtest_list_tests.
void PrintTo(const CorpusCase& c, std::ostream* os) {
  *os << c.file << " -> " << c.type << "/" << c.kind << " (expected.tsv line " << c.line << ")";
}

struct Manifest {
  bool opened = false;
  std::vector<CorpusCase> rows;
  std::vector<std::string> problems;  ///< malformed rows
};

std::filesystem::path corpus_dir() {
  return fp::test::data_dir() / "invalid";
}
std::filesystem::path manifest_path() {
  return corpus_dir() / "expected.tsv";
}

std::vector<std::string> split_tabs(const std::string& line) {
  std::vector<std::string> fields;
  std::size_t start = 0;
  while (true) {
    const std::size_t tab = line.find('\t', start);
    if (tab == std::string::npos) {
      fields.push_back(line.substr(start));
      return fields;
    }
    fields.push_back(line.substr(start, tab - start));
    start = tab + 1;
  }
}

bool is_blank(const std::string& s) {
  return std::all_of(s.begin(), s.end(), [](char c) { return std::isspace(static_cast<unsigned char>(c)) != 0; });
}

Manifest load_manifest() {
  Manifest m;
  std::ifstream in(manifest_path(), std::ios::binary);
  if (!in) {
    return m;
  }
  m.opened = true;
  std::string text;
  std::size_t number = 0;
  while (std::getline(in, text)) {
    ++number;
    if (!text.empty() && text.back() == '\r') {
      text.pop_back();
    }
    if (is_blank(text) || text.front() == '#') {
      continue;
    }
    const std::vector<std::string> fields = split_tabs(text);
    if (fields.size() != 4 || fields[0].empty() || fields[1].empty() || fields[2].empty() || fields[3].empty()) {
      m.problems.push_back("expected.tsv line " + std::to_string(number) +
                           ": expected 4 non-empty tab-separated fields (file, type, kind, fragment), got '" + text +
                           "'");
      continue;
    }
    m.rows.push_back(CorpusCase{fields[0], fields[1], fields[2], fields[3], number});
  }
  return m;
}

// Read once: the rows are needed at test registration (INSTANTIATE_TEST_SUITE_P) and again by
// the consistency test.
const Manifest& manifest() {
  static const Manifest m = load_manifest();
  return m;
}

// The .wkt files in the corpus directory, sorted; empty if the directory is missing.
std::vector<std::string> corpus_files() {
  std::vector<std::string> files;
  std::error_code ec;
  for (std::filesystem::directory_iterator it(corpus_dir(), ec), end; !ec && it != end; it.increment(ec)) {
    if (it->path().extension() == ".wkt") {
      files.push_back(it->path().filename().string());
    }
  }
  std::sort(files.begin(), files.end());
  return files;
}

// Every name to_string gives for a kind of error type E (the enumerators are 0, 1, 2, ...).
template <class E>
std::set<std::string> kind_names() {
  std::set<std::string> names;
  for (int i = 0; i < 64; ++i) {
    const std::string name = fp::to_string(static_cast<typename E::Kind>(i));
    if (name == "unknown") {
      break;
    }
    names.insert(name);
  }
  return names;
}

// A gtest name from a file name: "hole_outside.wkt" -> "hole_outside"; characters other than
// letters, digits and '_' become '_'. A name repeated by an earlier row gets the row's line.
std::string test_name(const ::testing::TestParamInfo<CorpusCase>& info) {
  const auto sanitize = [](const std::string& file) {
    std::string name = std::filesystem::path(file).stem().string();
    for (char& c : name) {
      if (std::isalnum(static_cast<unsigned char>(c)) == 0) {
        c = '_';
      }
    }
    return name.empty() ? std::string("unnamed") : name;
  };
  const std::string name = sanitize(info.param.file);
  const std::vector<CorpusCase>& rows = manifest().rows;
  const bool repeated =
      std::any_of(rows.begin(), rows.begin() + static_cast<std::ptrdiff_t>(std::min(info.index, rows.size())),
                  [&](const CorpusCase& row) { return sanitize(row.file) == name; });
  return repeated ? name + "_line" + std::to_string(info.param.line) : name;
}

bool contains(const std::string& text, const std::string& fragment) {
  return text.find(fragment) != std::string::npos;
}

// what() with the file's full path replaced by its bare name, so that the manifest's fragments
// do not depend on where the source tree is: "(/src/tests/data/invalid/a.wkt:line 1, column 3)"
// reads "(a.wkt:line 1, column 3)".
std::string relative_what(const std::exception& e, const std::filesystem::path& path, const std::string& file) {
  std::string what = e.what();
  const std::string full = path.string();
  for (std::size_t at = what.find(full); at != std::string::npos; at = what.find(full, at + file.size())) {
    what.replace(at, full.size(), file);
  }
  return what;
}

class InvalidCorpus : public ::testing::TestWithParam<CorpusCase> {};

TEST_P(InvalidCorpus, Rejects) {
  const CorpusCase& c = GetParam();
  const std::filesystem::path path = corpus_dir() / c.file;
  ASSERT_TRUE(std::filesystem::is_regular_file(path))
      << "expected.tsv line " << c.line << " names a missing file " << path;
  const std::string expected = c.type + "/" + c.kind;
  try {
    [[maybe_unused]] const fp::Domain domain = fp::Domain::from_wkt_file(path);
    ADD_FAILURE() << path << " was accepted; expected " << expected;
  } catch (const fp::WktError& e) {
    const std::string what = relative_what(e, path, c.file);
    EXPECT_EQ(c.type, wkt_error_type) << "expected " << expected << ", got WktError: " << what;
    EXPECT_EQ(c.kind, fp::to_string(e.kind())) << "what(): " << what;
    EXPECT_TRUE(contains(what, c.fragment))
        << "what() lacks the fragment\n  fragment: " << c.fragment << "\n  what():   " << what;
    EXPECT_EQ(e.source(), path.string()) << "what(): " << what;
    EXPECT_GE(e.line(), 1U) << "what(): " << what;
    EXPECT_GE(e.column(), 1U) << "what(): " << what;
  } catch (const fp::InvalidDomainError& e) {
    const std::string what = relative_what(e, path, c.file);
    EXPECT_EQ(c.type, invalid_domain_error_type) << "expected " << expected << ", got InvalidDomainError: " << what;
    EXPECT_EQ(c.kind, fp::to_string(e.kind())) << "what(): " << what;
    EXPECT_TRUE(contains(what, c.fragment))
        << "what() lacks the fragment\n  fragment: " << c.fragment << "\n  what():   " << what;
  } catch (const fp::Error& e) {
    ADD_FAILURE() << "expected " << expected << ", got another frontpack::Error: " << e.what();
  } catch (const std::exception& e) {
    ADD_FAILURE() << "expected " << expected << ", got a non-frontpack exception: " << e.what();
  }
}

INSTANTIATE_TEST_SUITE_P(InvalidCorpus, InvalidCorpus, ::testing::ValuesIn(manifest().rows), test_name);

TEST(InvalidCorpusManifest, MatchesTheCorpusDirectory) {
  const Manifest& m = manifest();
  ASSERT_TRUE(m.opened) << "cannot read the manifest " << manifest_path();
  for (const std::string& problem : m.problems) {
    ADD_FAILURE() << problem;
  }
  ASSERT_FALSE(m.rows.empty()) << "the manifest " << manifest_path() << " has no rows";

  const std::vector<std::string> files = corpus_files();
  ASSERT_FALSE(files.empty()) << "no .wkt file in " << corpus_dir();

  const std::set<std::string> wkt_kinds = kind_names<fp::WktError>();
  const std::set<std::string> domain_kinds = kind_names<fp::InvalidDomainError>();
  std::map<std::string, std::size_t> first_row;  // file -> manifest line
  for (const CorpusCase& row : m.rows) {
    const auto [it, inserted] = first_row.emplace(row.file, row.line);
    EXPECT_TRUE(inserted) << "expected.tsv line " << row.line << ": " << row.file << " already has a row at line "
                          << it->second;
    EXPECT_TRUE(std::filesystem::is_regular_file(corpus_dir() / row.file))
        << "expected.tsv line " << row.line << " names a missing file " << row.file;
    if (row.type == wkt_error_type) {
      EXPECT_EQ(wkt_kinds.count(row.kind), 1U)
          << "expected.tsv line " << row.line << ": '" << row.kind << "' is not a WktError kind";
    } else if (row.type == invalid_domain_error_type) {
      EXPECT_EQ(domain_kinds.count(row.kind), 1U)
          << "expected.tsv line " << row.line << ": '" << row.kind << "' is not an InvalidDomainError kind";
    } else {
      ADD_FAILURE() << "expected.tsv line " << row.line << ": unknown error type '" << row.type
                    << "' (WktError or InvalidDomainError)";
    }
  }
  for (const std::string& file : files) {
    EXPECT_EQ(first_row.count(file), 1U) << file << " has no row in expected.tsv";
  }
}

// Every kind of error that WKT input can produce has at least one corpus file.
TEST(InvalidCorpusManifest, CoversEveryKind) {
  // Kinds that only Domain::from_polygons can produce: the WKT reader rejects EMPTY, nan and inf
  // before validation.
  const std::set<std::string> not_from_wkt = {"empty", "non_finite_coordinate"};
  std::set<std::string> covered_wkt;
  std::set<std::string> covered_domain;
  for (const CorpusCase& row : manifest().rows) {
    (row.type == wkt_error_type ? covered_wkt : covered_domain).insert(row.kind);
  }
  for (const std::string& kind : kind_names<fp::WktError>()) {
    EXPECT_EQ(covered_wkt.count(kind), 1U) << "no corpus file for WktError/" << kind;
  }
  for (const std::string& kind : kind_names<fp::InvalidDomainError>()) {
    if (not_from_wkt.count(kind) == 0) {
      EXPECT_EQ(covered_domain.count(kind), 1U) << "no corpus file for InvalidDomainError/" << kind;
    }
  }
}

}  // namespace
