// pdd::region_attributes (Triangle's -A for pdd-mesh): every triangle of a monolithic or a
// decoupled mesh carries the attribute of the region in its face; pdd::triangle_neighbors.
#include <pdd/errors.hpp>
#include <pdd/generate.hpp>
#include <pdd/mesh/region_attributes.hpp>

#include <gtest/gtest.h>

#include "general_domains.hpp"

#include <cstddef>
#include <vector>

namespace region_attributes_test {
namespace {

/// Two components of closed loops: the square [0, 1]^2 with a square hole and the square
/// [2, 3] x [0, 1]; regions at (0.1, 0.1) (attribute 7) and (2.5, 0.5) (attribute -3).
pdd::pslg two_components() {
  pdd::pslg g;
  g.add_loop(std::vector<pdd::point>{{0, 0}, {1, 0}, {1, 1}, {0, 1}});
  g.add_loop(std::vector<pdd::point>{{0.4, 0.4}, {0.6, 0.4}, {0.6, 0.6}, {0.4, 0.6}});
  g.add_loop(std::vector<pdd::point>{{2, 0}, {3, 0}, {3, 1}, {2, 1}});
  g.holes.push_back({0.5, 0.5});
  g.regions.push_back({{0.1, 0.1}, 7.0, -1.0});
  g.regions.push_back({{2.5, 0.5}, -3.0, -1.0});
  return g;
}

pdd::point centroid(const pdd::triangle_mesh& m, std::size_t t) {
  const auto& tri = m.triangles[t];
  return pdd::detail::triangle_centroid(m.vertices[tri[0]], m.vertices[tri[1]], m.vertices[tri[2]]);
}

} // namespace

TEST(RegionAttributes, DecoupledMeshOfTwoComponents) {
  for (const std::size_t n : {1u, 8u}) {
    pdd::generate_options o;
    o.criteria.max_area = 2e-3;
    o.subdomains = n;
    const pdd::pslg g = two_components();
    const pdd::triangle_mesh m = pdd::generate(g, o).mesh;
    const std::vector<double> a = pdd::region_attributes(g, m);
    ASSERT_EQ(a.size(), m.triangles.size());
    std::size_t left = 0;
    for (std::size_t t = 0; t < m.triangles.size(); ++t) {
      const bool in_left = centroid(m, t).x < 1.5;
      left += in_left;
      ASSERT_EQ(a[t], in_left ? 7.0 : -3.0) << "N = " << n << ", triangle " << t;
    }
    EXPECT_GT(left, 100u);
    EXPECT_GT(m.triangles.size() - left, 100u);
  }
}

TEST(RegionAttributes, FacesOfInternalConstraintsAndFacesWithoutRegion) {
  // the layered domain (Triangle's rule): five faces, attributes 1..5; without its fifth region
  // point the top face gets 0
  pdd::pslg g = pdd::test::layered_domain(0.05);
  g.regions.pop_back();
  pdd::generate_options o;
  o.criteria.max_area = 0.05;
  const pdd::triangle_mesh m = pdd::generate(g, o).mesh;
  const std::vector<double> a = pdd::region_attributes(g, m);
  for (std::size_t t = 0; t < m.triangles.size(); ++t) {
    const pdd::point c = centroid(m, t);
    const double want = c.y > 4 ? 0.0 : (c.y > 2 ? 3.0 : 1.0) + (c.x > 5 ? 1.0 : 0.0);
    ASSERT_EQ(a[t], want) << t << " at " << pdd::to_string(c);
  }
}

TEST(RegionAttributes, RegionPointInAHoleIsNamed) {
  pdd::pslg g = two_components();
  g.regions.push_back({{0.5, 0.5}, 1.0, -1.0});
  pdd::generate_options o;
  o.criteria.max_area = 0.01;
  const pdd::triangle_mesh m = pdd::generate(two_components(), o).mesh;
  try {
    static_cast<void>(pdd::region_attributes(g, m));
    ADD_FAILURE() << "a region point in a hole was accepted";
  } catch (const pdd::geometry_error& e) {
    EXPECT_NE(std::string(e.what()).find("region 2"), std::string::npos) << e.what();
  }
}

TEST(TriangleNeighbors, SymmetricAndOpenOnlyOnTheBoundary) {
  pdd::generate_options o;
  o.criteria.max_area = 5e-3;
  const pdd::triangle_mesh m = pdd::generate(two_components(), o).mesh;
  const auto nb = pdd::triangle_neighbors(m);
  std::size_t open = 0;
  for (std::size_t t = 0; t < nb.size(); ++t)
    for (std::size_t i = 0; i < 3; ++i) {
      const long long u = nb[t][i];
      if (u < 0) {
        ++open;
        continue;
      }
      const auto& back = nb[static_cast<std::size_t>(u)];
      EXPECT_TRUE(back[0] == static_cast<long long>(t) || back[1] == static_cast<long long>(t) ||
                  back[2] == static_cast<long long>(t));
    }
  EXPECT_EQ(open, m.segments.size()); // every boundary edge is a segment edge, and no other
}

} // namespace region_attributes_test
