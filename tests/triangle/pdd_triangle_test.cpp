// pdd-triangle end to end: Triangle's output files, switches that change them, statistics,
// refusals; outputs read back by pdd's reader.
#include <pdd/io/poly.hpp>

#include <gtest/gtest.h>

#include "test_files.hpp"
#include "test_support.hpp"

#include <sys/wait.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace pdd_triangle_test {
namespace fs = std::filesystem;

namespace {

using run_result = pdd::test::command_result;

run_result run_in(const fs::path& dir, const std::string& args) {
  const std::string cmd =
      "cd '" + dir.string() + "' && '" + std::string(PDD_TRIANGLE_EXE) + "' " + args;
  return pdd::test::run_command(cmd);
}

/// A fresh folder holding key.poly.
fs::path folder_with_key(const std::string& name) {
  const fs::path dir = pdd::test::temp_path(name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  fs::copy_file(pdd::test::bundled_data("key.poly"), dir / "key.poly");
  return dir;
}

std::string first_line(const fs::path& p) {
  std::ifstream in(p);
  std::string line;
  std::getline(in, line);
  return line;
}

std::string second_line(const fs::path& p) {
  std::ifstream in(p);
  std::string line;
  std::getline(in, line);
  std::getline(in, line);
  return line;
}

} // namespace

TEST(PddTriangle, WritesTriangleFilesThatReadBack) {
  const fs::path dir = folder_with_key("pt_basic");
  const auto r = run_in(dir, "-pq30a0.01 key.poly");
  ASSERT_EQ(r.code, 0) << r.output;
  for (const char* s : {"Opening key.poly.", "Writing key.1.node.", "Writing key.1.ele.",
                        "Writing key.1.poly.", "Input vertices: 54", "Input segments: 54",
                        "Input holes: 1", "Mesh triangles: ", "Mesh subsegments"})
    EXPECT_NE(r.output.find(s), std::string::npos) << s << "\n" << r.output;
  // key.1.poly refers to key.1.node: pdd's reader gives the mesh's vertices and subsegments
  const pdd::pslg back = pdd::read_poly(dir / "key.1.poly");
  const pdd::pslg key = pdd::read_poly(dir / "key.poly");
  ASSERT_GT(back.vertices.size(), key.vertices.size());
  for (std::size_t i = 0; i < key.vertices.size(); ++i)
    EXPECT_EQ(back.vertices[i], key.vertices[i]) << i;
  EXPECT_EQ(back.holes, key.holes);
  EXPECT_GT(back.segments.size(), key.segments.size());
  EXPECT_EQ(first_line(dir / "key.1.node").substr(first_line(dir / "key.1.node").find(' ')),
            " 2 0 1");
  const std::string ele = first_line(dir / "key.1.ele");
  EXPECT_EQ(ele.substr(ele.find(' ')), " 3 0"); // no attribute column without -A
  EXPECT_EQ(second_line(dir / "key.1.ele").substr(0, 2), "1 ");
  // the statistics count what the files hold
  EXPECT_NE(r.output.find("Mesh triangles: " + ele.substr(0, ele.find(' '))), std::string::npos);
  // a second run numbers its outputs from the first one's name
  // key.1.poly's mesh vertices are not all on segments: isolated vertices, meshed whole
  const auto r2 = run_in(dir, "-pq key.1");
  ASSERT_EQ(r2.code, 0) << r2.output;
  EXPECT_NE(r2.output.find("not one of closed loops"), std::string::npos) << r2.output;
  EXPECT_TRUE(fs::exists(dir / "key.2.ele"));
}

TEST(PddTriangle, SecondOrderPAloneAndIgnoredSwitches) {
  const fs::path dir = folder_with_key("pt_o2");
  auto r = run_in(dir, "-pqo2Vi key.poly");
  ASSERT_EQ(r.code, 0) << r.output;
  EXPECT_NE(r.output.find("Adding vertices for second-order triangles."), std::string::npos);
  EXPECT_NE(r.output.find("Ignoring switch(es) -i"), std::string::npos) << r.output;
  const std::string ele = first_line(dir / "key.1.ele");
  EXPECT_EQ(ele.substr(ele.find(' ')), " 6 0"); // six nodes, no attribute
  std::istringstream row(second_line(dir / "key.1.ele"));
  std::vector<long> ids{std::istream_iterator<long>(row), std::istream_iterator<long>()};
  EXPECT_EQ(ids.size(), 7u);
  // p alone: the constrained Delaunay triangulation, the .node is the input's vertices
  const fs::path d2 = folder_with_key("pt_p");
  r = run_in(d2, "-pQ key.poly");
  ASSERT_EQ(r.code, 0) << r.output;
  const pdd::pslg key = pdd::read_poly(pdd::test::bundled_data("key.poly"));
  const std::string node = first_line(d2 / "key.1.node");
  EXPECT_EQ(node.substr(0, node.find(' ')), std::to_string(key.vertices.size()));
}

TEST(PddTriangle, RefinesItsOwnOutput) {
  const fs::path dir = folder_with_key("pt_r");
  auto r = run_in(dir, "-pqQ key.poly");
  ASSERT_EQ(r.code, 0) << r.output;
  r = run_in(dir, "-rpq30a0.002 key.1");
  ASSERT_EQ(r.code, 0) << r.output;
  EXPECT_NE(r.output.find("Refining the previous mesh."), std::string::npos) << r.output;
  const pdd::pslg before = pdd::read_node(dir / "key.1.node");
  const pdd::pslg after = pdd::read_node(dir / "key.2.node");
  ASSERT_GT(after.vertices.size(), before.vertices.size());
  EXPECT_TRUE(std::equal(before.vertices.begin(), before.vertices.end(), after.vertices.begin()));
  EXPECT_TRUE(fs::exists(dir / "key.2.ele"));
  EXPECT_TRUE(fs::exists(dir / "key.2.poly"));
  // an .ele or .area name is read only with -r
  r = run_in(dir, "-pq key.1.ele");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.output.find("only to refine a previous mesh (-r)"), std::string::npos) << r.output;
}

TEST(PddTriangle, SwitchesChangeTheFiles) {
  const fs::path dir = folder_with_key("pt_switches");
  auto r = run_in(dir, "-pq -a0.02 -zBAnQ key.poly --threads 2 --subdomains 1");
  ASSERT_EQ(r.code, 0) << r.output;
  EXPECT_EQ(r.output, ""); // -Q: nothing printed
  const std::string node = first_line(dir / "key.1.node");
  EXPECT_EQ(node.substr(node.find(' ')), " 2 0 0");              // -B: no markers
  EXPECT_EQ(second_line(dir / "key.1.node").substr(0, 2), "0 "); // -z
  const std::string ele = first_line(dir / "key.1.ele");
  EXPECT_EQ(ele.substr(ele.find(' ')), " 3 1"); // -A: the regional attribute column
  EXPECT_TRUE(fs::exists(dir / "key.1.neigh"));
  EXPECT_EQ(first_line(dir / "key.1.neigh"), ele.substr(0, ele.find(' ')) + " 3");

  const fs::path d2 = folder_with_key("pt_nep");
  r = run_in(d2, "-pqNEP key");
  ASSERT_EQ(r.code, 0) << r.output;
  EXPECT_NE(r.output.find("NOT writing a .node file."), std::string::npos);
  EXPECT_NE(r.output.find("NOT writing an .ele file."), std::string::npos);
  EXPECT_NE(r.output.find("NOT writing a .poly file."), std::string::npos);
  EXPECT_EQ(std::distance(fs::directory_iterator(d2), fs::directory_iterator{}), 1);

  const fs::path d3 = folder_with_key("pt_i");
  r = run_in(d3, "-pqI key.poly");
  ASSERT_EQ(r.code, 0) << r.output;
  EXPECT_TRUE(fs::exists(d3 / "key.node"));
  EXPECT_TRUE(fs::exists(d3 / "key.ele"));
  // the input .poly is never overwritten
  std::ifstream a(d3 / "key.poly"), b(pdd::test::bundled_data("key.poly"));
  std::stringstream sa, sb;
  sa << a.rdbuf();
  sb << b.rdbuf();
  EXPECT_EQ(sa.str(), sb.str());
}

TEST(PddTriangle, VerboseQualityStatistics) {
  const fs::path dir = folder_with_key("pt_v");
  const auto r = run_in(dir, "-pq25a0.005V key.poly");
  ASSERT_EQ(r.code, 0) << r.output;
  EXPECT_NE(r.output.find("Mesh quality statistics:"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("Angle histogram:"), std::string::npos);
  // no angle below 20 degrees with q25
  EXPECT_NE(r.output.find("  0 -  10 degrees:        0"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find(" 10 -  20 degrees:        0"), std::string::npos) << r.output;
}

TEST(PddTriangle, RefusesWhatItCannotDo) {
  const fs::path dir = folder_with_key("pt_refuse");
  struct refusal {
    const char* args;
    const char* message;
    int code;
  };
  for (const refusal& c :
       {refusal{"-pqY key.poly", "switch -Y", 2},
        refusal{"-q key.node", "cannot open 'key.node'", 1},
        refusal{"-pq key.1.ele", "only to refine a previous mesh (-r)", 2},
        refusal{"-pa0 key.poly", "greater than zero", 2},
        refusal{"-pq missing.poly", "missing.poly", 1}, refusal{"-pq", "input is required", 2},
        refusal{"-pq key.poly --threads 0", "--threads", 2}}) {
    const auto r = run_in(dir, c.args);
    EXPECT_EQ(r.code, c.code) << c.args << "\n" << r.output;
    EXPECT_NE(r.output.find(c.message), std::string::npos) << c.args << "\n" << r.output;
  }
  EXPECT_FALSE(fs::exists(dir / "key.1.node")); // nothing written by a refused run
}

TEST(PddTriangle, CheckSwitchAndAnEmptyDomain) {
  const fs::path dir = folder_with_key("pt_check");
  const auto checked = run_in(dir, "-pq30a0.01C key.poly");
  EXPECT_EQ(checked.code, 0) << checked.output;
  EXPECT_NE(checked.output.find("Checked the mesh with pdd's verifier (-C)"), std::string::npos)
      << checked.output;
  // Triangle's box example without c: no face is enclosed by segments; Triangle 1.6 writes its
  // eight vertices and no triangle (exit 0), pdd too, with a warning even under -Q
  std::ofstream(dir / "box.poly") << "8 2 0 1\n1 0 0 0\n2 0 3 0\n3 3 0 0\n4 3 3 33\n5 1 1 0\n"
                                     "6 1 2 0\n7 2 1 0\n8 2 2 0\n5 1\n1 1 2 5\n2 5 7 0\n"
                                     "3 7 8 0\n4 8 6 10\n5 6 5 0\n1\n1 1.5 1.5\n";
  const auto empty = run_in(dir, "-pqQ box.poly");
  EXPECT_EQ(empty.code, 0) << empty.output;
  EXPECT_NE(empty.output.find("warning: box.poly: the PSLG encloses no domain"), std::string::npos)
      << empty.output;
  EXPECT_EQ(first_line(dir / "box.1.ele"), "0 3 0");
  EXPECT_EQ(first_line(dir / "box.1.node"), "8 2 0 1");
}

#ifndef PDD_PERMISSIVE // D and S mesh on CGAL's Mesh_2
TEST(PddTriangle, ConformingDelaunayAndSteinerBudget) {
  const fs::path dir = folder_with_key("pt_conforming");
  const auto d = run_in(dir, "-pD key.poly");
  ASSERT_EQ(d.code, 0) << d.output;
  EXPECT_NE(d.output.find("1 subdomain: -D and -S mesh the whole domain"), std::string::npos)
      << d.output;
  EXPECT_EQ(pdd::read_poly(dir / "key.1.poly").holes, pdd::read_poly(dir / "key.poly").holes);
  const auto s = run_in(dir, "-pq30S7 key.poly"); // -pq30 on the key adds far more than 7
  ASSERT_EQ(s.code, 0) << s.output;
  EXPECT_NE(s.output.find("Mesh vertices: 61"), std::string::npos) << s.output;
  EXPECT_EQ(first_line(dir / "key.1.node").substr(0, 3), "61 ");
  const auto y = run_in(dir, "-pqYY key.poly");
  EXPECT_EQ(y.code, 2);
  EXPECT_NE(y.output.find("need segment splits"), std::string::npos) << y.output;
}
#endif

TEST(PddTriangle, VertexSetEdgesVoronoiAndHull) {
  const fs::path dir = pdd::test::fresh_dir("pt_points");
  // Triangle 1.6's example of the `triangle` package: four corners and the centre, which
  // Triangle triangulates into 4 triangles, 8 edges (4 on the hull), 4 Voronoi vertices and 4
  // rays; a duplicate of the centre is ignored with Triangle's warning.
  pdd::test::write_text(dir / "pts.node", "6 2 0 0\n1 0 0\n2 0 1\n3 0.5 0.5\n4 1 1\n5 1 0\n"
                                          "6 0.5 0.5\n");
  auto r = run_in(dir, "-cev pts");
  ASSERT_EQ(r.code, 0) << r.output;
  for (const char* s : {"Opening pts.node.", "Writing pts.1.edge.", "Writing pts.1.v.node.",
                        "Writing pts.1.v.edge.", "Writing pts.1.poly.",
                        "A duplicate vertex at (0.5, 0.5) appeared and was ignored",
                        "Input vertices: 6\n\n  Mesh vertices: 5\n", "Mesh edges: 8\n"})
    EXPECT_NE(r.output.find(s), std::string::npos) << s << "\n" << r.output;
  EXPECT_EQ(first_line(dir / "pts.1.node"), "6 2 0 1");
  EXPECT_EQ(first_line(dir / "pts.1.ele"), "4 3 0");
  EXPECT_EQ(first_line(dir / "pts.1.edge"), "8 1");
  EXPECT_EQ(first_line(dir / "pts.1.v.node"), "4 2 0 0");
  EXPECT_EQ(first_line(dir / "pts.1.v.edge"), "8 0");
  std::ifstream vedge(dir / "pts.1.v.edge");
  std::string line;
  std::getline(vedge, line); // the header
  std::size_t rays = 0;
  while (std::getline(vedge, line)) { // <id> <v> -1 <dx> <dy>: a ray
    std::istringstream fields(line);
    std::string id, v, w;
    fields >> id >> v >> w;
    rays += w == "-1";
  }
  EXPECT_EQ(rays, 4u);
  EXPECT_EQ(r.output.find("Input segments"), std::string::npos); // Triangle prints none here
  // the hull as the .poly's segments, over the .node's vertices: 4 segments of marker 1
  const pdd::pslg hull = pdd::read_poly(dir / "pts.1.poly");
  EXPECT_EQ(hull.vertices.size(), 6u);
  ASSERT_EQ(hull.segments.size(), 4u);
  for (const auto& s : hull.segments)
    EXPECT_EQ(s.marker, 1);
  // B and z: no marker column, numbering from 0; no .poly without c
  r = run_in(dir, "-QBze pts.node");
  ASSERT_EQ(r.code, 0) << r.output;
  EXPECT_EQ(first_line(dir / "pts.1.edge"), "8 0");
  EXPECT_EQ(second_line(dir / "pts.1.edge").substr(0, 2), "0 ");
  // vertex attributes are carried to the output, interpolated linearly (here 5 + x + 2 y)
  pdd::test::write_text(dir / "att.node", "4 2 1 0\n1 0 0 5\n2 1 0 6\n3 1 1 8\n4 0 1 7\n");
  r = run_in(dir, "-qa0.05 att");
  ASSERT_EQ(r.code, 0) << r.output;
  const pdd::pslg att = pdd::read_node(dir / "att.1.node");
  ASSERT_EQ(att.vertex_attribute_count, 1u);
  ASSERT_GT(att.vertices.size(), 4u);
  for (std::size_t v = 0; v < att.vertices.size(); ++v)
    EXPECT_NEAR(att.vertex_attributes[v], 5 + att.vertices[v].x + 2 * att.vertices[v].y, 1e-12);
  // a quality mesh of the hull, every input vertex kept
  r = run_in(dir, "-qa0.01 pts");
  ASSERT_EQ(r.code, 0) << r.output;
  const pdd::pslg mesh_nodes = pdd::read_node(dir / "pts.1.node");
  EXPECT_GT(mesh_nodes.vertices.size(), 6u);
  for (const pdd::point p : std::vector<pdd::point>{{0, 0}, {0, 1}, {0.5, 0.5}, {1, 1}, {1, 0}})
    EXPECT_NE(std::find(mesh_nodes.vertices.begin(), mesh_nodes.vertices.end(), p),
              mesh_nodes.vertices.end());
}

TEST(PddTriangle, VertexSetErrors) {
  const fs::path dir = pdd::test::fresh_dir("pt_points_bad");
  pdd::test::write_text(dir / "line.node", "3 2 0 0\n1 0 0\n2 1 1\n3 2 2\n");
  pdd::test::write_text(dir / "two.node", "2 2 0 0\n1 0 0\n2 1 1\n");
  pdd::test::write_text(dir / "bad.node", "3 2 0 0\n1 0 0\n2 1 x\n3 2 2\n");
  for (const auto& [args, message] :
       {std::pair{"line", "collinear"}, std::pair{"-v two.node", "at least three distinct"},
        std::pair{"bad", "bad.node:3"}, std::pair{"-pc line", "line.poly"}}) {
    const auto r = run_in(dir, args);
    EXPECT_EQ(r.code, 1) << args << "\n" << r.output;
    EXPECT_NE(r.output.find(message), std::string::npos) << args << "\n" << r.output;
  }
}

} // namespace pdd_triangle_test
