/// \file sinks.hpp
/// MeshSink models that keep nothing in memory: pdd::vtu_directory_sink (one .vtu file per
/// subdomain and a .pvtu index) and pdd::counting_sink (sizes only).
#pragma once

#include <pdd/concepts/mesh_sink.hpp>
#include <pdd/errors.hpp>
#include <pdd/io/vtu.hpp>
#include <pdd/core/triangle_mesh.hpp>

#include <cstddef>
#include <filesystem>
#include <mutex>
#include <string>
#include <vector>

namespace pdd {

/// Sizes of one delivered subdomain mesh.
struct piece_counts {
  bool delivered = false;
  std::size_t vertices = 0;
  std::size_t triangles = 0;
  std::size_t segments = 0; ///< including interface pieces
};

namespace detail {
/// Per-subdomain sizes recorded under a lock (shared by the streaming sinks).
class piece_register {
public:
  void start(index_t n) {
    const std::lock_guard lock(mutex_);
    if (pieces_.size() < n) pieces_.resize(n);
  }
  void record(index_t id, const triangle_mesh& m) {
    const std::lock_guard lock(mutex_);
    if (pieces_.size() <= id) pieces_.resize(id + std::size_t{1});
    pieces_[id] = {true, m.vertices.size(), m.triangles.size(), m.segments.size()};
  }
  /// Per subdomain id (after the last record).
  const std::vector<piece_counts>& pieces() const noexcept { return pieces_; }
  /// Total triangles over all subdomains.
  std::size_t triangles() const noexcept {
    std::size_t n = 0;
    for (const auto& p : pieces_)
      n += p.triangles;
    return n;
  }
  /// Total vertices summed over subdomains (interface vertices once per side).
  std::size_t vertices() const noexcept {
    std::size_t n = 0;
    for (const auto& p : pieces_)
      n += p.vertices;
    return n;
  }

private:
  std::mutex mutex_;
  std::vector<piece_counts> pieces_;
};
} // namespace detail

/// A MeshSink that writes each subdomain mesh to `<directory>/subdomain_<id>.vtu` (write_vtu:
/// its own vertex numbering, cell data "subdomain" = id) as soon as it arrives, keeps only its
/// sizes, and at finish() writes the index `<directory>/<index_name>` (write_pvtu) over the
/// pieces in id order. A repeated id overwrites its file. Files are written atomically.
/// Thread-safety: consume() may run concurrently (different files); the rest from one thread.
class vtu_directory_sink {
public:
  static constexpr bool retains_meshes = false;

  /// Creates `directory` (and parents) if needed.
  /// \throws pdd::error when the directory cannot be created.
  explicit vtu_directory_sink(std::filesystem::path directory, std::string index_name = "mesh.pvtu")
      : dir_(std::move(directory)), index_name_(std::move(index_name)) {
    std::error_code ec;
    std::filesystem::create_directories(dir_, ec);
    if (ec) throw error("cannot create directory '" + dir_.string() + "': " + ec.message());
  }

  /// The file name of subdomain id's piece.
  static std::string piece_name(index_t id) { return "subdomain_" + std::to_string(id) + ".vtu"; }

  void start(index_t n) { register_.start(n); }
  /// Writes the piece and records its sizes; the mesh is released on return.
  /// \throws pdd::error when writing fails.
  void consume(index_t id, triangle_mesh&& mesh) {
    const triangle_mesh m = std::move(mesh);
    write_vtu(dir_ / piece_name(id), m);
    register_.record(id, m);
  }
  /// Writes the .pvtu index over the delivered pieces.
  void finish() {
    std::vector<std::string> files;
    for (std::size_t i = 0; i < register_.pieces().size(); ++i)
      if (register_.pieces()[i].delivered) files.push_back(piece_name(static_cast<index_t>(i)));
    write_pvtu(index_path(), files);
  }

  std::filesystem::path index_path() const { return dir_ / index_name_; }
  const std::filesystem::path& directory() const noexcept { return dir_; }
  const std::vector<piece_counts>& pieces() const noexcept { return register_.pieces(); }
  std::size_t triangles() const noexcept { return register_.triangles(); }

private:
  std::filesystem::path dir_;
  std::string index_name_;
  detail::piece_register register_;
};
static_assert(MeshSink<vtu_directory_sink>);

/// A MeshSink that only records the sizes of the subdomain meshes (benchmarks, dry runs).
/// Thread-safety: consume() may run concurrently; the rest from one thread.
class counting_sink {
public:
  static constexpr bool retains_meshes = false;

  void start(index_t n) { register_.start(n); }
  void consume(index_t id, triangle_mesh&& mesh) {
    const triangle_mesh m = std::move(mesh);
    register_.record(id, m);
  }
  void finish() {}

  const std::vector<piece_counts>& pieces() const noexcept { return register_.pieces(); }
  std::size_t triangles() const noexcept { return register_.triangles(); }
  std::size_t vertices() const noexcept { return register_.vertices(); }

private:
  detail::piece_register register_;
};
static_assert(MeshSink<counting_sink>);

} // namespace pdd
