// pdd::statistics_sink: statistics of a streamed run equal those of the merged mesh.
#include <pdd/generate.hpp>
#include <pdd/mesh/sinks.hpp>
#include <pdd/mesh/statistics_sink.hpp>

#include <gtest/gtest.h>

#include "test_support.hpp"

#include <cstring>
#include <string>
#include <utility>
#include <vector>

namespace statistics_sink_test {
TEST(StatisticsSink, StreamedTotalsEqualTheMergedMeshStatistics) {
  const pdd::pslg g = pdd::test::star_polygon(12, 0.5); // input angles far below 60 deg
  pdd::generate_options o;
  o.criteria.max_area = 2e-4;
  o.subdomains = 16;
  o.threads = 2;
  const pdd::generate_result merged = pdd::generate(g, o);
  const pdd::mesh_statistics m = pdd::compute_statistics(merged.mesh);
  const pdd::shielding_statistics ms = pdd::compute_shielding_statistics(merged.mesh, g);
  ASSERT_GT(ms.shielded_triangles, 0u);

  std::vector<pdd::mesh_statistics> totals;
  for (const unsigned threads : {1u, 2u}) {
    o.threads = threads;
    pdd::counting_sink counts;
    pdd::statistics_sink measured(counts, g);
    const pdd::generate_statistics gs = pdd::generate(g, o, measured);
    const pdd::mesh_statistics& s = measured.statistics();
    const pdd::shielding_statistics& sh = measured.shielding();
    EXPECT_EQ(s.triangles, m.triangles);
    EXPECT_EQ(s.triangles, counts.triangles());
    EXPECT_EQ(s.vertices, counts.vertices()); // interface vertices once per side
    EXPECT_EQ(s.min_angle_deg, m.min_angle_deg);
    EXPECT_EQ(s.max_angle_deg, m.max_angle_deg);
    EXPECT_EQ(s.max_ratio, m.max_ratio);
    EXPECT_EQ(s.max_area, m.max_area);
    EXPECT_EQ(s.angle_histogram, m.angle_histogram);
    EXPECT_NEAR(s.area, m.area, 1e-12 * m.area);
    EXPECT_EQ(sh.shielded_triangles, ms.shielded_triangles);
    EXPECT_EQ(sh.shielded_triangles, gs.shielded_triangles);
    EXPECT_EQ(sh.min_angle_unshielded_deg, ms.min_angle_unshielded_deg);
    EXPECT_EQ(sh.max_ratio_unshielded, ms.max_ratio_unshielded);
    EXPECT_EQ(sh.max_ratio_shielded, ms.max_ratio_shielded);
    EXPECT_EQ(sh.min_input_angle_deg, ms.min_input_angle_deg);
    EXPECT_GE(sh.min_angle_unshielded_deg, 20.7);
    totals.push_back(s);
  }
  // combined in id order: the same bits for any thread count
  EXPECT_EQ(std::memcmp(&totals[0].area, &totals[1].area, sizeof(double)), 0);
}

// Without small input angles the shielding statistics come from the mesh statistics, with
// no pass of their own: bitwise those of compute_shielding_statistics, on meshes with ties
// (a uniform grid-like square) and without (random area bounds, the pipe's holes).
TEST(StatisticsSink, ShieldingStatisticsFromTheMeshStatisticsAreExact) {
  pdd::pslg square;
  square.add_loop(std::vector<pdd::point>{{0, 0}, {1, 0}, {1, 1}, {0, 1}}, 1);
  const pdd::pslg star = pdd::test::star_polygon(12, 0.5);
  for (const auto& [g, small] : {std::pair<const pdd::pslg*, bool>{&square, false},
                                 std::pair<const pdd::pslg*, bool>{&star, true}})
    for (const double area : {0.5, 1e-2, 3e-3, 7e-4, 1e-4}) {
      pdd::generate_options o;
      o.criteria.max_area = area;
      o.subdomains = 1;
      const pdd::generate_result r = pdd::generate(*g, o);
      const pdd::small_input_angles angles = pdd::find_small_input_angles(*g);
      ASSERT_EQ(angles.apexes.empty(), !small);
      const pdd::shielding_statistics want = pdd::compute_shielding_statistics(r.mesh, angles);
      const pdd::shielding_statistics got =
          pdd::shielding_statistics_of(r.mesh, angles, pdd::compute_statistics(r.mesh));
      const std::string at = "area " + std::to_string(area) + (small ? " star" : " square");
      EXPECT_EQ(got.shielded_triangles, want.shielded_triangles) << at;
      EXPECT_EQ(got.min_angle_unshielded_deg, want.min_angle_unshielded_deg) << at;
      EXPECT_EQ(got.max_ratio_unshielded, want.max_ratio_unshielded) << at;
      EXPECT_EQ(got.min_input_angle_deg, want.min_input_angle_deg) << at;
      EXPECT_EQ(got.max_ratio_shielded, want.max_ratio_shielded) << at;
      EXPECT_EQ(got.max_shield_angle_error_deg, want.max_shield_angle_error_deg) << at;
    }
  // an empty mesh
  const pdd::small_input_angles none = pdd::find_small_input_angles(square);
  const pdd::shielding_statistics empty =
      pdd::shielding_statistics_of({}, none, pdd::compute_statistics(pdd::triangle_mesh{}));
  EXPECT_EQ(empty.min_angle_unshielded_deg, 0.0);
  EXPECT_EQ(empty.max_ratio_unshielded, 0.0);
}

TEST(StatisticsSink, RepeatedIdReplacesItsPart) {
  pdd::pslg g;
  g.add_loop(std::vector<pdd::point>{{0, 0}, {1, 0}, {1, 1}, {0, 1}}, 1);
  pdd::counting_sink counts;
  pdd::statistics_sink measured(counts, g);
  pdd::triangle_mesh a;
  a.vertices = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  a.triangles = {{0, 1, 2}, {0, 2, 3}};
  pdd::triangle_mesh b;
  b.vertices = {{0, 0}, {1, 0}, {0, 1}};
  b.triangles = {{0, 1, 2}};
  measured.start(2);
  measured.consume(1, pdd::triangle_mesh(b));
  measured.consume(0, pdd::triangle_mesh(a));
  measured.consume(1, pdd::triangle_mesh(b)); // a repair re-delivers subdomain 1
  measured.finish();
  EXPECT_EQ(measured.statistics().triangles, 3u);
  EXPECT_DOUBLE_EQ(measured.statistics().area, 1.5);
  EXPECT_DOUBLE_EQ(measured.statistics().min_angle_deg, 45.0);
  EXPECT_DOUBLE_EQ(measured.shielding().min_angle_unshielded_deg, 45.0);
  EXPECT_EQ(measured.shielding().shielded_triangles, 0u);
}

} // namespace statistics_sink_test
