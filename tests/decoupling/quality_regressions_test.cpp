// The quality regressions of issue 11 (../shared/data/regressions/quality-*.poly, found by
// fuzzing pdd-mesh from the letter A): sharp exterior corners (a hole corner, a notch) whose
// bad neighbours CGAL's cluster rule left unrefined (kernels/cgal/detail/cluster_rule.hpp).
// Each file, monolithic and decoupled (N = 2, 8), on 1 and 2 threads: verified (exact Delaunay,
// conformity, area, the angle bound on every unshielded triangle, the area bound), bitwise the
// same on 1 and 2 threads, and passing pdd-mesh's own check (pdd::check_quality).
// Skipped when ../shared is absent.
#include "mesh_compare.hpp"
#include "test_support.hpp"
#include "verified.hpp"

#include <pdd/generate.hpp>
#include <pdd/io/poly.hpp>
#include <pdd/mesh/quality_check.hpp>

#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace quality_regressions_test {
namespace {

/// The files and area bounds of ../shared/data/regressions/README.md.
const std::vector<std::pair<std::string, double>> regression_cases = {
    {"quality-01.poly", 0.0011696}, {"quality-02.poly", 0.0167757}, {"quality-03.poly", 0.0171541},
    {"quality-04.poly", 0.0011696}, {"quality-05.poly", 0.0199262}, {"quality-06.poly", 0.0147238},
    {"quality-07.poly", 0.0206024}};

} // namespace

TEST(QualityRegressions, EveryUnshieldedTriangleMeetsTheBound) {
  const auto dir = pdd::test::shared_data_dir();
  if (dir.empty()) GTEST_SKIP() << "../shared/data is absent";
  int checked = 0;
  for (const auto& [name, area] : regression_cases) {
    const auto path = dir / "regressions" / name;
    ASSERT_TRUE(std::filesystem::exists(path)) << path;
    const pdd::pslg d = pdd::read_poly(path);
    for (const std::size_t n : {1, 2, 8}) {
      const std::string at = name + " N=" + std::to_string(n);
      pdd::generate_options o;
      o.criteria.max_area = area;
      o.subdomains = n;
      o.threads = 2;
      const pdd::generate_result r2 = pdd::generate(d, o);
      o.threads = 1;
      const pdd::generate_result r1 = pdd::generate(d, o);
      pdd::test::expect_verified(r2.mesh, d, o.criteria, at);
      EXPECT_NO_THROW(pdd::check_quality(r2.mesh, d, o.criteria)) << at;
      EXPECT_EQ(r2.statistics.interface_splits, 0u) << at;
      EXPECT_TRUE(pdd::test::bitwise_equal(r1.mesh, r2.mesh)) << at;
      ++checked;
    }
  }
  EXPECT_EQ(checked, 21);
}

TEST(QualityRegressions, PddMeshVerifiesAndWrites) {
  const auto dir = pdd::test::shared_data_dir();
  if (dir.empty()) GTEST_SKIP() << "../shared/data is absent";
  int checked = 0;
  for (const auto& [name, area] : regression_cases) {
    const auto out = pdd::test::temp_path(name + ".vtu");
    std::filesystem::remove(out);
    char bound[32];
    std::snprintf(bound, sizeof bound, "%.17g", area);
    const std::string cmd = std::string("'") + PDD_MESH_EXE + "' '" +
                            (dir / "regressions" / name).string() + "' --max-area " + bound +
                            " --subdomains 1 --verify -q -o '" + out.string() + "'";
    EXPECT_EQ(std::system(cmd.c_str()), 0) << cmd;
    EXPECT_TRUE(std::filesystem::exists(out)) << cmd;
    ++checked;
  }
  EXPECT_EQ(checked, 7);
}

} // namespace quality_regressions_test
