// pdd::cgal::mesher on domains of Triangle's rule (pslg::rule, issue 13): internal constraints
// keep both faces, isolated vertices become mesh vertices, and a constraint pair at an angle
// too small for double precision is refused with a meshing_error, never a corrupt triangulation.
#include <pdd/io/poly.hpp>
#include <pdd/kernels/cgal/mesher.hpp>
#include <pdd/mesh/cluster_exempt.hpp>
#include <pdd/mesh/verify.hpp>
#include <pdd/sizing/uniform.hpp>

#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

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

TEST(CgalMesherTriangleRule, UnresolvableAngleIsAMeshingError) {
  // a random arrangement (tests/common/general_domains.hpp, seed 7, before its 10 deg filter):
  // two segments leave the vertex (1, 0.168) at about 0.2 deg and cross the whole square
  std::istringstream in(R"(# pdd .poly: vertices <#> <dim> <#attributes> <#markers>
21 2 0 1
1 0 0 0
2 0.16820172248941206 0 0
3 0.695691668343259 0 0
4 1 0 0
5 1 0.16820172248941206 0
6 1 0.695691668343259 0
7 1 1 0
8 0.695691668343259 1 0
9 0.16820172248941206 1 0
10 0 1 0
11 0 0.695691668343259 0
12 0 0.16820172248941206 0
13 0.22681582160233213 0.25735874195924735 0
14 0.1716645008941692 0.3504092122288734 0
15 0.1722126783361483 0.5999858998232309 0
16 0.3797007097994091 0.38715307713619274 0
17 0.37457747206113295 0.6491512232554792 0
18 0.3815167528171107 0.8515433827913961 0
19 0.630091527254085 0.3705872874781643 0
20 0.5608863314584913 0.8348916207593444 0
21 0.7559803333674827 0.2028095094333075 0
# segments <#> <#markers>
19 1
1 1 2 0
2 2 3 0
3 3 4 0
4 4 5 0
5 5 6 0
6 6 7 0
7 7 8 0
8 8 9 0
9 9 10 0
10 10 11 0
11 11 12 0
12 12 1 0
13 15 5 0
14 5 11 0
15 11 13 0
16 8 20 0
17 11 8 0
18 8 6 0
19 13 3 0
# holes
0
)");
  pdd::pslg g = pdd::parse_poly(in, "seed7.poly", "");
  g.rule = pdd::domain_rule::triangle;
  try {
    (void)pdd::cgal::mesher{}.mesh(g, criteria(0.005), pdd::uniform_sizing{});
    ADD_FAILURE() << "meshed";
  } catch (const pdd::meshing_error& e) {
    EXPECT_NE(std::string(e.what()).find("cannot be split"), std::string::npos) << e.what();
  }
}

} // namespace
