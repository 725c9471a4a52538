// The Bahamas runs of tests/long and tests/ci_sized: ../shared/data/bahamas_islands.poly meshed
// by the stepwise pipeline (decoupled, or whole when the plan keeps one subdomain) and verified
// against the sizing field the plan used, with its statistics.
#pragma once

#include <pdd/mesh/verify.hpp>
#include <pdd/pipeline.hpp>
#include <pdd/shielding/shield_statistics.hpp>

#include "test_support.hpp"

#include <gtest/gtest.h>

#include <filesystem>

namespace pdd::test {

/// Meshes g as pdd::generate does, verifies the mesh (exact Delaunay, conformity, the area
/// bound, quality outside the shielded corners) and that no interface or shield segment was
/// split; st receives the run's statistics.
inline triangle_mesh mesh_verified(const pslg& g, const generate_options& o,
                                   generate_statistics& st) {
  pipeline<> p(g, o);
  triangle_mesh m = p.mesh_merged();
  st = p.statistics();
  verify_options vo{.criteria = o.criteria};
  vo.quality_exempt = find_shielded_triangles(m, g);
  const verification_report rep = verify(m, g, vo, p.meshing().sizing);
  EXPECT_TRUE(rep.ok()) << (rep.messages.empty() ? "" : rep.messages.front());
  EXPECT_EQ(rep.delaunay_violations, 0u);
  EXPECT_EQ(rep.area_violations, 0u);
  EXPECT_EQ(st.interface_splits, 0u);
  EXPECT_EQ(st.shield_splits, 0u);
  return m;
}

/// ../shared/data/bahamas_islands.poly, or empty when the shared data is absent.
inline std::filesystem::path bahamas_path() {
  const auto dir = shared_data_dir();
  if (dir.empty() || !std::filesystem::exists(dir / "bahamas_islands.poly")) return {};
  return dir / "bahamas_islands.poly";
}

} // namespace pdd::test
