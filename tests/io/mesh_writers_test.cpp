// Mesh writers: Triangle files, VTU/PVTU and MSH (read back by meshio through /usr/bin/python3),
// SVG pictures, write_mesh's dispatch.
#include "test_files.hpp"

#include <pdd/errors.hpp>
#include <pdd/io/msh.hpp>
#include <pdd/io/poly.hpp>
#include <pdd/io/svg.hpp>
#include <pdd/io/triangle_files.hpp>
#include <pdd/io/vtu.hpp>
#include <pdd/io/write_mesh.hpp>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

namespace mesh_writers_test {
namespace {

using json = nlohmann::json;

// meshio -> JSON: points, and per cell block its type, connectivity and integer cell data.
const char* meshio_dump = R"PY(
import json, sys
import meshio
m = meshio.read(sys.argv[1])
out = {"points": m.points.tolist(), "blocks": [], "point_data": {}}
for k, c in enumerate(m.cells):
    blk = {"type": c.type, "data": c.data.tolist(), "cell_data": {}}
    for name, arrays in m.cell_data.items():
        blk["cell_data"][name] = [int(v) for v in arrays[k]]
    out["blocks"].append(blk)
for name, d in m.point_data.items():
    if d.ndim == 1:
        out["point_data"][name] = [int(v) for v in d]
json.dump(out, open(sys.argv[2], "w"))
)PY";

json meshio_read(const std::filesystem::path& dir, const std::filesystem::path& file) {
  std::string log;
  const auto out = dir / "meshio.json";
  const int rc = pdd::test::run_python(dir, meshio_dump,
                                       "'" + file.string() + "' '" + out.string() + "'", log);
  EXPECT_EQ(rc, 0) << log;
  if (rc != 0) return json();
  return json::parse(pdd::test::read_text(out));
}

void expect_points(const json& j, const pdd::triangle_mesh& m) {
  ASSERT_EQ(j["points"].size(), m.vertices.size());
  for (std::size_t i = 0; i < m.vertices.size(); ++i) {
    EXPECT_EQ(j["points"][i][0].get<double>(), m.vertices[i].x);
    EXPECT_EQ(j["points"][i][1].get<double>(), m.vertices[i].y);
    EXPECT_EQ(j["points"][i][2].get<double>(), 0.0);
  }
}

template <class T>
T read_raw(const std::string& s, std::size_t& pos) {
  T v;
  EXPECT_LE(pos + sizeof(T), s.size());
  std::memcpy(&v, s.data() + pos, sizeof(T));
  pos += sizeof(T);
  return v;
}

/// The offset="..." values of a .vtu's XML header (before the appended data at `base`), in
/// file order.
std::vector<std::uint64_t> xml_offsets(const std::string& s, std::size_t base) {
  std::vector<std::uint64_t> offsets;
  for (std::size_t q = s.find("offset=\""); q != std::string::npos && q < base;
       q = s.find("offset=\"", q + 1))
    offsets.push_back(std::stoull(s.substr(q + 8, 20)));
  return offsets;
}

std::size_t count_of(const std::string& s, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t p = s.find(what); p != std::string::npos; p = s.find(what, p + 1))
    ++n;
  return n;
}

/// The `d` attribute of the first path whose attributes contain `style`.
std::string path_data(const std::string& svg, const std::string& style) {
  const auto at = svg.find(style);
  if (at == std::string::npos) return {};
  const auto d = svg.find(" d=\"", at);
  return svg.substr(d + 4, svg.find('"', d + 4) - d - 4);
}

} // namespace

TEST(TriangleFiles, NodeEleAndPolyReadBack) {
  const auto m = pdd::test::small_mesh();
  const auto dir = pdd::test::fresh_dir("tri");
  pdd::write_triangle_files(dir / "mesh.node", m);
  EXPECT_EQ(pdd::test::dir_entries(dir),
            (std::vector<std::string>{"mesh.ele", "mesh.node", "mesh.poly"}));
  // The .poly refers to the .node: read_poly gives back vertices, markers and segments.
  const auto g = pdd::read_poly(dir / "mesh.poly");
  EXPECT_EQ(g.vertices, m.vertices);
  EXPECT_EQ(g.vertex_markers, m.vertex_markers);
  ASSERT_EQ(g.segments.size(), m.segments.size());
  for (std::size_t i = 0; i < m.segments.size(); ++i) {
    EXPECT_EQ(g.segments[i].a, m.segments[i].a);
    EXPECT_EQ(g.segments[i].b, m.segments[i].b);
    EXPECT_EQ(g.segments[i].marker, m.segments[i].marker);
  }
  // The .ele: header, 1-based ids and vertices, the marker as attribute.
  std::istringstream ele(pdd::test::read_text(dir / "mesh.ele"));
  std::size_t nt = 0, corners = 0, attrs = 0;
  ele >> nt >> corners >> attrs;
  EXPECT_EQ(nt, m.triangles.size());
  EXPECT_EQ(corners, 3u);
  EXPECT_EQ(attrs, 1u);
  for (std::size_t t = 0; t < nt; ++t) {
    std::size_t id = 0, a = 0, b = 0, c = 0;
    int marker = -1;
    ele >> id >> a >> b >> c >> marker;
    EXPECT_EQ(id, t + 1);
    EXPECT_EQ(
        (std::array<std::size_t, 3>{a - 1, b - 1, c - 1}),
        (std::array<std::size_t, 3>{m.triangles[t][0], m.triangles[t][1], m.triangles[t][2]}));
    EXPECT_EQ(marker, m.triangle_markers[t]);
  }
  std::string rest;
  EXPECT_FALSE(ele >> rest) << rest;
}

TEST(Vtu, RawAppendedLayout) {
  const auto m = pdd::test::small_mesh();
  const auto p = pdd::test::temp_path("layout.vtu");
  pdd::write_vtu(p, m);
  const std::string s = pdd::test::read_text(p);
  EXPECT_NE(s.find("NumberOfPoints=\"8\" NumberOfCells=\"8\""), std::string::npos);
  EXPECT_NE(s.find("header_type=\"UInt64\""), std::string::npos);
  EXPECT_NE(s.find("<AppendedData encoding=\"raw\">"), std::string::npos);
  // Offsets in the XML, in order, must match the blocks that follow '_'.
  const std::size_t base = s.find('_', s.find("<AppendedData")) + 1;
  const std::vector<std::uint64_t> offsets = xml_offsets(s, base);
  ASSERT_EQ(offsets.size(), 6u);
  std::size_t pos = base;
  const std::uint64_t sizes[] = {8 * 4, 8 * 4, 8 * 24, 24 * 4, 8 * 4, 8};
  for (int k = 0; k < 6; ++k) {
    EXPECT_EQ(pos - base, offsets[static_cast<std::size_t>(k)]) << "block " << k;
    const auto bytes = read_raw<std::uint64_t>(s, pos);
    EXPECT_EQ(bytes, sizes[k]) << "block " << k;
    const std::size_t start = pos;
    if (k == 0) {
      for (std::size_t i = 0; i < 8; ++i)
        EXPECT_EQ(read_raw<std::int32_t>(s, pos), m.vertex_markers[i]);
    } else if (k == 1) {
      for (std::size_t i = 0; i < 8; ++i)
        EXPECT_EQ(read_raw<std::int32_t>(s, pos), m.triangle_markers[i]);
    } else if (k == 2) {
      for (std::size_t i = 0; i < 8; ++i) {
        EXPECT_EQ(read_raw<double>(s, pos), m.vertices[i].x);
        EXPECT_EQ(read_raw<double>(s, pos), m.vertices[i].y);
        EXPECT_EQ(read_raw<double>(s, pos), 0.0);
      }
    } else if (k == 3) {
      for (std::size_t i = 0; i < 24; ++i) {
        EXPECT_EQ(read_raw<std::int32_t>(s, pos),
                  static_cast<std::int32_t>(m.triangles[i / 3][i % 3]));
      }
    } else if (k == 4) {
      for (std::int32_t i = 0; i < 8; ++i)
        EXPECT_EQ(read_raw<std::int32_t>(s, pos), 3 * (i + 1));
    } else {
      for (int i = 0; i < 8; ++i)
        EXPECT_EQ(read_raw<std::uint8_t>(s, pos), 5);
    }
    pos = start + bytes;
  }
  EXPECT_EQ(s.substr(pos), "\n  </AppendedData>\n</VTKFile>\n");
}

TEST(Vtu, MeshioReadsVtuAndPvtuPieces) {
  if (!pdd::test::python_has("meshio")) GTEST_SKIP() << "/usr/bin/python3 lacks meshio";
  const auto m = pdd::test::small_mesh();
  const auto dir = pdd::test::fresh_dir("vtu");
  pdd::write_vtu(dir / "mesh.vtu", m);
  const json j = meshio_read(dir, dir / "mesh.vtu");
  ASSERT_FALSE(j.is_null());
  expect_points(j, m);
  ASSERT_EQ(j["blocks"].size(), 1u);
  const json& b = j["blocks"][0];
  EXPECT_EQ(b["type"], "triangle");
  ASSERT_EQ(b["data"].size(), m.triangles.size());
  for (std::size_t t = 0; t < m.triangles.size(); ++t)
    for (std::size_t k = 0; k < 3; ++k)
      EXPECT_EQ(b["data"][t][k].get<std::size_t>(), m.triangles[t][k]);
  EXPECT_EQ(b["cell_data"]["subdomain"].get<std::vector<int>>(), m.triangle_markers);
  EXPECT_EQ(j["point_data"]["vertex_marker"].get<std::vector<int>>(), m.vertex_markers);

  // A .pvtu over two pieces (one per subdomain): valid XML, matching declarations; meshio reads
  // each piece.
  pdd::triangle_mesh piece = m;
  piece.triangles.resize(4);
  piece.triangle_markers.resize(4);
  std::filesystem::create_directory(dir / "pieces");
  pdd::write_vtu(dir / "pieces" / "part_0.vtu", piece);
  pdd::write_vtu(dir / "pieces" / "part&1.vtu", m);
  pdd::write_pvtu(dir / "all.pvtu", {"pieces/part_0.vtu", "pieces/part&1.vtu"});
  const char* check_pvtu = R"PY(
import json, os, sys
import xml.etree.ElementTree as ET
import meshio
root = ET.parse(sys.argv[1]).getroot()
g = root.find("PUnstructuredGrid")
out = {"type": root.get("type"),
       "point": [a.get("Name") + ":" + a.get("type") for a in g.find("PPointData")],
       "cell": [a.get("Name") + ":" + a.get("type") for a in g.find("PCellData")],
       "points": [a.get("type") + ":" + a.get("NumberOfComponents") for a in g.find("PPoints")],
       "pieces": [], "cells": []}
for p in g.findall("Piece"):
    out["pieces"].append(p.get("Source"))
    m = meshio.read(os.path.join(os.path.dirname(sys.argv[1]), p.get("Source")))
    out["cells"].append(len(m.cells[0].data))
    assert sorted(m.point_data.keys()) == ["vertex_marker"]
    assert sorted(m.cell_data.keys()) == ["subdomain"]
json.dump(out, open(sys.argv[2], "w"))
)PY";
  std::string log;
  ASSERT_EQ(pdd::test::run_python(dir, check_pvtu,
                                  "'" + (dir / "all.pvtu").string() + "' '" +
                                      (dir / "pvtu.json").string() + "'",
                                  log),
            0)
      << log;
  const json pv = json::parse(pdd::test::read_text(dir / "pvtu.json"));
  EXPECT_EQ(pv["type"], "PUnstructuredGrid");
  EXPECT_EQ(pv["point"], json::array({"vertex_marker:Int32"}));
  EXPECT_EQ(pv["cell"], json::array({"subdomain:Int32"}));
  EXPECT_EQ(pv["points"], json::array({"Float64:3"}));
  EXPECT_EQ(pv["pieces"], json::array({"pieces/part_0.vtu", "pieces/part&1.vtu"}));
  EXPECT_EQ(pv["cells"], json::array({4, 8}));
  EXPECT_THROW(pdd::write_pvtu(dir / "none.pvtu", {}), pdd::error);
}

TEST(Msh, Layout41) {
  const auto m = pdd::test::small_mesh();
  const auto p = pdd::test::temp_path("layout.msh");
  pdd::write_msh(p, m);
  const std::string s = pdd::test::read_text(p);
  EXPECT_EQ(s.rfind("$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$Entities\n", 0), 0u);
  // 0 points, 5 curves (markers 1 2 3 4 7), 2 surfaces (markers 0 1), 0 volumes.
  EXPECT_NE(s.find("$Entities\n0 5 2 0\n"), std::string::npos);
  EXPECT_NE(s.find("$Nodes\n1 8 1 8\n2 1 0 8\n1\n2\n"), std::string::npos);
  // 7 blocks, 8 triangles + 7 lines, tags 1..15.
  EXPECT_NE(s.find("$Elements\n7 15 1 15\n2 1 2 4\n1 1 2 7\n"), std::string::npos);
  EXPECT_NE(s.find("\n1 5 1 1\n15 2 5\n$EndElements\n"), std::string::npos); // marker 7 last
  // One surface when every triangle has the same marker.
  auto one = m;
  std::fill(one.triangle_markers.begin(), one.triangle_markers.end(), 0);
  one.segments.clear();
  pdd::write_msh(p, one);
  const std::string s1 = pdd::test::read_text(p);
  EXPECT_NE(s1.find("$Entities\n0 0 1 0\n1 0 0 0 2 1 0 1 0 0\n$EndEntities\n"), std::string::npos)
      << s1;
}

TEST(Msh, MeshioReadsPhysicalTagsAsMarkers) {
  if (!pdd::test::python_has("meshio")) GTEST_SKIP() << "/usr/bin/python3 lacks meshio";
  const auto m = pdd::test::small_mesh();
  const auto dir = pdd::test::fresh_dir("msh");
  pdd::write_msh(dir / "mesh.msh", m);
  const json j = meshio_read(dir, dir / "mesh.msh");
  ASSERT_FALSE(j.is_null());
  expect_points(j, m);
  using tri = std::tuple<std::size_t, std::size_t, std::size_t, int>;
  std::vector<tri> got_t, want_t;
  std::vector<tri> got_l, want_l;
  for (const json& b : j["blocks"]) {
    const auto phys = b["cell_data"]["gmsh:physical"].get<std::vector<int>>();
    ASSERT_EQ(phys.size(), b["data"].size());
    for (std::size_t i = 0; i < phys.size(); ++i) {
      const json& c = b["data"][i];
      if (b["type"] == "triangle")
        got_t.emplace_back(c[0].get<std::size_t>(), c[1].get<std::size_t>(),
                           c[2].get<std::size_t>(), phys[i]);
      else if (b["type"] == "line")
        got_l.emplace_back(c[0].get<std::size_t>(), c[1].get<std::size_t>(), 0, phys[i]);
      else
        ADD_FAILURE() << "unexpected cell type " << b["type"];
    }
  }
  for (std::size_t t = 0; t < m.triangles.size(); ++t)
    want_t.emplace_back(m.triangles[t][0], m.triangles[t][1], m.triangles[t][2],
                        m.triangle_markers[t]);
  for (const auto& e : m.segments)
    want_l.emplace_back(e.a, e.b, 0, e.marker);
  std::sort(got_t.begin(), got_t.end());
  std::sort(want_t.begin(), want_t.end());
  std::sort(got_l.begin(), got_l.end());
  std::sort(want_l.begin(), want_l.end());
  EXPECT_EQ(got_t, want_t);
  EXPECT_EQ(got_l, want_l);
}

TEST(Svg, PslgMeshAndHugeMesh) {
  const auto dir = pdd::test::fresh_dir("svg");
  pdd::pslg g;
  g.add_loop(std::vector<pdd::point>{{0, 0}, {4, 0}, {4, 2}, {0, 2}}, 1);
  g.add_loop(std::vector<pdd::point>{{1, 0.5}, {1, 1.5}, {2, 1.5}, {2, 0.5}}, 2);
  g.holes.push_back({1.5, 1});
  g.regions.push_back({{3, 1}, 1.0, 0.1});
  pdd::write_svg(dir / "g.svg", g);
  const std::string s = pdd::test::read_text(dir / "g.svg");
  EXPECT_NE(s.find("width=\"1000.00\" height=\"510.00\""), std::string::npos) << s.substr(0, 200);
  EXPECT_EQ(count_of(s, "<circle"), 9u);                            // 8 vertices + 1 region point
  EXPECT_EQ(count_of(path_data(s, "stroke=\"#ff0000\""), "M"), 2u); // one hole cross
  // y is flipped: model (0, 2) is the top-left pixel (10, 10).
  EXPECT_NE(s.find("L10.00 10.00"), std::string::npos);

  const auto m = pdd::test::small_mesh();
  pdd::write_svg(dir / "m.svg", m, g);
  const std::string ms = pdd::test::read_text(dir / "m.svg");
  EXPECT_EQ(count_of(path_data(ms, "stroke=\"#555555\""), "M"), 15u); // unique mesh edges
  EXPECT_EQ(count_of(ms, "stroke=\"none\""), 2u);                     // two subdomain fills

  pdd::svg_options small;
  small.max_triangles = 4;
  pdd::write_svg(dir / "huge.svg", m, small);
  const std::string hs = pdd::test::read_text(dir / "huge.svg");
  EXPECT_NE(hs.find("its subdomains are drawn filled"), std::string::npos);
  // each subdomain is one filled outline: the unit squares' 4 boundary edges each
  EXPECT_EQ(count_of(hs, "fill-rule=\"nonzero\""), 2u);
  EXPECT_EQ(count_of(path_data(hs, "fill-rule=\"nonzero\""), "L"), 4u);
  // the separator (edge 1-4), on the picture and in the automatic inset
  EXPECT_EQ(count_of(hs, "stroke=\"#000000\""), 2u);
  EXPECT_NE(hs.find("clip-path=\"url(#pdd-inset)\""), std::string::npos);
  EXPECT_NE(hs.find("inset: x "), std::string::npos);
  EXPECT_NE(hs.find("8 triangles, 8 vertices"), std::string::npos); // the legend
  EXPECT_NE(hs.find("2 subdomain(s)"), std::string::npos);

  if (pdd::test::python_has("xml.etree.ElementTree")) {
    std::string log;
    const char* parse = "import sys, xml.etree.ElementTree as ET\n"
                        "for f in sys.argv[1:]: ET.parse(f)\n";
    EXPECT_EQ(pdd::test::run_python(dir, parse,
                                    (dir / "g.svg").string() + " " + (dir / "m.svg").string() +
                                        " " + (dir / "huge.svg").string(),
                                    log),
              0)
        << log;
  }
}

TEST(Svg, Decomposition) {
  pdd::decomposition d;
  d.vertices = {{0, 0}, {1, 0},       {2, 0},       {2, 1},       {1, 1},
                {0, 1}, {1.25, 0.25}, {1.25, 0.75}, {1.75, 0.75}, {1.75, 0.25}};
  d.vertex_markers.assign(d.vertices.size(), 0);
  using k = pdd::edge_tag::kind;
  const pdd::edge_tag ext1{k::external, 0, 1, pdd::no_index};
  pdd::subdomain a, b;
  a.loops = {{0, 1, 4, 5}};
  a.tags = {{ext1, {k::interface, 0, 0, 1}, ext1, ext1}};
  b.loops = {{1, 2, 3, 4}, {6, 7, 8, 9}};
  b.tags = {{ext1, ext1, ext1, {k::interface, 0, 0, 0}},
            {{k::external, 1, 2, pdd::no_index},
             {k::external, 1, 2, pdd::no_index},
             {k::external, 1, 2, pdd::no_index},
             {k::external, 1, 2, pdd::no_index}}};
  d.subdomains = {a, b};
  d.interfaces = {{0, 1, {1, 4}}};
  const auto dir = pdd::test::fresh_dir("dec");
  pdd::write_svg(dir / "d.svg", d);
  const std::string s = pdd::test::read_text(dir / "d.svg");
  EXPECT_EQ(count_of(s, "fill-rule=\"evenodd\""), 2u);
  EXPECT_NE(pdd::detail::fill_colour(0), pdd::detail::fill_colour(1));
  EXPECT_NE(s.find(pdd::detail::fill_colour(0)), std::string::npos);
  EXPECT_NE(s.find(pdd::detail::fill_colour(1)), std::string::npos);
  EXPECT_EQ(count_of(path_data(s, "fill-rule"), "Z"), 1u);          // subdomain 0: one loop
  EXPECT_EQ(count_of(path_data(s, "stroke=\"#000000\""), "M"), 1u); // interface drawn once
  EXPECT_EQ(count_of(path_data(s, "stroke=\"" + pdd::detail::marker_colour(2) + "\""), "M"), 4u);

  // Broken decompositions are refused before a file is created.
  auto bad = d;
  bad.subdomains[0].loops[0][2] = 99;
  EXPECT_THROW(pdd::write_svg(dir / "bad.svg", bad), pdd::error);
  bad = d;
  bad.subdomains[1].tags[1].pop_back();
  EXPECT_THROW(pdd::write_svg(dir / "bad.svg", bad), pdd::error);
  EXPECT_EQ(pdd::test::dir_entries(dir), std::vector<std::string>{"d.svg"});
}

TEST(WriteMesh, DispatchesOnTheExtension) {
  const auto m = pdd::test::small_mesh();
  const auto dir = pdd::test::fresh_dir("dispatch");
  pdd::write_mesh(dir / "a.vtu", m);
  pdd::write_mesh(dir / "b.MSH", m);
  pdd::write_mesh(dir / "c.node", m);
  pdd::write_mesh(dir / "d.ele", m);
  pdd::write_mesh(dir / "e.svg", m);
  EXPECT_EQ(pdd::test::dir_entries(dir),
            (std::vector<std::string>{"a.vtu", "b.MSH", "c.ele", "c.node", "c.poly", "d.ele",
                                      "d.node", "d.poly", "e.svg"}));
  EXPECT_EQ(pdd::test::read_text(dir / "b.MSH").rfind("$MeshFormat", 0), 0u);
  try {
    pdd::write_mesh(dir / "f.xyz", m);
    ADD_FAILURE() << "no exception";
  } catch (const pdd::error& e) {
    const std::string msg = e.what();
    for (const char* ext : {".vtu", ".msh", ".node", ".ele", ".svg", ".xyz"})
      EXPECT_NE(msg.find(ext), std::string::npos) << msg;
  }
}

TEST(WriteMesh, InconsistentMeshesAreRefusedAndLeaveNoFile) {
  const auto dir = pdd::test::fresh_dir("inconsistent");
  auto m = pdd::test::small_mesh();
  m.triangles[3][1] = 99;
  for (const char* name : {"x.vtu", "x.msh", "x.node", "x.svg"})
    EXPECT_THROW(pdd::write_mesh(dir / name, m), pdd::error) << name;
  m = pdd::test::small_mesh();
  m.triangle_markers.pop_back();
  EXPECT_THROW(pdd::write_vtu(dir / "y.vtu", m), pdd::error);
  m = pdd::test::small_mesh();
  m.segments[0].b = 8;
  EXPECT_THROW(pdd::write_msh(dir / "z.msh", m), pdd::error);
  EXPECT_TRUE(pdd::test::dir_entries(dir).empty());
}

TEST(WriteMesh, EmptyMarkersAreZeros) {
  auto m = pdd::test::small_mesh();
  m.vertex_markers.clear();
  m.triangle_markers.clear();
  const auto dir = pdd::test::fresh_dir("nomarkers");
  pdd::write_triangle_files(dir / "m.node", m);
  const auto g = pdd::read_poly(dir / "m.poly");
  EXPECT_EQ(g.vertex_markers, std::vector<int>(8, 0));
  pdd::write_msh(dir / "m.msh", m);
  EXPECT_NE(pdd::test::read_text(dir / "m.msh").find("$Entities\n0 5 1 0\n"), std::string::npos);
}

// Region attributes (pdd-mesh -A): the .vtu's cell data "region_attribute" (Float64, after
// "subdomain"), the .msh's physical tags (surfaces by attribute), the .ele's attribute column.
TEST(RegionAttributeWriters, VtuCellDataBlock) {
  const auto m = pdd::test::small_mesh();
  const std::vector<double> attr = {1.5, 1.5, 1.5, 1.5, -2, -2, -2, 0.25};
  const auto p = pdd::test::temp_path("regions.vtu");
  pdd::write_vtu(p, m, attr);
  const std::string s = pdd::test::read_text(p);
  const std::size_t name = s.find("Name=\"region_attribute\"");
  ASSERT_NE(name, std::string::npos);
  EXPECT_LT(s.find("Name=\"subdomain\""), name);
  EXPECT_LT(name, s.find("</CellData>"));
  EXPECT_EQ(s.rfind("<DataArray type=\"Float64\"", name), s.rfind("<DataArray", name));
  // the blocks in order, each where its offset says; the region block is the third
  const std::size_t base = s.find('_', s.find("<AppendedData")) + 1;
  const std::vector<std::uint64_t> offsets = xml_offsets(s, base);
  ASSERT_EQ(offsets.size(), 7u);
  const std::uint64_t sizes[] = {8 * 4, 8 * 4, 8 * 8, 8 * 24, 24 * 4, 8 * 4, 8};
  std::size_t pos = base;
  for (std::size_t k = 0; k < 7; ++k) {
    EXPECT_EQ(pos - base, offsets[k]) << "block " << k;
    const auto bytes = read_raw<std::uint64_t>(s, pos);
    EXPECT_EQ(bytes, sizes[k]) << "block " << k;
    if (k == 2) {
      for (std::size_t t = 0; t < 8; ++t)
        EXPECT_EQ(read_raw<double>(s, pos), attr[t]) << t;
    }
    pos = offsets[k] + base + 8 + bytes;
  }
  EXPECT_EQ(s.substr(pos), "\n  </AppendedData>\n</VTKFile>\n");
  // without attributes the file is the one write_vtu always wrote
  pdd::write_vtu(p, m);
  EXPECT_EQ(pdd::test::read_text(p).find("region_attribute"), std::string::npos);
}

TEST(RegionAttributeWriters, MshSurfacesByAttributeAndEleColumn) {
  const auto m = pdd::test::small_mesh();
  const std::vector<double> attr = {5, 5, 5, -3, -3, -3, 5, 5};
  const auto p = pdd::test::temp_path("regions.msh");
  pdd::write_msh(p, m, attr);
  const std::string s = pdd::test::read_text(p);
  // 5 curves (segment markers), 2 surfaces: attribute -3 (tag 1) and 5 (tag 2)
  EXPECT_NE(s.find("$Entities\n0 5 2 0\n"), std::string::npos) << s;
  EXPECT_NE(s.find(" 0 1 -3 0\n"), std::string::npos) << s;
  EXPECT_NE(s.find(" 0 1 5 0\n"), std::string::npos) << s;
  EXPECT_NE(s.find("\n2 1 2 3\n4 "), std::string::npos) << s; // surface 1: triangles 4..6
  EXPECT_NE(s.find("\n2 2 2 5\n1 "), std::string::npos) << s; // surface 2: 1..4, 7, 8
  // the .ele's attribute column
  const auto node = pdd::test::temp_path("regions.node");
  pdd::write_mesh(node, m, attr);
  std::istringstream ele(pdd::test::read_text(pdd::test::temp_path("regions.ele")));
  std::size_t n = 0, corners = 0, columns = 0;
  ele >> n >> corners >> columns;
  ASSERT_EQ(n, 8u);
  ASSERT_EQ(columns, 1u);
  for (std::size_t t = 0; t < n; ++t) {
    std::size_t id = 0, a = 0, b = 0, c = 0;
    double value = 0;
    ele >> id >> a >> b >> c >> value;
    EXPECT_EQ(value, attr[t]) << t;
  }
}

TEST(RegionAttributeWriters, RefusedWhereTheyCannotBeWrittenAndNoFileIsLeft) {
  const auto m = pdd::test::small_mesh();
  const auto dir = pdd::test::fresh_dir("region_refusals");
  const std::vector<double> half = {1, 2, 3, 4, 5, 6, 7, 8.5};
  EXPECT_THROW(pdd::write_msh(dir / "a.msh", m, half), pdd::error); // 8.5: no physical tag
  try {
    pdd::write_msh(dir / "a.msh", m, half);
  } catch (const pdd::error& e) {
    EXPECT_NE(std::string(e.what()).find("8.5"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("triangle 7"), std::string::npos) << e.what();
  }
  const std::vector<double> three = {1, 2, 3};
  EXPECT_THROW(pdd::write_vtu(dir / "b.vtu", m, three), pdd::error); // not one per triangle
  EXPECT_THROW(pdd::write_mesh(dir / "c.ele", m, three), pdd::error);
  const std::vector<double> ok(m.triangles.size(), 1.0);
  EXPECT_THROW(pdd::write_mesh(dir / "d.svg", m, ok), pdd::error); // an .svg cannot show them
  EXPECT_TRUE(pdd::test::dir_entries(dir).empty());
}

} // namespace mesh_writers_test
