// CI-sized (ctest label "ci": the release preset runs it, the sanitizer presets do not build
// it) version of tests/long/kernel_squares_test.cpp: every kernel meshes the unit square at
// about a million triangles, where its queue, buckets and arrays have grown, and the mesh is
// verified (exact Delaunay, conformity, the angle and area bounds); the bound decides the size.
#include <pdd/kernels/cgal/mesher.hpp>
#include <pdd/kernels/native/mesher.hpp>
#include <pdd/sizing/uniform.hpp>

#include "../kernels/kernel_types.hpp"
#include "test_domains.hpp"
#include "verified.hpp"

#include <gtest/gtest.h>

namespace kernel_million_test {
template <class M>
class CiSizedKernel : public ::testing::Test {};
TYPED_TEST_SUITE(CiSizedKernel, pdd::test::kernel_types, pdd::test::kernel_names);

TYPED_TEST(CiSizedKernel, AMillionTrianglesVerified) {
  const pdd::pslg square = pdd::test::unit_square();
  pdd::mesh_criteria c;
  c.max_area = 1.0 / (0.656 * 1e6); // the mean triangle area of a quality mesh
  const pdd::mesher_result r = TypeParam{}.mesh(square, c, pdd::uniform_sizing{});
  EXPECT_EQ(pdd::test::expect_verified(r.mesh, square, c, "1M"), 0u);
  const auto n = static_cast<double>(r.mesh.triangles.size());
  EXPECT_GT(n, 1e6 / 1.5);
  EXPECT_LT(n, 1e6 * 1.5);
}

} // namespace kernel_million_test
