/// \file sinks.hpp
/// MeshSink models that keep nothing in memory: pdd::piece_directory_sink (one .vtu or binary
/// .pddm file per subdomain and an index; pdd::vtu_directory_sink for VTU) and
/// pdd::counting_sink (sizes only).
#pragma once

#include <pdd/concepts/mesh_sink.hpp>
#include <pdd/core/triangle_mesh.hpp>
#include <pdd/errors.hpp>
#include <pdd/io/piece_files.hpp>

#include <cstddef>
#include <filesystem>
#include <mutex>
#include <string>
#include <vector>

namespace pdd {

/// Sizes of one delivered subdomain mesh.
struct piece_counts {
  /// Whether the subdomain's mesh has arrived (consume was called for its id); the sizes are
  /// 0 until it has.
  bool delivered = false;
  /// Vertices of the subdomain's own mesh (its interface vertices counted here too).
  std::size_t vertices = 0;
  /// Triangles of the subdomain's mesh.
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

/// A MeshSink that writes each subdomain mesh to `<directory>/subdomain_<id>.<ext>` as soon as
/// it arrives (pdd::write_piece in the sink's format: write_vtu or write_binary_mesh; its own
/// vertex numbering, triangle markers = id), keeps only its sizes, and at finish() writes the
/// index `<directory>/<index_name>` (mesh.pvtu or mesh.pddi by default; pdd::write_piece_index)
/// over the pieces in id order. A repeated id overwrites its file. Files are written atomically.
/// Thread-safety: consume() may run concurrently (different files); the rest from one thread.
class piece_directory_sink {
public:
  /// False: a piece is on disk, not in memory, once consume returns (see MeshSink).
  static constexpr bool retains_meshes = false;

  /// Creates `directory` (and parents) if needed. An empty `index_name`: piece_index_name(f).
  /// \throws pdd::error when the directory cannot be created.
  explicit piece_directory_sink(std::filesystem::path directory,
                                piece_format format = piece_format::vtu,
                                std::string index_name = {})
      : dir_(std::move(directory)), format_(format),
        index_name_(index_name.empty() ? piece_index_name(format) : std::move(index_name)) {
    std::error_code ec;
    std::filesystem::create_directories(dir_, ec);
    if (ec) throw error("cannot create directory '" + dir_.string() + "': " + ec.message());
  }

  /// The file name of subdomain id's piece in format f (pdd::piece_file_name).
  static std::string piece_name(index_t id, piece_format f = piece_format::vtu) {
    return piece_file_name(id, f);
  }

  /// Reserves room for the sizes of n subdomains (MeshSink's optional start).
  void start(index_t n) { register_.start(n); }
  /// Writes the piece and records its sizes; the mesh is released on return.
  /// \throws pdd::error when writing fails.
  void consume(index_t id, triangle_mesh&& mesh) {
    const triangle_mesh m = std::move(mesh);
    write_piece(dir_ / piece_name(id, format_), m, format_);
    register_.record(id, m);
  }
  /// Writes the index over the delivered pieces.
  void finish() {
    std::vector<std::string> files;
    for (std::size_t i = 0; i < register_.pieces().size(); ++i)
      if (register_.pieces()[i].delivered)
        files.push_back(piece_name(static_cast<index_t>(i), format_));
    write_piece_index(index_path(), files, format_);
  }

  /// Removes the pieces this sink has written (best effort, for a failed run: no index exists).
  void remove_written() const {
    for (std::size_t i = 0; i < register_.pieces().size(); ++i)
      if (register_.pieces()[i].delivered) {
        std::error_code ec;
        std::filesystem::remove(dir_ / piece_name(static_cast<index_t>(i), format_), ec);
      }
  }

  /// `<directory>/<index_name>`: where finish() writes (or has written) the index.
  std::filesystem::path index_path() const { return dir_ / index_name_; }
  /// The directory the pieces and the index go to, as given to the constructor.
  const std::filesystem::path& directory() const noexcept { return dir_; }
  /// The pieces' file format (vtu by default, or binary .pddm).
  piece_format format() const noexcept { return format_; }
  /// The sizes of each subdomain's piece, by subdomain id (piece_counts::delivered false for a
  /// piece not written yet); size: at least the n of start(n).
  const std::vector<piece_counts>& pieces() const noexcept { return register_.pieces(); }
  /// Total triangles over the pieces written so far.
  std::size_t triangles() const noexcept { return register_.triangles(); }

private:
  std::filesystem::path dir_;
  piece_format format_;
  std::string index_name_;
  detail::piece_register register_;
};
static_assert(MeshSink<piece_directory_sink>);

/// The VTU piece_directory_sink (its default format): `.vtu` pieces and `mesh.pvtu`.
using vtu_directory_sink = piece_directory_sink;

/// A MeshSink that only records the sizes of the subdomain meshes (benchmarks, dry runs).
/// Thread-safety: consume() may run concurrently; the rest from one thread.
class counting_sink {
public:
  /// False: only sizes are kept (see MeshSink).
  static constexpr bool retains_meshes = false;

  /// Reserves room for the sizes of n subdomains (MeshSink's optional start).
  void start(index_t n) { register_.start(n); }
  /// Records the sizes of subdomain id's mesh and releases the mesh; a repeated id replaces
  /// its sizes.
  void consume(index_t id, triangle_mesh&& mesh) {
    const triangle_mesh m = std::move(mesh);
    register_.record(id, m);
  }
  /// Does nothing (the sizes are complete once the last consume has returned).
  void finish() {}

  /// The sizes of each subdomain's mesh, by subdomain id (piece_counts::delivered false for a
  /// mesh not received); size: at least the n of start(n).
  const std::vector<piece_counts>& pieces() const noexcept { return register_.pieces(); }
  /// Total triangles over the meshes received.
  std::size_t triangles() const noexcept { return register_.triangles(); }
  /// Total vertices summed over the meshes received (an interface vertex once per side).
  std::size_t vertices() const noexcept { return register_.vertices(); }

private:
  detail::piece_register register_;
};
static_assert(MeshSink<counting_sink>);

} // namespace pdd
