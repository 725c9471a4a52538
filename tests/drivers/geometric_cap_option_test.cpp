// pdd-mesh --geometric-max-subdomains: the geometric path's cap reaches the loop (a tight cap
// makes no more subdomains than it allows, the default more), and bad values are refused.
#include "test_files.hpp"
#include "test_support.hpp"

#include <pdd/core/pslg.hpp>
#include <pdd/io/poly.hpp>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace geometric_cap_option_test {
namespace {

const std::string exe = std::string("'") + PDD_MESH_EXE + "' ";

/// The unit square with a 1e-4 notch in its bottom side: a feature far below the mesh.
std::string notched_square_file() {
  pdd::pslg g;
  g.add_loop(std::vector<pdd::point>{
      {0, 0}, {0.5, 0}, {0.5, 1e-4}, {0.5001, 1e-4}, {0.5001, 0}, {1, 0}, {1, 1}, {0, 1}});
  const auto path = pdd::test::temp_path("geometric_cap_notch.poly");
  pdd::write_poly(path, g);
  return path.string();
}

nlohmann::json stats_of(const std::string& options, const std::string& name) {
  const auto stats = pdd::test::temp_path(name);
  const auto r = pdd::test::run_command(exe + notched_square_file() +
                                        " --max-area 5e-6 --threads 1 -q --stats " +
                                        stats.string() + " " + options);
  EXPECT_EQ(r.code, 0) << r.output;
  std::ifstream in(stats);
  return nlohmann::json::parse(in);
}

} // namespace

TEST(PddMeshGeometricCap, TheCapReachesTheLoop) {
  const nlohmann::json tight = stats_of("--geometric-max-subdomains 64", "cap_tight.json");
  const nlohmann::json plain = stats_of("", "cap_default.json");
  // the tight cap: every refined round stops at 64 (the plan may then fall back to one)
  ASSERT_TRUE(tight.contains("estimated_over_refinement")) << tight.dump();
  EXPECT_LE(tight["subdomains"].get<std::size_t>(), 64u) << tight.dump();
  // the default (4096): the loop grades far more subdomains towards the notch
  EXPECT_GT(plain["subdomains"].get<std::size_t>(), 64u) << plain.dump();
  EXPECT_EQ(plain["path"], "geometric") << plain.dump();
}

TEST(PddMeshGeometricCap, BadCapsAreRefused) {
  for (const std::string bad : {"1", "0", "-5", "many"}) {
    const auto r = pdd::test::run_command(exe + notched_square_file() +
                                          " --max-area 5e-6 -q --geometric-max-subdomains " + bad);
    EXPECT_NE(r.code, 0) << bad;
    EXPECT_NE(r.output.find("--geometric-max-subdomains"), std::string::npos) << r.output;
  }
}

} // namespace geometric_cap_option_test
