/// \file vtu_directory_sink.hpp
/// pdd::mpi::piece_directory_sink (pdd::mpi::vtu_directory_sink for VTU): per-subdomain files
/// (VTU or binary) written by the ranks that meshed them, and one index written by rank 0 once
/// every rank has succeeded.
#pragma once

#include <pdd/concepts/mesh_sink.hpp>
#include <pdd/core/triangle_mesh.hpp>
#include <pdd/io/piece_files.hpp>
#include <pdd/mesh/sinks.hpp>
#include <pdd/mpi/detail/wire.hpp>

#include <mpi.h>

#include <filesystem>
#include <string>
#include <system_error>
#include <utility>
#include <vector>

namespace pdd::mpi {

/// A MeshSink for pdd::mpi::mesh_subdomains: on every rank, consume() writes the subdomain's
/// file exactly as pdd::piece_directory_sink does (`<directory>/subdomain_<id>.vtu` or `.pddm`,
/// atomically, the same bytes), and finish(), which mesh_subdomains calls once every rank has
/// succeeded, writes the index `<directory>/<index_name>` (mesh.pvtu or mesh.pddi by default)
/// over all n subdomains on rank 0 only (the same bytes as the threaded run's index).
/// remove_written() removes this rank's files after a failed run (nothing of it is left when
/// every rank calls it).
/// Thread-safety: consume() may run concurrently (different files); the rest from one thread.
class piece_directory_sink {
public:
  /// False: a piece is on disk, not in memory, once consume returns (see MeshSink).
  static constexpr bool retains_meshes = false;

  /// Creates `directory` if needed (every rank: the ranks share a file system). An empty
  /// `index_name`: pdd::piece_index_name(format).
  /// \throws pdd::error when it cannot be created.
  piece_directory_sink(MPI_Comm comm, std::filesystem::path directory,
                       piece_format format = piece_format::vtu, std::string index_name = {})
      : files_(std::move(directory), format, std::move(index_name)) {
    detail::check(MPI_Comm_rank(comm, &rank_), "MPI_Comm_rank");
  }

  /// Every rank: takes note of the number of subdomains n, the pieces the index will list.
  void start(index_t n) {
    n_ = n;
    files_.start(n);
  }
  /// Writes the piece (\throws pdd::error when writing fails).
  void consume(index_t id, triangle_mesh&& mesh) { files_.consume(id, std::move(mesh)); }
  /// Rank 0: writes the index over the n pieces (all delivered: every rank has succeeded).
  void finish() {
    if (rank_ != 0) return;
    std::vector<std::string> names(n_);
    for (index_t i = 0; i < n_; ++i)
      names[i] = pdd::piece_directory_sink::piece_name(i, files_.format());
    write_piece_index(files_.index_path(), names, files_.format());
  }

  /// Removes the pieces this rank has written (best effort: the run has failed already).
  void remove_written() const { files_.remove_written(); }

  /// `<directory>/<index_name>`: where rank 0's finish() writes the index (the same path on
  /// every rank).
  std::filesystem::path index_path() const { return files_.index_path(); }
  /// The sizes of the pieces this rank wrote, by subdomain id.
  const std::vector<piece_counts>& pieces() const noexcept { return files_.pieces(); }

private:
  pdd::piece_directory_sink files_;
  int rank_ = 0;
  index_t n_ = 0;
};
static_assert(MeshSink<piece_directory_sink>);

/// The VTU piece_directory_sink (its default format).
using vtu_directory_sink = piece_directory_sink;

} // namespace pdd::mpi
