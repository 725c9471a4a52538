// pdd::verify on domains of Triangle's rule (issue 13): isolated input vertices inside the
// domain must be mesh vertices, internal constraints unions of mesh edges, the area that of the
// faces (an internal boundary's inside counts).
#include <pdd/generate.hpp>
#include <pdd/mesh/verify.hpp>

#include <gtest/gtest.h>

#include <vector>

namespace {

pdd::pslg square() {
  pdd::pslg g;
  g.add_loop(std::vector<pdd::point>{{0, 0}, {4, 0}, {4, 4}, {0, 4}});
  return g;
}

pdd::verify_options criteria() {
  pdd::verify_options vo;
  vo.criteria.min_angle_deg = 20.7;
  vo.criteria.max_area = 0.1;
  return vo;
}

pdd::triangle_mesh mesh_of(const pdd::pslg& g) {
  pdd::generate_options o;
  o.criteria = criteria().criteria;
  return pdd::generate(g, o).mesh;
}

TEST(VerifyGeneral, IsolatedVerticesMustBeMeshVertices) {
  pdd::pslg with = square();
  with.add_vertex({1.3, 2.7});
  with.add_vertex({9, 9}); // outside the domain: not asked for
  with.rule = pdd::domain_rule::triangle;
  EXPECT_TRUE(pdd::verify(mesh_of(with), with, criteria()).ok());
  const pdd::verification_report r = pdd::verify(mesh_of(square()), with, criteria());
  EXPECT_EQ(r.missing_vertices, 1u);
  EXPECT_FALSE(r.ok());
  ASSERT_FALSE(r.messages.empty());
  EXPECT_NE(r.messages.front().find("input vertex 4"), std::string::npos) << r.messages.front();
}

TEST(VerifyGeneral, InternalConstraintsAndInternalBoundaries) {
  pdd::pslg diagonal = square();
  diagonal.add_segment(0, 2);
  diagonal.rule = pdd::domain_rule::triangle;
  EXPECT_TRUE(pdd::verify(mesh_of(diagonal), diagonal, criteria()).ok());
  // a mesh that ignores the diagonal misses it, whatever its area
  const pdd::verification_report r = pdd::verify(mesh_of(square()), diagonal, criteria());
  EXPECT_GE(r.missing_segments, 1u);
  pdd::pslg nested = square();
  nested.add_loop(std::vector<pdd::point>{{1, 1}, {3, 1}, {3, 3}, {1, 3}});
  nested.rule = pdd::domain_rule::triangle;
  const pdd::verification_report n = pdd::verify(mesh_of(nested), nested, criteria());
  EXPECT_TRUE(n.ok());
  EXPECT_NEAR(n.area_domain, 16.0, 1e-12);
  nested.rule = pdd::domain_rule::odd_nesting; // the inside is a hole: the mesh covers too much
  EXPECT_FALSE(pdd::verify(mesh_of(nested), nested, criteria()).area_ok);
}

} // namespace
