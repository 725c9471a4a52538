// pdd::native::mesher in the decoupling pipeline: pdd::generate<pdd::native::mesher> and the
// stepwise pdd::pipeline give verified meshes, bitwise identical for every thread count and
// executor, close in size to the native kernel on the whole domain (dissertation Table 6.1).
#include <pdd/generate.hpp>
#include <pdd/geometry/model_domains.hpp>
#include <pdd/kernels/native/mesher.hpp>
#include <pdd/mesh/sinks.hpp>
#include <pdd/parallel/sequential_executor.hpp>
// pdd::generate with the sequential executor: compiled here, not in libpdd
#include <pdd/pipeline/generate_templates.hpp>

#include "mesh_compare.hpp"
#include "verified.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

namespace native_kernel_test {
namespace {

using pdd::test::bitwise_equal;
using pdd::test::expect_verified;
using native = pdd::native::mesher;

TEST(NativeKernelPipeline, DecoupledRunsAreVerifiedAndThreadIndependent) {
  struct named {
    const char* name;
    pdd::pslg domain;
    double max_area;
  };
  const std::vector<named> domains{{"key", pdd::key_domain(), 4e-4},
                                   {"pipe", pdd::pipe_domain(), 2e-4}};
  for (const auto& [name, d, max_area] : domains) {
    for (const std::size_t n : {5u, 16u}) {
      SCOPED_TRACE(std::string(name) + " N " + std::to_string(n));
      pdd::generate_options o;
      o.criteria.max_area = max_area;
      o.subdomains = n;
      o.threads = 1;
      const pdd::generate_result one = pdd::generate<native>(d, o);
      EXPECT_EQ(one.statistics.subdomains, n);
      EXPECT_EQ(one.statistics.interface_splits, 0u);
      expect_verified(one.mesh, d, o.criteria);
      for (const unsigned threads : {2u, 4u}) {
        o.threads = threads;
        EXPECT_TRUE(bitwise_equal(one.mesh, pdd::generate<native>(d, o).mesh)) << threads;
      }
      const auto seq =
          pdd::generate<native, pdd::default_partitioner, pdd::sequential_executor>(d, o);
      EXPECT_TRUE(bitwise_equal(one.mesh, seq.mesh));
      o.subdomains = 1;
      const auto mono = pdd::generate<native>(d, o);
      expect_verified(mono.mesh, d, o.criteria);
      EXPECT_LT(std::abs(static_cast<double>(one.mesh.triangles.size()) /
                             static_cast<double>(mono.mesh.triangles.size()) -
                         1.0),
                0.05);
    }
  }
}

TEST(NativeKernelPipeline, StepwisePipelineMatchesGenerate) {
  pdd::generate_options o;
  o.criteria.max_area = 5e-4;
  o.subdomains = 8;
  o.threads = 2;
  const pdd::pslg d = pdd::key_domain();
  pdd::pipeline<native> pl(d, o);
  pl.decouple();
  pdd::merge_sink sink(2);
  EXPECT_EQ(pl.mesh(sink).subdomains, 8u);
  expect_verified(sink.mesh(), d, o.criteria);
  EXPECT_TRUE(bitwise_equal(sink.mesh(), pdd::generate<native>(d, o).mesh));
}

} // namespace

} // namespace native_kernel_test
