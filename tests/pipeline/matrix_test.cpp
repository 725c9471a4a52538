// The test matrix for the uniform decoupling method: the bundled key and pipe domains
// and every shared geometry with input angles >= 60 deg, N in {1, 2, 16, 64, 256}, threads
// {1, 2}: verify passes (Delaunay across interfaces, conformity, area, quality), no interface
// split, the merged mesh is bitwise identical for both thread counts, and the meshes delivered
// to a per-subdomain sink merge to exactly the same mesh.
#include <pdd/generate.hpp>
#include <pdd/geometry/model_domains.hpp>
#include <pdd/geometry/properties.hpp>
#include <pdd/io/poly.hpp>
#include <pdd/mesh/merge.hpp>
#include <pdd/mesh/quality.hpp>
#include <pdd/mesh/verify.hpp>

#include "mesh_compare.hpp"
#include "recording_sink.hpp"
#include "test_support.hpp"
#include "verified.hpp"

#include <gtest/gtest.h>

#include <cstring>
#include <mutex>
#include <string>
#include <vector>

namespace matrix_test {
namespace {

using pdd::test::bitwise_equal;

struct named_domain {
  std::string name;
  pdd::pslg domain;
  double triangles; // aimed at
};

std::vector<named_domain> matrix_domains() {
  std::vector<named_domain> out{{"key", pdd::key_domain(), 40000},
                                {"pipe", pdd::pipe_domain(), 40000}};
  for (const auto& f : pdd::test::shared_poly_files()) {
    try {
      pdd::pslg d = pdd::read_poly(f);
      const pdd::pslg_properties p = pdd::analyze(d);
      // not made of closed loops: tests/pipeline/general_pslg_test.cpp
      if (p.closed_loops && p.min_angle_deg >= 60.0)
        out.push_back({f.filename().string(), std::move(d), 40000});
    } catch (const pdd::error&) {
    }
  }
  return out;
}

} // namespace

TEST(UniformMatrix, VerifiedDeterministicAndSinkConsistent) {
  for (const auto& [name, d, triangles] : matrix_domains()) {
    for (const std::size_t n : {1u, 2u, 16u, 64u, 256u}) {
      SCOPED_TRACE(name + " N " + std::to_string(n));
      pdd::generate_options o;
      o.criteria.max_area = pdd::domain_area(d) / (triangles * 0.656);
      o.subdomains = n;
      o.threads = 1;
      const pdd::generate_result one = pdd::generate(d, o);
      EXPECT_EQ(one.statistics.subdomains, n);
      EXPECT_EQ(one.statistics.interface_splits, 0u);
      pdd::test::expect_verified(one.mesh, d, o.criteria);

      o.threads = 2;
      EXPECT_TRUE(bitwise_equal(one.mesh, pdd::generate(d, o).mesh)) << "1 vs 2 threads";

      pdd::test::recording_sink sink;
      pdd::generate(d, o, sink);
      ASSERT_EQ(sink.meshes.size(), n);
      EXPECT_EQ(sink.started_with, n);
      EXPECT_TRUE(bitwise_equal(one.mesh, pdd::merge_meshes(sink.take_parts(), 1)))
          << "per-subdomain output does not merge to the merged mesh";
    }
  }
}

} // namespace matrix_test
