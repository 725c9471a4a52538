// Helpers shared by pdd's tests: paths to data, temporary files, shared/ geometry discovery.
#pragma once

#include <gtest/gtest.h>

#include <unistd.h>

#include <pdd/core/pslg.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numbers>
#include <string>
#include <vector>

namespace pdd::test {

/// The repository's bundled data folder (examples/data).
inline std::filesystem::path bundled_data(const std::string& name) {
  return std::filesystem::path(PDD_SOURCE_DIR) / "examples" / "data" / name;
}

/// ../shared/data beside the repository; empty when absent (tests then GTEST_SKIP).
inline std::filesystem::path shared_data_dir() {
  std::filesystem::path p(PDD_SHARED_DATA_DIR);
  std::error_code ec;
  return std::filesystem::is_directory(p, ec) ? p : std::filesystem::path{};
}

/// All .poly files in ../shared/data, sorted; empty when absent.
inline std::vector<std::filesystem::path> shared_poly_files() {
  std::vector<std::filesystem::path> out;
  const auto dir = shared_data_dir();
  if (dir.empty()) return out;
  for (const auto& e : std::filesystem::directory_iterator(dir))
    if (e.path().extension() == ".poly") out.push_back(e.path());
  std::sort(out.begin(), out.end());
  return out;
}

/// A fresh path in the tests' temporary folder (the file is not created): named after the running
/// test, or, outside a test (a namespace-scope file), after the process, since ctest runs every
/// test of a binary in its own process at once and they would otherwise rewrite one file while
/// another reads it.
inline std::filesystem::path temp_path(const std::string& name) {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  std::string prefix = info ? std::string(info->test_suite_name()) + "_" + info->name()
                            : "process" + std::to_string(::getpid());
  for (char& c : prefix)
    if (c == '/') c = '_';
  return std::filesystem::path(PDD_TEST_TMP_DIR) / (prefix + "_" + name);
}

/// A star polygon: `spikes` tips at radius 1 and as many notches at radius `inner`, the first
/// tip on the positive x axis (tip angles 2 atan(...) well below 60 deg for many spikes).
inline pslg star_polygon(int spikes, double inner) {
  pslg g;
  std::vector<point> p;
  for (int i = 0; i < 2 * spikes; ++i) {
    const double r = i % 2 == 0 ? 1.0 : inner, a = i * std::numbers::pi / spikes;
    p.push_back({r * std::cos(a), r * std::sin(a)});
  }
  g.add_loop(p, 1);
  return g;
}

} // namespace pdd::test
