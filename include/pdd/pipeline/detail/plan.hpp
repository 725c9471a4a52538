/// \file plan.hpp
/// Implementation of pdd::pipeline: the memory check, the executor construction and a sink
/// wrapper that times finish().
#pragma once

#include <pdd/concepts/mesh_sink.hpp>
#include <pdd/core/index.hpp>
#include <pdd/core/triangle_mesh.hpp>
#include <pdd/errors.hpp>
#include <pdd/pipeline/planning.hpp>
#include <pdd/pipeline/system.hpp>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>
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

/// \throws pdd::limit_error when the estimate exceeds 90% of physical memory, or a mesh kept in
/// memory would exceed 32-bit indices.
inline void check_memory_plan(double triangles, std::size_t subdomains, unsigned threads,
                              bool retains_meshes, double max_area) {
  if (!std::isfinite(triangles)) return;
  const auto gib = [](double b) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.1f GiB", b / 1073741824.0);
    return std::string(buf);
  };
  const std::string what = "max_area " + std::to_string(max_area) + " gives about " +
                           std::to_string(static_cast<long long>(triangles)) + " triangles";
  if (retains_meshes && triangles / 2.0 * 1.05 >= static_cast<double>(no_index))
    throw limit_error(what + ": more vertices than 32-bit indices allow in one mesh; use a "
                             "file sink (vtu_directory_sink) or a larger max_area");
  const double need = estimate_peak_bytes(triangles, subdomains, threads, retains_meshes);
  const double have = static_cast<double>(physical_memory_bytes());
  if (have > 0.0 && need > 0.9 * have)
    throw limit_error(what + ", needing about " + gib(need) + " of memory at the peak (" +
                      std::to_string(subdomains) + " subdomains, " + std::to_string(threads) +
                      " threads" + (retains_meshes ? ", kept in memory" : "") +
                      "); the machine has " + gib(have) +
                      (retains_meshes ? ". Use a file sink (vtu_directory_sink)," : ". Use") +
                      " more subdomains or a larger max_area");
}

} // namespace pdd::detail
