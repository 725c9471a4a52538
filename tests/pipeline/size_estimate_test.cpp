// pdd::estimate_mesh_size (the triangle estimate bounded by the local feature size) and the
// pipeline's up-front refusal under generate_options::max_triangles (issue 17 item 5).
#include <pdd/errors.hpp>
#include <pdd/generate.hpp>
#include <pdd/geometry/feature_gap.hpp>
#include <pdd/geometry/model_domains.hpp>
#include <pdd/mesh/sinks.hpp>
#include <pdd/pipeline.hpp>
#include <pdd/sizing/any_sizing.hpp>
#include <pdd/sizing/mesh_size_estimate.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace size_estimate_test {
namespace {

pdd::pslg polygon(std::initializer_list<pdd::point> pts) {
  pdd::pslg g;
  for (const pdd::point& p : pts)
    g.vertices.push_back(p);
  const auto n = static_cast<pdd::index_t>(g.vertices.size());
  for (pdd::index_t i = 0; i < n; ++i)
    g.segments.push_back({i, (i + 1) % n, 0});
  return g;
}

/// An isosceles spike: base 1, height h, apex vertex 2.
pdd::pslg spike(double h) {
  return polygon({{0, 0}, {1, 0}, {0.5, h}});
}

} // namespace

TEST(EstimateMeshSize, UniformWhereNoFeatureIsSmallerThanTheMesh) {
  // A unit square at A = 1e-4: nothing is smaller than the triangles, so the estimate is
  // area / (0.656 A) exactly (and the cause is empty).
  const auto e =
      pdd::estimate_mesh_size(polygon({{0, 0}, {1, 0}, {1, 1}, {0, 1}}), 1e-4, pdd::any_sizing{});
  EXPECT_NEAR(e.triangles, 1.0 / (0.656e-4), 1e-6);
  EXPECT_NEAR(e.area_triangles, e.triangles, 1e-6);
  EXPECT_EQ(e.cause.first.id, pdd::no_index);
}

TEST(EstimateMeshSize, CorridorCountsByItsWidth) {
  // 1 x 100 with no area bound: about 100 / (0.656 * 1.2 * 1^2) triangles across its width.
  const auto e = pdd::estimate_mesh_size(polygon({{0, 0}, {100, 0}, {100, 1}, {0, 1}}), INFINITY,
                                         pdd::any_sizing{});
  EXPECT_GT(e.triangles, 100.0 / (0.656 * pdd::across_area_factor));
  EXPECT_LT(e.triangles, 2.0 * 100.0 / (0.656 * pdd::across_area_factor));
  EXPECT_TRUE(std::isinf(e.area_triangles));
}

TEST(EstimateMeshSize, WedgeGrowsWithTheInverseAngleAndNamesTheApex) {
  // Spikes of aspect 1e2 .. 1e6 at A = 1: beyond the area term, a wedge of angle theta adds
  // about ln(L / l) / (0.656 c theta) triangles; each 10x in aspect adds about 10x.
  double previous = 0.0;
  for (const double h : {1e2, 1e3, 1e4, 1e5, 1e6}) {
    const auto e = pdd::estimate_mesh_size(spike(h), 1.0, pdd::any_sizing{});
    EXPECT_EQ(e.cause.apex, 2u) << h;
    const double theta = 2.0 * std::atan(0.5 / h) * 180.0 / 3.141592653589793;
    EXPECT_NEAR(e.cause_angle_deg, theta, 1e-9 * theta) << h;
    EXPECT_GT(e.triangles, e.area_triangles) << h;
    if (previous > 0.0) {
      EXPECT_GT(e.triangles / previous, 5.0) << h;
      EXPECT_LT(e.triangles / previous, 20.0) << h;
    }
    previous = e.triangles;
    EXPECT_LT(e.pieces, 1000u) << h; // the cost follows the wedge's scales, not the mesh
  }
}

TEST(EstimateMeshSize, FeatureGapSeesNarrowWedgesAndIgnoresRightAngles) {
  const pdd::pslg g = spike(1e4);
  const pdd::feature_gap_field f(g);
  ASSERT_EQ(f.size(), 1u);
  // halfway up the spike the gap is its width there (0.5), given by the two long segments
  const auto mid = f.at({0.5, 5000.0}, 0);
  EXPECT_NEAR(mid.gap, 0.5, 1e-9);
  EXPECT_EQ(mid.pair.apex, 2u);
  EXPECT_LT(f.angle_deg(2), 0.006);
  // a unit square: the gap at the centre is the side (two opposite sides), never 0 at corners
  const pdd::pslg sq = polygon({{0, 0}, {1, 0}, {1, 1}, {0, 1}});
  const pdd::feature_gap_field fs(sq);
  for (std::size_t t = 0; t < fs.size(); ++t)
    for (const pdd::point p : {pdd::point{0, 0}, pdd::point{1e-9, 1e-9}, pdd::point{0.5, 0.5}})
      EXPECT_GT(fs.at(p, t).gap, 0.5);
}

TEST(EstimateMeshSize, PipelineRefusesAboveMaxTrianglesWithTheCause) {
  pdd::generate_options o;
  o.criteria.max_area = 1.0;
  o.subdomains = 1;
  pdd::pipeline<> pl(spike(1e4), o);
  const double e = pl.statistics().estimated_triangles;
  EXPECT_EQ(e, pl.size_estimate().triangles);
  EXPECT_GT(e, 2.0 * pl.size_estimate().area_triangles);
  EXPECT_NO_THROW(pl.check_memory<pdd::merge_sink>()); // fits in memory
  o.max_triangles = static_cast<std::size_t>(e / 2.0);
  pdd::pipeline<> limited(spike(1e4), o);
  try {
    limited.check_memory<pdd::merge_sink>();
    FAIL() << "no limit_error";
  } catch (const pdd::limit_error& err) {
    const std::string m = err.what();
    for (const char* part : {"max_triangles", "the angle of", "at vertex 2 (0.5, 10000)",
                             "by the area bound alone", "GiB"})
      EXPECT_NE(m.find(part), std::string::npos) << part << "\n" << m;
  }
  EXPECT_THROW(pdd::generate(spike(1e4), o), pdd::limit_error);
  // the user's limit replaces the memory check: a limit above the estimate lets it run
  o.max_triangles = static_cast<std::size_t>(e * 2.0);
  const pdd::generate_result r = pdd::generate(spike(1e4), o);
  EXPECT_GT(static_cast<double>(r.mesh.triangles.size()), e / 2.0);
  EXPECT_LT(static_cast<double>(r.mesh.triangles.size()), e * 2.0);
}

} // namespace size_estimate_test
