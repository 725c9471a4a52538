// Comparing two output directories file by file (the resumed and MPI runs against a clean
// threaded one) and reading a --stats JSON file.
#pragma once

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "test_files.hpp"

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

namespace pdd::test {

/// Expects the same file names with the same bytes in a and b, the manifest
/// (pdd-manifest.json) included unless `manifest` is false (the library's plain
/// piece_directory_sink writes none); returns the number of files that are the same.
inline std::size_t expect_same_files(const std::filesystem::path& a, const std::filesystem::path& b,
                                     const std::string& what, bool manifest = true) {
  std::vector<std::string> names = dir_entries(a);
  if (!manifest) std::erase(names, std::string("pdd-manifest.json"));
  EXPECT_EQ(names, dir_entries(b)) << what;
  std::size_t same = 0;
  for (const std::string& name : names) {
    const bool equal = read_text(a / name) == read_text(b / name);
    EXPECT_TRUE(equal) << what << ": " << name << " differs";
    same += equal;
  }
  return same;
}

/// The JSON document in file p (a --stats file, a manifest).
inline nlohmann::json read_json(const std::filesystem::path& p) {
  return nlohmann::json::parse(read_text(p));
}

} // namespace pdd::test
