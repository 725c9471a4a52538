// pdd::cgal::mesher on domains of Triangle's rule (pslg::rule, issue 13): internal constraints
// keep both faces, isolated vertices become mesh vertices, a constraint pair at a sub-degree
// angle is meshed and verifies, and one at an angle too small for double precision is refused
// with an unresolvable_input_error, never a corrupt triangulation.
#include <pdd/generate.hpp>
#include <pdd/kernels/cgal/mesher.hpp>
#include <pdd/mesh/cluster_exempt.hpp>
#include <pdd/mesh/verify.hpp>
#include <pdd/sizing/uniform.hpp>

#include <gtest/gtest.h>

#include "general_domains.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <string>
#include <vector>

namespace triangle_rule_test {
namespace {

pdd::mesh_criteria criteria(double max_area) {
  pdd::mesh_criteria c;
  c.min_angle_deg = 20.7;
  c.max_area = max_area;
  return c;
}

TEST(CgalMesherTriangleRule, InternalConstraintKeepsBothFaces) {
  pdd::pslg g;
  g.add_loop(std::vector<pdd::point>{{0, 0}, {4, 0}, {4, 4}, {0, 4}});
  g.add_loop(std::vector<pdd::point>{{1, 1}, {3, 1}, {3, 3}, {1, 3}}); // no hole point
  g.add_segment(0, 4); // corner to inner corner: an internal constraint, degree 3 at both ends
  const pdd::index_t well = g.add_vertex({0.5, 3});
  const auto odd = pdd::cgal::mesher{}.mesh(g, criteria(0.1), pdd::uniform_sizing{});
  g.rule = pdd::domain_rule::triangle;
  const auto all = pdd::cgal::mesher{}.mesh(g, criteria(0.1), pdd::uniform_sizing{});
  // odd nesting: the inner square is a hole; Triangle's rule: an internal boundary, meshed
  EXPECT_GT(all.mesh.triangles.size(), odd.mesh.triangles.size() * 6 / 5);
  pdd::verify_options vo;
  vo.criteria = criteria(0.1);
  vo.quality_exempt = pdd::find_cluster_exempt_triangles(all.mesh, g, 20.7); // 45 deg at (0, 0)
  const pdd::verification_report r = pdd::verify(all.mesh, g, vo);
  EXPECT_TRUE(r.ok()) << (r.messages.empty() ? "" : r.messages.front());
  EXPECT_NEAR(r.area_mesh, 16.0, 1e-12);
  bool used = false;
  for (const auto& t : all.mesh.triangles)
    for (const pdd::index_t v : t)
      used = used || v == well;
  EXPECT_TRUE(used);
}

TEST(CgalMesherTriangleRule, UnresolvableAngleIsAnUnresolvableInputError) {
  // two segments leave (0, 0.3) at about 2e-16 rad and cross the whole square: an input limit
  // (its own class and exit code), not a kernel failure
  const pdd::pslg g = pdd::test::unresolvable_angle_domain();
  try {
    (void)pdd::cgal::mesher{}.mesh(g, criteria(0.005), pdd::uniform_sizing{});
    ADD_FAILURE() << "meshed";
  } catch (const pdd::unresolvable_input_error& e) {
    EXPECT_NE(std::string(e.what()).find("cannot be split"), std::string::npos) << e.what();
    EXPECT_EQ(e.subdomain(), -1);
  }
  // through pdd::generate (the whole domain, subdomain 0): the class is kept
  pdd::generate_options o;
  o.criteria = criteria(0.005);
  try {
    (void)pdd::generate(g, o);
    ADD_FAILURE() << "meshed";
  } catch (const pdd::unresolvable_input_error& e) {
    EXPECT_NE(std::string(e.what()).find("cannot be split"), std::string::npos) << e.what();
  }
}

// Two segments leave the vertex (1, 0.168) at about 0.2 deg and cross the whole square (this
// domain was refused as unresolvable while the kernel refined at circumcentres): meshed, and it
// verifies with the cluster rule's exemption at that angle and nowhere else.
TEST(CgalMesherTriangleRule, ASubDegreeAngleIsMeshedAndVerifies) {
  const pdd::pslg g = pdd::test::sub_degree_angle_domain();
  const auto r = pdd::cgal::mesher{}.mesh(g, criteria(0.005), pdd::uniform_sizing{});
  pdd::verify_options vo;
  vo.criteria = criteria(0.005);
  vo.quality_exempt = pdd::find_cluster_exempt_triangles(r.mesh, g, 20.7);
  const pdd::verification_report report = pdd::verify(r.mesh, g, vo);
  EXPECT_TRUE(report.ok()) << (report.messages.empty() ? "" : report.messages.front());
  EXPECT_NEAR(report.area_mesh, 1.0, 1e-12);
  const auto exempt = std::count(vo.quality_exempt->begin(), vo.quality_exempt->end(), 1);
  EXPECT_GT(exempt, 0);
  EXPECT_LT(exempt, static_cast<std::ptrdiff_t>(r.mesh.triangles.size() / 10));
}

} // namespace

namespace {

/// A closed triangle with a small angle at corner 0 and one dangling segment from that corner
/// to `out` (a point outside the triangle).
pdd::pslg corner_with_outside_segment(pdd::point a, pdd::point b, pdd::point c, pdd::point out) {
  pdd::pslg g;
  g.add_loop(std::vector<pdd::point>{a, b, c});
  g.add_segment(0, g.add_vertex(out));
  g.rule = pdd::domain_rule::triangle;
  return g;
}

} // namespace

TEST(CgalMesherTriangleRule, DanglingSegmentOutsideASmallAngleIsLeftOut) {
  // fuzz findings (tests/fuzz): a dangling segment outside the domain that made a cluster with
  // a domain corner below 20.7 deg was never split, the cluster never reduced, and the corner's
  // bad faces were refined without end (3 GB in 8 s, a hang, or a sub-degree meshing_error).
  // Triangle 1.6 -pq20.7 meshes the first with 8 triangles.
  const std::vector<pdd::pslg> cases = {
      corner_with_outside_segment({1, 0}, {-1, 0}, {0.5, -0.15}, {0.5, 0.15}),
      corner_with_outside_segment({1, 0}, {-1, 0}, {0.5, -0.15}, {0, 0.5}),
      corner_with_outside_segment({6, 0}, {2, 1}, {0, 1}, {0, 0}),
  };
  for (std::size_t k = 0; k < cases.size(); ++k) {
    SCOPED_TRACE("case " + std::to_string(k));
    const pdd::pslg& g = cases[k];
    for (const double area : {std::numeric_limits<double>::infinity(), 0.01}) {
      const auto r = pdd::cgal::mesher{}.mesh(g, criteria(area), pdd::uniform_sizing{});
      EXPECT_LT(r.mesh.triangles.size(), std::isinf(area) ? 200u : 20000u);
      pdd::verify_options vo;
      vo.criteria = criteria(area);
      vo.quality_exempt = pdd::find_cluster_exempt_triangles(r.mesh, g, 20.7);
      const pdd::verification_report rep = pdd::verify(r.mesh, g, vo);
      EXPECT_TRUE(rep.ok()) << (rep.messages.empty() ? "" : rep.messages.front());
      for (const pdd::mesh_edge& e : r.mesh.segments) // the outside segment is not in the mesh
        EXPECT_FALSE((e.a == 0 && e.b == 3) || (e.a == 3 && e.b == 0));
    }
  }
  // the same segment inside the domain (a dangling crack into the corner) is kept
  pdd::pslg inside = corner_with_outside_segment({1, 0}, {-1, 0}, {0.5, -0.15}, {0.2, -0.05});
  const auto r = pdd::cgal::mesher{}.mesh(inside, criteria(0.01), pdd::uniform_sizing{});
  bool kept = false;
  for (const pdd::mesh_edge& e : r.mesh.segments)
    kept = kept || (std::min(e.a, e.b) == 0 && std::max(e.a, e.b) >= 3);
  EXPECT_TRUE(kept);
}

} // namespace triangle_rule_test
