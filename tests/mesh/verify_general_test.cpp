// pdd::verify on domains of Triangle's rule (issue 13): isolated input vertices inside the
// domain must be mesh vertices, internal constraints unions of mesh edges, the area that of the
// faces (an internal boundary's inside counts); segments with no domain face on either side
// (dangling outside the domain or in a hole) are left out of the mesh, as Triangle does.
#include <pdd/generate.hpp>
#include <pdd/mesh/verify.hpp>

#include <gtest/gtest.h>

#include <string>
#include <utility>
#include <vector>

namespace verify_general_test {
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
  pdd::verify_options as_given = criteria();
  as_given.rule_as_given = true;
  EXPECT_FALSE(pdd::verify(mesh_of(nested), nested, as_given).area_ok);
  // with the defaults the PSLG is read as pdd::generate reads it (no hole point, not closed
  // loops in pdd's sense: Triangle's rule, an internal boundary), and the mesh is right
  EXPECT_TRUE(pdd::verify(mesh_of(nested), nested, criteria()).ok());
}

TEST(VerifyGeneral, SegmentsOutsideTheDomainAreNotAskedFor) {
  // found by the fuzzer (tests/fuzz): a quadrilateral with a dangling chain from its corner
  // (0, 0) through (2, 0) to (2, 1) in the unbounded face; Triangle 1.6 -pq20.7a0.1 leaves the
  // chain out of its mesh, and so does pdd
  pdd::pslg outside;
  for (const pdd::point p : {pdd::point{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}})
    outside.add_vertex(p);
  for (const auto& [a, b] : std::vector<std::pair<pdd::index_t, pdd::index_t>>{
           {0, 1}, {1, 2}, {0, 3}, {3, 4}, {4, 5}, {5, 0}})
    outside.add_segment(a, b);
  outside.rule = pdd::domain_rule::triangle;
  const pdd::verification_report r = pdd::verify(mesh_of(outside), outside, criteria());
  EXPECT_TRUE(r.ok()) << (r.messages.empty() ? "" : r.messages.front());
  EXPECT_EQ(r.missing_segments, 0u);
  EXPECT_NEAR(r.area_domain, 1.5, 1e-12); // the quadrilateral alone
  // a dangling segment inside a hole is left out as well
  pdd::pslg in_hole = square();
  in_hole.add_loop(std::vector<pdd::point>{{1, 1}, {3, 1}, {3, 3}, {1, 3}});
  in_hole.add_segment(in_hole.add_vertex({1.5, 1.5}), in_hole.add_vertex({2.5, 1.5}));
  in_hole.holes.push_back({2, 2.5});
  in_hole.rule = pdd::domain_rule::triangle;
  EXPECT_TRUE(pdd::verify(mesh_of(in_hole), in_hole, criteria()).ok());
  // the same kind of segment inside the domain is still asked for
  pdd::pslg inside = square();
  inside.add_segment(inside.add_vertex({1, 1}), inside.add_vertex({2.5, 3}));
  inside.rule = pdd::domain_rule::triangle;
  const pdd::verification_report m = pdd::verify(mesh_of(square()), inside, criteria());
  EXPECT_EQ(m.missing_segments, 1u);
  ASSERT_FALSE(m.messages.empty());
  EXPECT_NE(m.messages.front().find("segment 4"), std::string::npos) << m.messages.front();
}

} // namespace

} // namespace verify_general_test
