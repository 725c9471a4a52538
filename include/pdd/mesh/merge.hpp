/// \file merge.hpp
/// Merging subdomain meshes into one mesh: pdd::merge_meshes and the in-memory MeshSink
/// pdd::merge_sink.
#pragma once

#include <pdd/concepts/mesh_sink.hpp>
#include <pdd/mesh/detail/merge.hpp>
#include <pdd/core/triangle_mesh.hpp>

#include <mutex>
#include <utility>
#include <vector>

namespace pdd {

/// Merges subdomain meshes (parts[i] is subdomain i's mesh) into one conforming mesh: vertices
/// that several parts share (their interface vertices, bitwise identical by construction) are
/// identified by exact coordinates among each part's segment endpoints and kept once;
/// triangle markers are the part index; segments are the parts' segments less the interface
/// pieces (marker pdd::interface_marker), i.e. the edges on input segments with their markers.
/// Numbering (deterministic, independent of `threads`): part 0's vertices in its order, then
/// each later part's vertices not already present, in its order; triangles in part order.
/// Each part is released as soon as it has been copied (peak memory about twice the mesh).
/// \param threads 0: all cores; 1: sequential.
/// \throws pdd::limit_error beyond 32-bit indices; pdd::decoupling_error if a part has two
/// vertices at one point. Complexity O(total size) work, plus O(B) hashing of the B boundary
/// vertices on one thread. Thread-safety: reentrant.
inline triangle_mesh merge_meshes(std::vector<triangle_mesh>&& parts, unsigned threads = 0) {
  std::vector<triangle_mesh> owned = std::move(parts);
  return detail::merge_parts(owned, threads);
}

/// A MeshSink that keeps every subdomain mesh and merges them at finish() (merge_meshes):
/// the result does not depend on the order in which meshes arrive or on the thread count.
/// Thread-safety: consume() may run concurrently; the rest from one thread.
class merge_sink {
public:
  /// True: every subdomain mesh stays in memory until finish() merges them (see MeshSink).
  static constexpr bool retains_meshes = true;

  /// \param threads threads of the merge at finish() (0: all cores, 1: sequential).
  explicit merge_sink(unsigned threads = 0) : threads_(threads) {}

  /// Reserves room for n subdomains.
  void start(index_t n) {
    const std::lock_guard lock(mutex_);
    if (parts_.size() < n) parts_.resize(n);
  }
  /// Stores (or replaces) subdomain id's mesh. O(1) amortised.
  void consume(index_t id, triangle_mesh&& mesh) {
    triangle_mesh old;
    {
      const std::lock_guard lock(mutex_);
      if (parts_.size() <= id) parts_.resize(id + std::size_t{1});
      old = std::exchange(parts_[id], std::move(mesh));
    }
  }
  /// Merges the stored meshes into mesh(). Missing ids count as empty meshes.
  void finish() {
    merged_ = merge_meshes(std::move(parts_), threads_);
    parts_ = {};
  }

  /// The merged mesh (after finish()).
  const triangle_mesh& mesh() const noexcept { return merged_; }
  /// Moves the merged mesh out (after finish()).
  triangle_mesh take() noexcept { return std::move(merged_); }

private:
  unsigned threads_;
  std::mutex mutex_;
  std::vector<triangle_mesh> parts_;
  triangle_mesh merged_;
};
static_assert(MeshSink<merge_sink>);

} // namespace pdd
