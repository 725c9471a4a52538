/// \file plan.hpp
/// Implementation of pdd::pipeline: the executor construction and a sink wrapper that times
/// finish().
#pragma once

#include <pdd/concepts/mesh_sink.hpp>
#include <pdd/core/triangle_mesh.hpp>

#include <chrono>
#include <utility>

namespace pdd::detail {

/// Builds an Executor for a thread count: E{threads} when E takes one, else E{}.
template <class E>
E make_executor(unsigned threads) {
  if constexpr (requires { E{threads}; })
    return E{threads};
  else
    return E{};
}

/// Forwards to a MeshSink and measures the time spent in its finish() (the merge).
template <MeshSink S>
struct timed_sink {
  static constexpr bool retains_meshes = sink_retains_meshes<S>;
  S& sink;
  double finish_seconds = 0.0;

  void start(index_t n) { start_sink(sink, n); }
  void consume(index_t id, triangle_mesh&& mesh) { sink.consume(id, std::move(mesh)); }
  void finish() {
    const auto t0 = std::chrono::steady_clock::now();
    sink.finish();
    finish_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  }
};

} // namespace pdd::detail
