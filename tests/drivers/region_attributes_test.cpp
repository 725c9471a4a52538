// pdd-mesh -A (--region-attributes): the .poly's regional attributes written with the mesh, in
// the decoupled runs (closed loops, and a general domain decoupled from its faces) and the
// monolithic one (general domain), counted in --stats; a note without -A; refusals.
#include <pdd/io/poly.hpp>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "general_domains.hpp"
#include "test_files.hpp"
#include "test_support.hpp"

#include <cmath>
#include <cstddef>
#include <fstream>
#include <map>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

namespace region_attributes_test {
namespace fs = std::filesystem;

namespace {

pdd::test::command_result run_mesh(const std::string& args) {
  const std::string exe = PDD_MESH_EXE;
  const std::string cmd = "'" + exe + "' " + args;
  return pdd::test::run_command(cmd);
}

/// Two squares side by side, each a component of the domain, with regions 4 and 9.
std::string two_squares_poly() {
  pdd::pslg g;
  g.add_loop(std::vector<pdd::point>{{0, 0}, {1, 0}, {1, 1}, {0, 1}});
  g.add_loop(std::vector<pdd::point>{{2, 0}, {3, 0}, {3, 1}, {2, 1}});
  g.regions.push_back({{0.5, 0.5}, 4.0, -1.0});
  g.regions.push_back({{2.5, 0.5}, 9.0, -1.0});
  const auto p = pdd::test::temp_path("two_squares.poly");
  pdd::write_poly(p, g);
  return p.string();
}

/// The .ele's attribute column, by attribute: the triangles whose centroid x is left of 1.5
/// and right of it.
std::map<double, std::pair<std::size_t, std::size_t>> ele_attributes(const fs::path& node) {
  std::ifstream ele(fs::path(node).replace_extension(".ele"));
  std::ifstream nodes(node);
  std::size_t nv = 0, dim = 0, na = 0, nm = 0;
  nodes >> nv >> dim >> na >> nm;
  std::vector<double> x(nv + 1);
  for (std::size_t i = 0; i < nv; ++i) {
    std::size_t id = 0;
    double y = 0;
    nodes >> id;
    nodes >> x[id] >> y;
    for (std::size_t k = 0; k < na + nm; ++k)
      nodes >> y;
  }
  std::size_t nt = 0, corners = 0, columns = 0;
  ele >> nt >> corners >> columns;
  EXPECT_EQ(columns, 1u);
  std::map<double, std::pair<std::size_t, std::size_t>> out;
  for (std::size_t t = 0; t < nt; ++t) {
    std::size_t id = 0, a = 0, b = 0, c = 0;
    double value = 0;
    ele >> id >> a >> b >> c >> value;
    auto& [left, right] = out[value];
    ++((x[a] + x[b] + x[c]) / 3 < 1.5 ? left : right);
  }
  return out;
}

} // namespace

TEST(PddMeshRegionAttributes, DecoupledEleVtuMshAndStats) {
  const std::string poly = two_squares_poly();
  const auto node = pdd::test::temp_path("two_squares_out.node");
  const auto stats = pdd::test::temp_path("two_squares_stats.json");
  const auto r = run_mesh(poly + " --max-area 1e-3 --subdomains 6 --threads 2 -A -o " +
                          node.string() + " --stats " + stats.string());
  ASSERT_EQ(r.code, 0) << r.output;
  EXPECT_EQ(r.output.find("-A writes them"), std::string::npos) << r.output;
  const auto by = ele_attributes(node);
  ASSERT_EQ(by.size(), 2u);
  EXPECT_GT(by.at(4.0).first, 500u);
  EXPECT_EQ(by.at(4.0).second, 0u);
  EXPECT_EQ(by.at(9.0).first, 0u);
  EXPECT_GT(by.at(9.0).second, 500u);
  std::ifstream in(stats);
  const nlohmann::json j = nlohmann::json::parse(in);
  ASSERT_TRUE(j.contains("region_attributes")) << j.dump();
  ASSERT_EQ(j["region_attributes"].size(), 2u);
  EXPECT_EQ(j["region_attributes"][0]["attribute"], 4.0);
  EXPECT_EQ(j["region_attributes"][0]["triangles"], by.at(4.0).first);
  EXPECT_EQ(j["region_attributes"][1]["triangles"], by.at(9.0).second);
  // the .vtu carries the cell data, the .msh one physical tag per region
  const auto vtu = pdd::test::temp_path("two_squares_out.vtu");
  const auto msh = pdd::test::temp_path("two_squares_out.msh");
  for (const auto& out : {vtu, msh}) {
    const auto rr = run_mesh(poly + " --max-area 1e-3 --subdomains 6 -A -q -o " + out.string());
    ASSERT_EQ(rr.code, 0) << rr.output;
  }
  EXPECT_NE(pdd::test::read_text(vtu).find("Name=\"region_attribute\""), std::string::npos);
  const std::string m = pdd::test::read_text(msh);
  EXPECT_NE(m.find(" 0 1 4 0\n"), std::string::npos);
  EXPECT_NE(m.find(" 0 1 9 0\n"), std::string::npos);
}

TEST(PddMeshRegionAttributes, GeneralDomainNoteAndRefusals) {
  const auto poly = pdd::test::temp_path("layered.poly");
  pdd::write_poly(poly, pdd::test::layered_domain(0.05));
  const auto node = pdd::test::temp_path("layered_out.node");
  // without -A: said, not silently dropped
  const auto quiet = run_mesh(poly.string() + " --max-area 0.05 -o " + node.string());
  ASSERT_EQ(quiet.code, 0) << quiet.output;
  EXPECT_NE(quiet.output.find("-A writes them"), std::string::npos) << quiet.output;
  const auto r = run_mesh(poly.string() + " --max-area 0.05 -A --verify -o " + node.string());
  ASSERT_EQ(r.code, 0) << r.output;
  std::size_t regions = 0;
  for (const auto& [value, lr] : ele_attributes(node)) {
    EXPECT_EQ(value, static_cast<double>(static_cast<int>(value)));
    EXPECT_GE(value, 1.0);
    EXPECT_LE(value, 5.0);
    regions += lr.first + lr.second > 0;
  }
  EXPECT_EQ(regions, 5u);
  // an .svg cannot carry them; per-subdomain files do not take -A
  const auto svg = run_mesh(poly.string() + " --max-area 0.05 -A -o " +
                            pdd::test::temp_path("layered.svg").string());
  EXPECT_EQ(svg.code, 1) << svg.output;
  EXPECT_NE(svg.output.find("region attributes"), std::string::npos) << svg.output;
  EXPECT_FALSE(fs::exists(pdd::test::temp_path("layered.svg")));
  const auto per = run_mesh(poly.string() + " --max-area 0.05 -A --output-per-subdomain " +
                            pdd::test::temp_path("layered_pieces").string());
  EXPECT_EQ(per.code, 2) << per.output;
}

TEST(PddMeshRegionAttributes, GeneralDomainDecoupledFromItsFaces) {
  const auto poly = pdd::test::temp_path("layered16.poly");
  pdd::write_poly(poly, pdd::test::layered_domain(0.01));
  const auto node = pdd::test::temp_path("layered16_out.node");
  const auto stats = pdd::test::temp_path("layered16_stats.json");
  const auto r = run_mesh(poly.string() +
                          " --max-area 0.01 --subdomains 16 --threads 2 -A "
                          "--verify -o " +
                          node.string() + " --stats " + stats.string());
  ASSERT_EQ(r.code, 0) << r.output;
  EXPECT_NE(r.output.find("MADD from its 5 faces"), std::string::npos) << r.output;
  std::ifstream in(stats);
  const nlohmann::json j = nlohmann::json::parse(in);
  EXPECT_GE(j["subdomains"], 16); // the regions' areas: the graded path, which may add some
  EXPECT_EQ(j["path"], "graded");
  EXPECT_EQ(j["conforming"], true);
  EXPECT_EQ(j["region_attributes"].size(), 5u) << j.dump();
  // a dangling crack and an isolated well lie inside subdomains: decoupled, verified
  const auto combined = pdd::test::temp_path("combined.poly");
  pdd::write_poly(combined, pdd::test::combined_domain(0.05));
  const auto yes =
      run_mesh(combined.string() + " --max-area 0.05 --subdomains 8 -A --verify -o " +
               pdd::test::temp_path("combined_out.node").string() + " --stats " + stats.string());
  ASSERT_EQ(yes.code, 0) << yes.output;
  EXPECT_NE(yes.output.find("verification passed"), std::string::npos) << yes.output;
  std::ifstream in2(stats);
  const nlohmann::json j2 = nlohmann::json::parse(in2);
  EXPECT_GE(j2["subdomains"], 8);
  EXPECT_EQ(j2["interface_splits"], 0);
  // rings touching at a vertex: decoupled, verified
  const auto pinched = pdd::test::temp_path("pinched.poly");
  pdd::write_poly(pinched, pdd::test::pinched_rings());
  const auto rings =
      run_mesh(pinched.string() + " --max-area 0.05 --subdomains 4 --verify -o " +
               pdd::test::temp_path("pinched_out.node").string() + " --stats " + stats.string());
  ASSERT_EQ(rings.code, 0) << rings.output;
  EXPECT_NE(rings.output.find("verification passed"), std::string::npos) << rings.output;
  std::ifstream in3(stats);
  EXPECT_EQ(nlohmann::json::parse(in3)["subdomains"], 4);
  // a chord at 30 deg to the bottom side (and 60 deg to the right side): caps around both
  // ends, decoupled and verified, the plan's reason naming the first
  pdd::pslg chord;
  chord.add_loop(std::vector<pdd::point>{
      {0, 0}, {4, 0}, {4, 4 * std::tan(std::numbers::pi / 6)}, {4, 4}, {0, 4}});
  chord.add_segment(0, 2);
  const auto corner = pdd::test::temp_path("corner.poly");
  pdd::write_poly(corner, chord);
  const auto capped =
      run_mesh(corner.string() + " --max-area 0.05 --subdomains 4 --verify -o " +
               pdd::test::temp_path("corner_out.node").string() + " --stats " + stats.string());
  ASSERT_EQ(capped.code, 0) << capped.output;
  EXPECT_NE(capped.output.find("verification passed"), std::string::npos) << capped.output;
  EXPECT_NE(capped.output.find("2 cap(s) (the first at vertex 0 (0, 0))"), std::string::npos)
      << capped.output;
  std::ifstream in4(stats);
  const nlohmann::json capped_stats = nlohmann::json::parse(in4);
  EXPECT_EQ(capped_stats["subdomains"], 4);
  EXPECT_EQ(capped_stats["interface_splits"], 0);
}

} // namespace region_attributes_test
