// MeshSinks for tests: one that keeps every delivered mesh by id, and one that forwards to two.
#pragma once

#include <pdd/concepts/mesh_sink.hpp>
#include <pdd/core/triangle_mesh.hpp>

#include <cstddef>
#include <map>
#include <mutex>
#include <utility>
#include <vector>

namespace pdd::test {

/// Keeps the last mesh delivered for every id (a repair may deliver one again), counts the
/// deliveries and records start() and finish(). Thread-safe consume().
struct recording_sink {
  std::mutex m;
  std::map<index_t, triangle_mesh> meshes;
  std::size_t deliveries = 0;
  index_t started_with = no_index; ///< the n of start(n); no_index: not called
  bool finished = false;
  void start(index_t n) { started_with = n; }
  void consume(index_t id, triangle_mesh&& mesh) {
    const std::lock_guard lock(m);
    meshes[id] = std::move(mesh);
    ++deliveries;
  }
  void finish() { finished = true; }
  /// The meshes in id order (moved out).
  std::vector<triangle_mesh> take_parts() {
    std::vector<triangle_mesh> parts;
    for (auto& [id, mesh] : meshes)
      parts.push_back(std::move(mesh));
    meshes.clear();
    return parts;
  }
};
static_assert(MeshSink<recording_sink>);

/// Forwards to two sinks (the first gets a copy).
template <class A, class B>
struct tee_sink {
  A& a;
  B& b;
  void start(index_t n) {
    start_sink(a, n);
    start_sink(b, n);
  }
  void consume(index_t id, triangle_mesh&& mesh) {
    triangle_mesh copy = mesh;
    a.consume(id, std::move(copy));
    b.consume(id, std::move(mesh));
  }
  void finish() {
    a.finish();
    b.finish();
  }
};

} // namespace pdd::test
