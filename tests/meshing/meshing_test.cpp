// Tests of the parallel decoupled meshing (dissertation 6.4): every subdomain of hand-made
// decompositions meshed with pdd::cgal::mesher on the sequential and TBB executors, merged,
// verified (Delaunay across interfaces, conformity, area, quality), bitwise identical across
// executors and thread counts; the file and counting sinks; the invariance repair; errors.
#include "hand_decompositions.hpp"

#include <pdd/decoupling/decouple.hpp>
#include <pdd/kernels/cgal/mesher.hpp>
#include <pdd/madd/validate_decomposition.hpp>
#include <pdd/mesh/merge.hpp>
#include <pdd/mesh/quality.hpp>
#include <pdd/mesh/sinks.hpp>
#include <pdd/mesh/verify.hpp>
#include <pdd/meshing/mesh_subdomains.hpp>
#include <pdd/parallel/sequential_executor.hpp>
#include <pdd/parallel/tbb_executor.hpp>

#include "mesh_compare.hpp"
#include "recording_sink.hpp"
#include "test_files.hpp"
#include "test_support.hpp"
#include "verified.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <mutex>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace meshing_test {
namespace {

using pdd::index_t;
using pdd::point;
using pdd::test::hand_case;

using pdd::test::recording_sink;
using pdd::test::tee_sink;

struct run_result {
  pdd::triangle_mesh mesh;
  pdd::meshing_statistics stats;
  double k = 0;
};

template <class E, class M = pdd::cgal::mesher>
run_result run(const hand_case& c, const pdd::mesh_criteria& criteria, const E& ex,
               unsigned merge_threads, pdd::decoupling_options dopt = {}, unsigned max_repairs = 3,
               const M& mesher = {}) {
  dopt.criteria = criteria;
  auto dd = pdd::decouple(c.parts, dopt, ex);
  pdd::merge_sink sink(merge_threads);
  run_result r;
  r.k = dd.k;
  r.stats = pdd::mesh_subdomains(dd, {criteria, max_repairs}, mesher, ex, sink);
  r.mesh = sink.take();
  return r;
}

using pdd::test::bitwise_equal;

void expect_valid(const pdd::triangle_mesh& m, const hand_case& c,
                  const pdd::mesh_criteria& criteria) {
  pdd::test::expect_verified(m, c.domain, criteria);
  EXPECT_EQ(m.triangle_markers.size(), m.triangles.size());
  // Merged segments are the input boundary only: no interface piece survives the merge.
  for (const auto& e : m.segments)
    EXPECT_NE(e.marker, pdd::interface_marker);
}

struct named_case {
  const char* name;
  hand_case c;
  std::size_t subdomains;
};

std::vector<named_case> cases() {
  return {{"grid 2x1", pdd::test::grid_case(2, 1), 2},
          {"grid 2x2", pdd::test::grid_case(2, 2), 4},
          {"grid 4x4", pdd::test::grid_case(4, 4), 16},
          {"rectangle 3x2", pdd::test::grid_case(3, 2, 3.0, 1.0), 6},
          {"annulus 4", pdd::test::annulus_case(), 4}};
}

TEST(DecoupledMeshing, MergedMeshVerifiesAndIsIdenticalAcrossExecutors) {
  pdd::mesh_criteria criteria;
  for (const auto& [name, c, n] : cases()) {
    SCOPED_TRACE(name);
    // The hand-made decomposition is well formed (orientation, tags, angles, areas).
    const auto check = pdd::validate_decomposition(c.parts, c.domain);
    ASSERT_TRUE(check.ok()) << check.summary();
    criteria.max_area = name == std::string("rectangle 3x2") ? 6e-4 : 2e-4;
    const run_result seq = run(c, criteria, pdd::sequential_executor{}, 1);
    ASSERT_EQ(seq.stats.subdomains.size(), n);
    EXPECT_EQ(seq.stats.interface_splits, 0u);
    EXPECT_EQ(seq.stats.remeshed_subdomains, 0u);
    EXPECT_EQ(seq.stats.triangles(), seq.mesh.triangles.size());
    for (const auto& s : seq.stats.subdomains)
      EXPECT_EQ(s.runs, 1u);
    expect_valid(seq.mesh, c, criteria);
    for (std::size_t t = 0; t < seq.mesh.triangles.size(); ++t)
      ASSERT_LT(static_cast<std::size_t>(seq.mesh.triangle_markers[t]), n);

    // The monolithic kernel mesh for comparison: decoupling over-refines only a little.
    const auto mono = pdd::cgal::mesher{}.mesh(c.domain, criteria, pdd::uniform_sizing{});
    EXPECT_LT(static_cast<double>(seq.mesh.triangles.size()),
              1.10 * static_cast<double>(mono.mesh.triangles.size()));

    for (unsigned threads : {1u, 2u}) {
      const run_result par = run(c, criteria, pdd::tbb_executor{threads}, threads);
      EXPECT_TRUE(bitwise_equal(seq.mesh, par.mesh)) << "tbb threads " << threads;
    }
    const run_result mixed = run(c, criteria, pdd::tbb_executor{2}, 1);
    EXPECT_TRUE(bitwise_equal(seq.mesh, mixed.mesh));
  }
}

TEST(DecoupledMeshing, WithoutAreaBound) {
  // Proposition 12: only the ratio criterion; k = min(lfs_min, L / 4).
  const auto c = pdd::test::annulus_case();
  const pdd::mesh_criteria criteria;
  const run_result r = run(c, criteria, pdd::sequential_executor{}, 1);
  EXPECT_EQ(r.stats.interface_splits, 0u);
  const pdd::verification_report rep = pdd::verify(r.mesh, c.domain, {.criteria = criteria});
  EXPECT_TRUE(rep.ok());
}

TEST(DecoupledMeshing, InterfaceVerticesSharedBitwise) {
  // Each interface vertex of a subdomain mesh appears bitwise in the neighbour's mesh.
  const auto c = pdd::test::grid_case(2, 2);
  pdd::mesh_criteria criteria;
  criteria.max_area = 5e-4;
  auto dd = pdd::decouple(c.parts, {criteria});
  recording_sink rec;
  pdd::mesh_subdomains(dd, {criteria}, pdd::cgal::mesher{}, pdd::tbb_executor{2}, rec);
  EXPECT_TRUE(rec.finished);
  ASSERT_EQ(rec.meshes.size(), 4u);
  for (const auto& e : dd.path) {
    const auto& ma = rec.meshes[e.sides[0]];
    const auto& mb = rec.meshes[e.sides[1]];
    std::vector<point> pa, pb;
    for (const auto& seg : ma.segments)
      if (seg.marker == pdd::interface_marker) pa.push_back(ma.vertices[seg.a]);
    for (const auto& seg : mb.segments)
      if (seg.marker == pdd::interface_marker) pb.push_back(mb.vertices[seg.a]);
    std::sort(pa.begin(), pa.end());
    std::sort(pb.begin(), pb.end());
    std::size_t common = 0;
    for (const point& p : pa)
      common += std::binary_search(pb.begin(), pb.end(), p);
    EXPECT_GE(common, static_cast<std::size_t>(e.pieces) - 1);
  }
}

TEST(DecoupledMeshing, MergeIndependentOfDeliveryOrder) {
  const auto c = pdd::test::grid_case(4, 4);
  pdd::mesh_criteria criteria;
  criteria.max_area = 1e-3;
  auto dd = pdd::decouple(c.parts, {criteria});
  recording_sink rec;
  pdd::mesh_subdomains(dd, {criteria}, pdd::cgal::mesher{}, pdd::sequential_executor{}, rec);
  const auto merged_in_order = [&](std::vector<index_t> order, unsigned threads) {
    pdd::merge_sink sink(threads);
    for (index_t id : order)
      sink.consume(id, pdd::triangle_mesh(rec.meshes[id]));
    sink.finish();
    return sink.take();
  };
  std::vector<index_t> forward, backward;
  for (index_t i = 0; i < 16; ++i)
    forward.push_back(i);
  backward.assign(forward.rbegin(), forward.rend());
  const auto a = merged_in_order(forward, 1);
  const auto b = merged_in_order(backward, 2);
  EXPECT_TRUE(bitwise_equal(a, b));
  expect_valid(a, c, criteria);
  // Vertex count: parts minus each shared vertex's extra copies.
  std::size_t parts = 0;
  for (const auto& [id, m] : rec.meshes)
    parts += m.vertices.size();
  EXPECT_LT(a.vertices.size(), parts);
}

TEST(DecoupledMeshing, InvarianceRepairCatchesAndFixesTooLongPieces) {
  // k far above Theorem 15's value: the pieces are longer than the kernel's edges, so it
  // splits them. The check must catch that, re-split the segments with k / 2, re-mesh both
  // sides, and deliver only conforming meshes.
  const auto c = pdd::test::grid_case(2, 2);
  pdd::mesh_criteria criteria;
  criteria.max_area = 1e-3;
  pdd::decoupling_options dopt;
  dopt.k_override = 0.06; // Theorem 15 gives 0.0133
  for (const unsigned threads : {1u, 2u}) {
    const run_result r = run(c, criteria, pdd::tbb_executor{threads}, threads, dopt, 6);
    EXPECT_GT(r.stats.interface_splits, 0u);
    EXPECT_GT(r.stats.remeshed_subdomains, 0u);
    EXPECT_GT(r.stats.repair_rounds, 0u);
    expect_valid(r.mesh, c, criteria);
    const run_result s = run(c, criteria, pdd::sequential_executor{}, 1, dopt, 6);
    EXPECT_TRUE(bitwise_equal(r.mesh, s.mesh));
    EXPECT_EQ(r.stats.interface_splits, s.stats.interface_splits);
  }
  // Without repairs the same run refuses to deliver a non-conforming mesh.
  auto dd = pdd::decouple(c.parts, {.criteria = criteria, .k_override = 0.06});
  recording_sink rec;
  EXPECT_THROW(
      pdd::mesh_subdomains(dd, {criteria, 0}, pdd::cgal::mesher{}, pdd::sequential_executor{}, rec),
      pdd::decoupling_error);
  EXPECT_FALSE(rec.finished);
  // Every mesh that did reach the sink kept all its interface pieces.
  for (const auto& [id, m] : rec.meshes) {
    const auto in = dd.input(id);
    std::size_t pieces = 0, kept = 0;
    for (const auto p : in.segment_path_edge)
      pieces += p != pdd::no_index;
    for (const auto& e : m.segments)
      kept += e.marker == pdd::interface_marker;
    EXPECT_EQ(kept, pieces);
  }
}

/// A kernel that fails on the subdomain containing a given vertex.
struct failing_mesher {
  point trigger;
  template <pdd::SizingField S>
  pdd::mesher_result mesh(const pdd::pslg& d, const pdd::mesh_criteria& c, const S& s) const {
    for (const point& p : d.vertices)
      if (p == trigger) throw std::runtime_error("kernel exploded");
    return pdd::cgal::mesher{}.mesh(d, c, s);
  }
};
static_assert(pdd::DelaunayMesher<failing_mesher>);

TEST(DecoupledMeshing, KernelErrorsCarryTheSubdomainId) {
  const auto c = pdd::test::grid_case(4, 4);
  pdd::mesh_criteria criteria;
  criteria.max_area = 1e-2;
  // Vertex (0.75, 0.75) belongs to cells 10, 11, 14, 15; the smallest id is reported.
  const failing_mesher bad{{0.75, 0.75}};
  const auto expect_id = [&](const auto& ex) {
    try {
      run(c, criteria, ex, 1, {}, 3, bad);
      FAIL() << "no exception";
    } catch (const pdd::meshing_error& e) {
      EXPECT_EQ(e.subdomain(), 10);
      EXPECT_NE(std::string(e.what()).find("kernel exploded"), std::string::npos);
    }
  };
  expect_id(pdd::sequential_executor{});
  expect_id(pdd::tbb_executor{1});
  expect_id(pdd::tbb_executor{2});
  // The kernel's own meshing_error(-1, ...) gets the id too: minimum angle out of range.
  pdd::mesh_criteria wrong = criteria;
  auto dd = pdd::decouple(c.parts, {criteria});
  wrong.min_angle_deg = 70;
  pdd::counting_sink count;
  try {
    pdd::mesh_subdomains(dd, {wrong}, pdd::cgal::mesher{}, pdd::tbb_executor{2}, count);
    FAIL() << "no exception";
  } catch (const pdd::meshing_error& e) {
    EXPECT_EQ(e.subdomain(), 0);
  }
}

TEST(Sinks, CountingSink) {
  const auto c = pdd::test::annulus_case();
  pdd::mesh_criteria criteria;
  criteria.max_area = 1e-3;
  auto dd = pdd::decouple(c.parts, {criteria});
  pdd::counting_sink count;
  const auto st =
      pdd::mesh_subdomains(dd, {criteria}, pdd::cgal::mesher{}, pdd::tbb_executor{2}, count);
  ASSERT_EQ(count.pieces().size(), 4u);
  EXPECT_EQ(count.triangles(), st.triangles());
  for (index_t s = 0; s < 4; ++s) {
    EXPECT_TRUE(count.pieces()[s].delivered);
    EXPECT_EQ(count.pieces()[s].triangles, st.subdomains[s].triangles);
    EXPECT_EQ(count.pieces()[s].vertices, st.subdomains[s].vertices);
  }
  static_assert(!pdd::sink_retains_meshes<pdd::counting_sink>);
  static_assert(!pdd::sink_retains_meshes<pdd::vtu_directory_sink>);
  static_assert(pdd::sink_retains_meshes<pdd::merge_sink>);
  static_assert(pdd::sink_retains_meshes<recording_sink>);
}

TEST(Sinks, VtuDirectorySinkWritesEveryPiece) {
  const auto c = pdd::test::grid_case(2, 2);
  pdd::mesh_criteria criteria;
  criteria.max_area = 2e-3;
  auto dd = pdd::decouple(c.parts, {criteria});
  const auto dir = pdd::test::temp_path("pieces");
  std::filesystem::remove_all(dir);
  recording_sink rec;
  pdd::vtu_directory_sink files(dir);
  tee_sink<recording_sink, pdd::vtu_directory_sink> tee{rec, files};
  pdd::mesh_subdomains(dd, {criteria}, pdd::cgal::mesher{}, pdd::tbb_executor{2}, tee);
  ASSERT_TRUE(std::filesystem::exists(files.index_path()));
  ASSERT_EQ(files.pieces().size(), 4u);
  for (index_t s = 0; s < 4; ++s) {
    EXPECT_TRUE(std::filesystem::exists(dir / pdd::vtu_directory_sink::piece_name(s)));
    EXPECT_EQ(files.pieces()[s].triangles, rec.meshes[s].triangles.size());
  }
  // The delivered meshes merge to the same mesh as a merge_sink run.
  std::vector<pdd::triangle_mesh> parts;
  for (auto& [id, m] : rec.meshes)
    parts.push_back(m);
  const auto merged = pdd::merge_meshes(std::move(parts), 2);
  auto dd2 = pdd::decouple(c.parts, {criteria});
  pdd::merge_sink ms(1);
  pdd::mesh_subdomains(dd2, {criteria}, pdd::cgal::mesher{}, pdd::sequential_executor{}, ms);
  EXPECT_TRUE(bitwise_equal(merged, ms.mesh()));

  // Read the pieces back with an independent reader (meshio) and compare bit for bit.
  if (!pdd::test::python_has("meshio"))
    GTEST_SKIP() << "/usr/bin/python3 with meshio is not available";
  const auto dump = dir / "dump.txt";
  std::string log;
  ASSERT_EQ(
      pdd::test::run_python(
          dir,
          "import meshio, re, sys\n"
          "d = sys.argv[1]\n"
          "src = re.findall(r'Source=\"([^\"]+)\"', open(d + '/mesh.pvtu').read())\n"
          "out = open(sys.argv[2], 'w')\n"
          "for f in src:\n"
          "    m = meshio.read(d + '/' + f)\n"
          "    tri = m.get_cells_type('triangle')\n"
          "    sub = m.cell_data['subdomain'][0]\n"
          "    out.write('%s %d %d %d\\n' % (f, len(m.points), len(tri), int(sub[0])))\n"
          "    for p in m.points: out.write('%s %s\\n' % (float(p[0]).hex(), float(p[1]).hex()))\n"
          "    for t in tri: out.write('%d %d %d\\n' % tuple(t))\n",
          "'" + dir.string() + "' '" + dump.string() + "'", log),
      0)
      << log;
  std::ifstream in(dump);
  for (index_t s = 0; s < 4; ++s) {
    std::string name;
    std::size_t nv = 0, nt = 0;
    int marker = -1;
    ASSERT_TRUE(in >> name >> nv >> nt >> marker);
    EXPECT_EQ(name, pdd::vtu_directory_sink::piece_name(s));
    const auto& m = rec.meshes[s];
    ASSERT_EQ(nv, m.vertices.size());
    ASSERT_EQ(nt, m.triangles.size());
    EXPECT_EQ(marker, static_cast<int>(s));
    for (std::size_t v = 0; v < nv; ++v) {
      std::string hx, hy;
      in >> hx >> hy;
      ASSERT_EQ(std::strtod(hx.c_str(), nullptr), m.vertices[v].x);
      ASSERT_EQ(std::strtod(hy.c_str(), nullptr), m.vertices[v].y);
    }
    for (std::size_t t = 0; t < nt; ++t) {
      index_t a, b, cc;
      in >> a >> b >> cc;
      ASSERT_EQ(a, m.triangles[t][0]);
      ASSERT_EQ(b, m.triangles[t][1]);
      ASSERT_EQ(cc, m.triangles[t][2]);
    }
  }
}

TEST(DecoupledMeshing, RepairFailuresListTheFirstEightAndSayWhyAboveRupperts) {
  pdd::decoupled_decomposition dd;
  for (pdd::index_t e = 0; e < 12; ++e) {
    pdd::path_edge pe;
    pe.u = e;
    pe.v = e + 1;
    pe.k = 0.5;
    dd.path.push_back(pe);
  }
  const std::map<pdd::index_t, std::vector<pdd::index_t>> failures{{3, {0, 1, 2, 3, 4}},
                                                                   {7, {5, 6, 7, 8, 9, 10, 11}}};
  pdd::mesh_criteria c;
  const std::string at = pdd::describe_path_failures(dd, failures, c);
  EXPECT_NE(at.find("subdomain 3, separator segment 0-1 (k 0.500000)"), std::string::npos) << at;
  EXPECT_NE(at.find("subdomain 7, separator segment 7-8"), std::string::npos) << "the eighth";
  EXPECT_EQ(at.find("separator segment 8-9"), std::string::npos) << "the ninth is counted only";
  EXPECT_NE(at.find("; and 4 more"), std::string::npos) << at;
  EXPECT_EQ(at.find("Ruppert"), std::string::npos) << "20.7 deg: the path is proven";
  c.min_angle_deg = 34.0;
  const std::string above = pdd::describe_path_failures(dd, failures, c);
  EXPECT_NE(above.find("angle bound is 34 deg: mesh the domain whole"), std::string::npos) << above;
}

} // namespace

} // namespace meshing_test
