// pdd-mesh with sizing fields: --sizing, --background, --area-grid, the .poly regions, their
// errors and the --stats fields sizing and gradation.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "test_files.hpp"
#include "test_support.hpp"

#include <sys/wait.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

namespace sizing_options_test {
namespace {

using run_result = pdd::test::command_result;

run_result run_mesh(const std::string& args) {
  const std::string cmd = std::string("'") + PDD_MESH_EXE + "' " + args;
  return pdd::test::run_command(cmd);
}

std::string write_text(const std::string& name, const std::string& text) {
  const auto p = pdd::test::temp_path(name);
  std::ofstream(p) << text;
  return p.string();
}

nlohmann::json stats_of(const std::string& args) {
  const auto stats = pdd::test::temp_path("s.json");
  const run_result r = run_mesh(args + " --verify -q --stats " + stats.string());
  EXPECT_EQ(r.code, 0) << r.output;
  std::ifstream in(stats);
  return nlohmann::json::parse(in);
}

const std::string square_region = "4 2 0 0\n1 0 0\n2 1 0\n3 1 1\n4 0 1\n4 0\n1 1 2\n2 2 3\n"
                                  "3 3 4\n4 4 1\n0\n1\n1 0.5 0.5 0 1e-4\n";

TEST(PddMeshSizing, PolyRegionsAreUsed) {
  // Triangle 1.6 -pq20.7Aa: 15602 triangles (was 2 while regions were ignored)
  const auto poly = write_text("sq.poly", square_region);
  for (const char* n : {"1", "4"}) {
    const nlohmann::json j = stats_of(poly + " --subdomains " + n);
    EXPECT_EQ(j["sizing"], "regional");
    EXPECT_DOUBLE_EQ(j["gradation"].get<double>(), 1.0);
    EXPECT_GT(j["triangles"].get<double>(), 0.96 * 15602) << n;
    EXPECT_LT(j["triangles"].get<double>(), 1.06 * 15602) << n;
    EXPECT_EQ(j["conforming"], true);
    EXPECT_LE(j["max_area_ratio"].get<double>(), 1.0);
  }
  // with --max-area the smaller bound holds
  const nlohmann::json j = stats_of(poly + " --max-area 5e-5 --subdomains 1");
  EXPECT_EQ(j["sizing"], "min(regional, uniform)");
  EXPECT_GT(j["triangles"].get<double>(), 1.9 * 15602 * 0.96);
}

TEST(PddMeshSizing, ExpressionGridAndBackground) {
  const std::string square =
      write_text("sq.poly", square_region.substr(0, square_region.find("1\n1 0.5")) + "0\n");
  nlohmann::json j = stats_of(square + " --sizing \"1e-3*(1+9*x)\" --subdomains 4 --threads 2");
  EXPECT_EQ(j["sizing"], "expression");
  EXPECT_NEAR(j["gradation"].get<double>(), 10.0, 0.5); // max F / min F over the box
  EXPECT_EQ(j["interface_splits"], 0);
  const auto grid = write_text("g.txt", "2 2 0 0 1 1\n1e-3 1e-2\n1e-3 1e-2\n");
  j = stats_of(square + " --area-grid " + grid + " --subdomains 1");
  EXPECT_EQ(j["sizing"], "grid");
  EXPECT_DOUBLE_EQ(j["gradation"].get<double>(), 10.0);
  const auto node =
      write_text("bg.node", "4 2 1 0\n1 0 0 1e-3\n2 1 0 1e-2\n3 1 1 1e-2\n4 0 1 1e-3\n");
  const auto stem = node.substr(0, node.size() - 5);
  std::ofstream(stem + ".ele") << "2 3 0\n1 1 2 3\n2 1 3 4\n";
  j = stats_of(square + " --background " + node + " --subdomains 1");
  EXPECT_EQ(j["sizing"], "background_mesh");
  EXPECT_DOUBLE_EQ(j["gradation"].get<double>(), 10.0);
}

TEST(PddMeshSizing, ErrorsNameColumnLineOrRegion) {
  const auto poly = write_text("sq.poly", square_region);
  run_result r = run_mesh(poly + " --sizing \"1e-4*(1+z)\"");
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.output.find("column 9"), std::string::npos) << r.output; // the z
  const auto grid = write_text("g.txt", "2 2 0 0 1 1\n1 2\n1 zwei\n");
  r = run_mesh(poly + " --area-grid " + grid);
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.output.find("g.txt:3:"), std::string::npos) << r.output;
  const auto outside = write_text("out.poly", square_region.substr(0, square_region.find("1 0.5")) +
                                                  "1 2 2 0 1e-4\n");
  r = run_mesh(outside);
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.output.find("region 0"), std::string::npos) << r.output;
  r = run_mesh(poly + " --sizing \"x-0.5\"");
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.output.find("must be > 0"), std::string::npos) << r.output;
}

// A field that vanishes inside the domain's hole (never in the domain) meshes at one and four
// subdomains: the field is bounded over the domain, not its bounding box (issue 36 item 2).
TEST(PddMeshSizing, AFieldThatVanishesInAHoleMeshes) {
  const auto poly = write_text("holed.poly", "8 2 0 0\n1 0 0\n2 1 0\n3 1 1\n4 0 1\n"
                                             "5 0.4 0.4\n6 0.6 0.4\n7 0.6 0.6\n8 0.4 0.6\n"
                                             "8 0\n1 1 2\n2 2 3\n3 3 4\n4 4 1\n"
                                             "5 5 6\n6 6 7\n7 7 8\n8 8 5\n1\n1 0.5 0.5\n");
  for (const char* n : {"1", "4"}) {
    const nlohmann::json j =
        stats_of(poly + " --sizing \"1e-3*(sqrt((x-0.5)^2+(y-0.5)^2)-0.05)\" --subdomains " + n);
    EXPECT_EQ(j["conforming"], true) << n;
    EXPECT_LE(j["max_area_ratio"].get<double>(), 1.0) << n;
    EXPECT_NEAR(j["gradation"].get<double>(), (std::sqrt(0.5) - 0.05) / 0.05, 0.5) << n;
  }
}

} // namespace

} // namespace sizing_options_test
