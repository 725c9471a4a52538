/// \file mesh_sink_ref.hpp
/// pdd::mesh_sink_ref: any MeshSink behind one type, so that the pipeline's code for a kernel
/// is compiled once (in libpdd) for every sink a program delivers to.
#pragma once

#include <pdd/concepts/mesh_sink.hpp>
#include <pdd/core/index.hpp>
#include <pdd/core/triangle_mesh.hpp>

#include <memory>
#include <utility>

namespace pdd {

/// A MeshSink that forwards to another MeshSink it refers to (not owns): start (when the sink
/// has it), consume and finish, from the same threads and in the same order as it is called.
/// One indirect call per subdomain mesh. The referred sink must outlive the reference.
/// referred_retains_meshes() says what the referred sink's type says (pdd::sink_retains_meshes);
/// the reference's own type says nothing (true, the safe answer), so the memory check asks the
/// reference (pipeline::check_memory).
class mesh_sink_ref {
public:
  /// Refers to `sink`.
  template <MeshSink S>
  requires(!std::same_as<S, mesh_sink_ref>) explicit mesh_sink_ref(S& sink) noexcept
      : sink_(std::addressof(sink)), start_(&start_of<S>), consume_(&consume_of<S>),
        finish_(&finish_of<S>), retains_(sink_retains_meshes<S>) {}

  /// Calls the referred sink's start(n) when it has one.
  void start(index_t n) { start_(sink_, n); }
  /// The referred sink's consume(id, mesh).
  void consume(index_t id, triangle_mesh&& mesh) { consume_(sink_, id, std::move(mesh)); }
  /// The referred sink's finish().
  void finish() { finish_(sink_); }
  /// Whether the referred sink keeps the meshes in memory (pdd::sink_retains_meshes of its type).
  bool referred_retains_meshes() const noexcept { return retains_; }

private:
  template <class S>
  static void start_of(void* s, index_t n) {
    start_sink(*static_cast<S*>(s), n);
  }
  template <class S>
  static void consume_of(void* s, index_t id, triangle_mesh&& mesh) {
    static_cast<S*>(s)->consume(id, std::move(mesh));
  }
  template <class S>
  static void finish_of(void* s) {
    static_cast<S*>(s)->finish();
  }

  void* sink_;
  void (*start_)(void*, index_t);
  void (*consume_)(void*, index_t, triangle_mesh&&);
  void (*finish_)(void*);
  bool retains_;
};

static_assert(MeshSink<mesh_sink_ref>);

} // namespace pdd
