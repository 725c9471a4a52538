// The geometric path on the shared real geometries (issue 17): Lake Superior, Texas and the
// three-element airfoil, N = 64 (geometric sizing on) and automatic N (the path its rule picks),
// coarse bounds (the fast suite): verified
// against the pipeline's F (exact Delaunay, conformity, area <= F at every centroid, quality of
// the unshielded triangles), bitwise identical at 1 and 2 threads, and the statistics name the
// geometric path. Skips (counted) without ../shared.
#include <pdd/generate.hpp>
#include <pdd/geometry/properties.hpp>
#include <pdd/io/poly.hpp>
#include <pdd/mesh/merge.hpp>
#include <pdd/mesh/verify.hpp>
#include <pdd/pipeline.hpp>
#include <pdd/shielding/shield_statistics.hpp>

#include "mesh_compare.hpp"
#include "pipeline_run.hpp"
#include "test_support.hpp"
#include "verified.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <string>

namespace geometric_real_test {
namespace {

struct run {
  pdd::triangle_mesh mesh;
  pdd::generate_statistics stats;
};

run mesh_verified(const pdd::pslg& g, const pdd::generate_options& o) {
  pdd::test::pipeline_run p = pdd::test::run_pipeline(g, o);
  run r{std::move(p.mesh), p.stats};
  pdd::test::expect_verified_shielded(r.mesh, g, o.criteria, p.sizing);
  EXPECT_EQ(r.stats.interface_splits, 0u);
  EXPECT_EQ(r.stats.shield_splits, 0u);
  return r;
}

TEST(GeometricReal, LakeTexasAirfoilVerifiedAndThreadIndependent) {
  const auto dir = pdd::test::shared_data_dir();
  if (dir.empty()) GTEST_SKIP() << "../shared/data not found: 0 geometries checked";
  std::size_t checked = 0, geometric = 0;
  for (const char* name : {"lake_superior", "texas", "mesh2d_airfoil_3element"}) {
    const auto file = dir / (std::string(name) + ".poly");
    if (!std::filesystem::exists(file)) continue;
    const pdd::pslg g = pdd::read_poly(file.string());
    pdd::generate_options o;
    o.criteria.max_area = pdd::domain_area(g) / 20000.0;
    o.planning.target_subdomain_triangles = 4000; // automatic N decomposes a small mesh
    o.planning.min_subdomain_triangles = 1000;
    // coarse bounds put many coastline features below the mesh size: a short loop keeps the
    // fast suite fast (the loop's efficiency is benchmarks/results/real-geometries.md's)
    o.geometric_loop = {.max_rounds = 2, .max_subdomains = 400};
    for (const std::size_t n : {64u, 0u}) {
      SCOPED_TRACE(std::string(name) + " N " + std::to_string(n));
      o.subdomains = n;
      o.geometric_sizing =
          n == 0 ? pdd::geometric_sizing_mode::automatic : pdd::geometric_sizing_mode::on;
      o.threads = 1;
      const run one = mesh_verified(g, o);
      if (n != 0) {
        EXPECT_EQ(one.stats.path, "geometric") << one.stats.plan_reason;
        EXPECT_GE(one.stats.sizing_rounds, 1u);
      } else { // automatic: the rule's path, and its reason
        const bool needed = one.stats.plan_reason.find("Algorithm 8.3") != std::string::npos;
        EXPECT_TRUE(one.stats.path == (needed ? "geometric" : "graded") ||
                    (needed && one.stats.path == "monolithic"))
            << one.stats.path << ": " << one.stats.plan_reason;
      }
      geometric += one.stats.path == "geometric" ? 1 : 0;
      o.threads = 2;
      const run two = mesh_verified(g, o);
      EXPECT_TRUE(pdd::test::bitwise_equal(one.mesh, two.mesh));
      std::printf("%s N %zu: %zu subdomains, %zu triangles, %zu shielded, rounds %zu, estimated "
                  "over-refinement %.4f; %s\n",
                  name, n, one.stats.subdomains, one.mesh.triangles.size(),
                  one.stats.shielded_triangles, one.stats.sizing_rounds,
                  one.stats.estimated_over_refinement.empty()
                      ? 0.0
                      : one.stats.estimated_over_refinement[one.stats.sizing_round_used],
                  one.stats.plan_reason.c_str());
      ++checked;
    }
  }
  RecordProperty("checked", static_cast<int>(checked));
  EXPECT_EQ(checked, 6u);
  EXPECT_GE(geometric, 3u); // N = 64 with geometric sizing on
  RecordProperty("geometric", static_cast<int>(geometric));
}

} // namespace

} // namespace geometric_real_test
