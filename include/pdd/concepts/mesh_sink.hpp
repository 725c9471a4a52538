/// \file mesh_sink.hpp
/// The MeshSink concept: where the subdomain meshes of a decoupled run go.
///
/// A MeshSink receives each subdomain mesh, with its subdomain id, as soon as the kernel has
/// meshed it and its interface pieces passed the invariance check (Corollary 13), and is told
/// when all have arrived.
///
/// Requirements: for `S s`, `pdd::index_t id` and `pdd::triangle_mesh m`:
/// `s.consume(id, std::move(m))` and `s.finish()`. Optional: `s.start(n)` (n: the number of
/// subdomains) is called first when present; `S::retains_meshes` (a static constexpr bool,
/// true when absent) says whether the sink keeps the meshes in memory, which the pipeline's
/// memory estimate takes into account (see pdd::sink_retains_meshes).
///
/// Semantics: consume may be called concurrently from several threads, for different ids, in
/// any order (largest subdomains first, completion order): models are thread-safe. The mesh
/// delivered for subdomain i is its kernel mesh: its first vertices are the subdomain input's
/// vertices, its triangle markers are i, and its segments include the interface pieces with
/// marker pdd::interface_marker. Interface vertices are bitwise identical in the meshes on
/// both sides. consume may be called again for an id already delivered (only after an
/// invariance repair re-meshed it, which the theory says never happens): the new mesh
/// replaces the old one. finish() is called once, after the last consume, from one thread.
///
/// Models: pdd::merge_sink (one merged mesh in memory), pdd::vtu_directory_sink (one .vtu per
/// subdomain plus a .pvtu index, nothing kept), pdd::counting_sink (statistics only).
#pragma once

#include <pdd/core/index.hpp>
#include <pdd/core/triangle_mesh.hpp>

#include <concepts>
#include <utility>

namespace pdd {

template <class S>
concept MeshSink = requires(S& s, index_t id, triangle_mesh&& m) {
  s.consume(id, std::move(m));
  s.finish();
};

/// Calls sink.start(n) when the sink has it (the optional part of MeshSink); the one place
/// that tests for it, for the pipeline and for sinks that wrap other sinks.
template <class S>
void start_sink(S& sink, index_t n) {
  if constexpr (requires { sink.start(n); }) sink.start(n);
}

/// Whether sink type S keeps the meshes it receives in memory (S::retains_meshes, default
/// true): the pipeline refuses area bounds whose mesh would not fit in memory only then.
template <class S>
inline constexpr bool sink_retains_meshes = [] {
  if constexpr (requires { S::retains_meshes; })
    return static_cast<bool>(S::retains_meshes);
  else
    return true;
}();

} // namespace pdd
