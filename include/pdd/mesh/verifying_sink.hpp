/// \file verifying_sink.hpp
/// pdd::verifying_sink: a MeshSink decorator that verifies every subdomain mesh in memory with
/// pdd::pieces_verifier (pdd-verify's checks: each piece alone, then its interfaces as the
/// neighbours arrive) before handing it on, so that a streamed run (`pdd-mesh --verify
/// --output-per-subdomain`) is verified without reading its files back.
#pragma once

#include <pdd/concepts/mesh_sink.hpp>
#include <pdd/core/index.hpp>
#include <pdd/core/triangle_mesh.hpp>
#include <pdd/mesh/verify_pieces.hpp>

#include <atomic>
#include <chrono>
#include <cstdint>
#include <functional>
#include <string>
#include <utility>

namespace pdd {

/// Adds every subdomain mesh to `verifier` (as piece number id, named name(id) in its messages,
/// e.g. the piece's file name) and then hands it to the inner sink; finish() is the inner
/// sink's, and the verdict is verifier.finish() after it. A subdomain delivered twice (an
/// invariance repair, which the theory says never happens) is added twice, and its interface
/// edges then count as overlaps: the report fails rather than hide it.
/// \tparam Inner a MeshSink. Thread-safety: consume() may run concurrently (as the inner
/// sink's); `inner` and `verifier` must outlive the sink.
template <MeshSink Inner>
class verifying_sink {
public:
  /// The inner sink's: this decorator keeps no mesh itself.
  static constexpr bool retains_meshes = sink_retains_meshes<Inner>;

  /// Verifies into `verifier`, naming subdomain id name(id) in its messages, then hands every
  /// mesh to `inner`.
  verifying_sink(Inner& inner, pieces_verifier& verifier, std::function<std::string(index_t)> name)
      : inner_(inner), verifier_(verifier), name_(std::move(name)) {}

  /// Passes start(n) on to the inner sink when it has one.
  void start(index_t n) { start_sink(inner_, n); }
  /// Verifies the mesh (pieces_verifier::add), then hands it on.
  void consume(index_t id, triangle_mesh&& mesh) {
    const auto t0 = std::chrono::steady_clock::now();
    verifier_.add(static_cast<std::uint32_t>(id), name_(id), mesh);
    const auto ns =
        std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::steady_clock::now() - t0);
    nanoseconds_.fetch_add(ns.count(), std::memory_order_relaxed);
    inner_.consume(id, std::move(mesh));
  }
  /// Calls the inner sink's finish().
  void finish() { inner_.finish(); }

  /// Seconds spent verifying, summed over the threads that called consume().
  double seconds() const noexcept {
    return 1e-9 * static_cast<double>(nanoseconds_.load(std::memory_order_relaxed));
  }

private:
  Inner& inner_;
  pieces_verifier& verifier_;
  std::function<std::string(index_t)> name_;
  std::atomic<long long> nanoseconds_{0};
};

} // namespace pdd
