// Tests of pdd::mesh_sink_ref: it forwards start, consume and finish to the sink it refers to,
// in order, start only where the sink has one, and says whether that sink keeps its meshes;
// pdd::generate's sink overload (through the reference) delivers what the sink itself gets.
#include <pdd/generate.hpp>
#include <pdd/geometry/model_domains.hpp>
#include <pdd/mesh/mesh_sink_ref.hpp>
#include <pdd/mesh/sinks.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <mutex>
#include <string>
#include <utility>
#include <vector>

namespace mesh_sink_ref_test {
namespace {

// Records every call, in order. consume() may run on several threads at once (a sink's
// contract, sinks.hpp), so it records under a lock.
struct recording_sink {
  std::mutex lock;
  std::vector<std::string> calls;
  void start(pdd::index_t n) { calls.push_back("start " + std::to_string(n)); }
  void consume(pdd::index_t id, pdd::triangle_mesh&& m) {
    const std::lock_guard<std::mutex> held(lock);
    calls.push_back("consume " + std::to_string(id) + " " + std::to_string(m.triangles.size()));
  }
  void finish() { calls.push_back("finish"); }
};

// No start(), no retains_meshes: the reference must not call start, and says "retains".
struct minimal_sink {
  int consumed = 0;
  bool finished = false;
  void consume(pdd::index_t, pdd::triangle_mesh&&) { ++consumed; }
  void finish() { finished = true; }
};

pdd::triangle_mesh one_triangle() {
  pdd::triangle_mesh m;
  m.vertices = {{0, 0}, {1, 0}, {0, 1}};
  m.triangles = {{0, 1, 2}};
  return m;
}

TEST(MeshSinkRef, ForwardsEveryCallInOrder) {
  recording_sink sink;
  pdd::mesh_sink_ref ref(sink);
  ref.start(2);
  ref.consume(1, one_triangle());
  ref.consume(0, pdd::triangle_mesh{});
  ref.finish();
  const std::vector<std::string> want{"start 2", "consume 1 1", "consume 0 0", "finish"};
  EXPECT_EQ(sink.calls, want);
  EXPECT_TRUE(ref.referred_retains_meshes());
}

TEST(MeshSinkRef, StartIsOptionalAndRetainingIsTheSinksAnswer) {
  minimal_sink sink;
  pdd::mesh_sink_ref ref(sink);
  ref.start(3); // minimal_sink has no start: nothing happens
  ref.consume(0, one_triangle());
  ref.finish();
  EXPECT_EQ(sink.consumed, 1);
  EXPECT_TRUE(sink.finished);
  EXPECT_TRUE(ref.referred_retains_meshes()); // a sink that does not say keeps its meshes
  pdd::counting_sink counting;
  EXPECT_FALSE(pdd::mesh_sink_ref(counting).referred_retains_meshes());
}

TEST(MeshSinkRef, GenerateDeliversThroughTheReferenceAsToTheSink) {
  const pdd::pslg d = pdd::key_domain();
  pdd::generate_options o;
  o.criteria.max_area = 2e-3;
  o.subdomains = 4;
  recording_sink direct;
  const pdd::generate_statistics st = pdd::generate(d, o, direct);
  recording_sink behind;
  pdd::mesh_sink_ref ref(behind);
  pdd::generate(d, o, ref); // a reference is a sink too, and is not wrapped again
  ASSERT_EQ(direct.calls.size(), st.subdomains + 2);
  EXPECT_EQ(direct.calls.front(), "start " + std::to_string(st.subdomains));
  EXPECT_EQ(direct.calls.back(), "finish");
  std::vector<std::string> a = direct.calls, b = behind.calls; // consume order may differ
  std::sort(a.begin(), a.end());
  std::sort(b.begin(), b.end());
  EXPECT_EQ(a, b);
}

} // namespace
} // namespace mesh_sink_ref_test
