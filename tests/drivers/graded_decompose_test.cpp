// pdd-decompose's graded MADD options (dissertation 4.4): vertex weights from the .poly's
// first vertex attribute, weight files, the area-ratio rule; statistics and clear errors.
#include <pdd/io/decomposition_io.hpp>
#include <pdd/io/poly.hpp>
#include <pdd/madd/validate_decomposition.hpp>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "test_files.hpp"

#include <fstream>
#include <string>

namespace graded_decompose_test {
namespace {

pdd::test::command_result decompose(const std::string& args) {
  return pdd::test::run_command("'" PDD_DECOMPOSE_EXE "' " + args);
}

nlohmann::json read_json(const std::string& p) {
  std::ifstream in(p);
  return nlohmann::json::parse(in);
}

/// The unit square, weight 4 on the vertices of its left side (the first attribute), written
/// for the running test.
std::string weighted_square() {
  return pdd::test::write_temp_file("graded_square.poly",
                                    "4 2 1 0\n1 0 0 4\n2 1 0 0\n3 1 1 0\n4 0 1 4\n4 0\n1 1 2\n"
                                    "2 2 3\n3 3 4\n4 4 1\n0\n");
}

} // namespace

TEST(PddDecomposeGraded, VertexWeightsGiveNSubdomainsAndStatistics) {
  const std::string stats = pdd::test::write_temp_file("graded_v.json", "");
  const std::string out = pdd::test::write_temp_file("graded_v.pdd", "");
  const auto r =
      decompose(weighted_square() + " -n 24 --vertex-weights --interpolation 0 " +
                "--uniform-factor 3 --weight-factor 3 -q --stats " + stats + " -o " + out);
  ASSERT_EQ(r.code, 0) << r.output;
  const auto j = read_json(stats);
  EXPECT_EQ(j["subdomains"], 24);
  EXPECT_TRUE(j["valid"].get<bool>());
  EXPECT_EQ(j["graded"]["mode"], "vertex_weights");
  EXPECT_EQ(j["graded"]["interpolation"], 0.0);
  // a subdomain away from the left side has no weight; one on it at least 4 + 4
  EXPECT_EQ(j["graded"]["weight_min"].get<double>(), 0.0);
  EXPECT_GE(j["graded"]["weight_max"].get<double>(), 8.0);
  const auto d = pdd::read_decomposition(out);
  EXPECT_TRUE(pdd::validate_decomposition(d, pdd::read_poly(weighted_square())).ok());
}

TEST(PddDecomposeGraded, AreaFunctionStopsAtTheRatioBound) {
  const std::string stats = pdd::test::write_temp_file("graded_a.json", "");
  const auto r = decompose(weighted_square() + " --area-function '0.002+0.05*x' --area-ratio 1 " +
                           "--stats " + stats);
  ASSERT_EQ(r.code, 0) << r.output;
  EXPECT_NE(r.output.find("graded (area ratio): area / required area per subdomain"),
            std::string::npos)
      << r.output;
  const auto j = read_json(stats);
  EXPECT_GE(j["subdomains"].get<int>(), 65); // the integral of 1 / F is 65
  EXPECT_EQ(j["graded"]["mode"], "area_ratio");
  EXPECT_LE(j["graded"]["area_ratio_max"].get<double>(), 1.0);
  EXPECT_GT(j["graded"]["area_ratio_max"].get<double>(), 0.25);
}

TEST(PddDecomposeGraded, BadOptionsAndFilesAreClearErrors) {
  const std::string plain = pdd::test::write_temp_file(
      "graded_plain.poly", "4 2 0 0\n1 0 0\n2 1 0\n3 1 1\n4 0 1\n4 0\n1 1 2\n2 2 3\n3 3 4\n"
                           "4 4 1\n0\n");
  auto r = decompose(plain + " -n 4 --vertex-weights");
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.output.find("<#attributes> is 0"), std::string::npos) << r.output;
  const std::string bad =
      pdd::test::write_temp_file("graded_bad.node", "2 2 1 0\n1 0 0 1\n2 1 1 -2\n");
  r = decompose(plain + " -n 4 --node-weights " + bad);
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.output.find(bad + ":3: expected the vertex weight to be >= 0, found -2"),
            std::string::npos)
      << r.output;
  r = decompose(plain + " -n 4 --area-function '0.1+*x'");
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.output.find("column"), std::string::npos) << r.output;
  EXPECT_EQ(decompose(weighted_square() + " -n 4 --vertex-weights --interpolation 2").code, 2);
  EXPECT_EQ(decompose(weighted_square() + " --vertex-weights").code, 2); // N needed
  EXPECT_EQ(decompose(weighted_square() + " -n 4 --vertex-weights --node-weights " + bad).code, 2);
  EXPECT_EQ(decompose(weighted_square() + " -n 4 --vertex-weights --max-area 0.01").code, 2);
  EXPECT_EQ(decompose(weighted_square() + " -n 4 --vertex-weights --uniform-factor 0 "
                                          "--weight-factor 0")
                .code,
            1);
}

TEST(PddDecomposeGraded, WeightAndAreaGridsFromFiles) {
  // weights 0 except the node (0,0) of a 3 x 3 grid over the square: the corner's subdomain
  // is small; the stats report the weights
  const std::string weights =
      pdd::test::write_temp_file("graded_w3.grid", "3 3 0 0 0.5 0.5\n9 0 0\n0 0 0\n0 0 0\n");
  const std::string stats = pdd::test::write_temp_file("graded_g.json", "");
  auto r =
      decompose(weighted_square() + " -n 12 -q --grid-weights " + weights + " --stats " + stats);
  ASSERT_EQ(r.code, 0) << r.output;
  auto j = read_json(stats);
  EXPECT_EQ(j["graded"]["mode"], "grid_weights");
  EXPECT_EQ(j["graded"]["weight_max"].get<double>(), 9.0);
  EXPECT_EQ(j["graded"]["weight_min"].get<double>(), 0.0);
  // required area 0.05 everywhere (a 2 x 2 area grid): every subdomain <= 0.05 * 1.5
  const std::string areas =
      pdd::test::write_temp_file("graded_a2.grid", "2 2 0 0 1 1\n0.05 0.05\n0.05 0.05\n");
  r = decompose(weighted_square() + " -q --area-grid " + areas + " --area-ratio 1.5 --stats " +
                stats);
  ASSERT_EQ(r.code, 0) << r.output;
  j = read_json(stats);
  EXPECT_LE(j["graded"]["area_ratio_max"].get<double>(), 1.5);
  EXPECT_GE(j["subdomains"].get<int>(), 14); // 1 / (0.05 * 1.5) = 13.3
}

} // namespace graded_decompose_test
