/// \file vtu_directory_sink.hpp
/// pdd::mpi::vtu_directory_sink: per-subdomain VTU files written by the ranks that meshed them,
/// and one .pvtu index written by rank 0 once every rank has succeeded.
#pragma once

#include <pdd/concepts/mesh_sink.hpp>
#include <pdd/core/triangle_mesh.hpp>
#include <pdd/io/vtu.hpp>
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
/// file exactly as pdd::vtu_directory_sink does (`<directory>/subdomain_<id>.vtu`, atomically,
/// the same bytes), and finish(), which mesh_subdomains calls once every rank has succeeded,
/// writes the index `<directory>/<index_name>` over all n subdomains on rank 0 only (the same
/// bytes as the threaded run's index). remove_written() removes this rank's files after a
/// failed run (nothing of it is left when every rank calls it).
/// Thread-safety: consume() may run concurrently (different files); the rest from one thread.
class vtu_directory_sink {
public:
  static constexpr bool retains_meshes = false;

  /// Creates `directory` if needed (every rank: the ranks share a file system).
  /// \throws pdd::error when it cannot be created.
  vtu_directory_sink(MPI_Comm comm, std::filesystem::path directory,
                     std::string index_name = "mesh.pvtu")
      : files_(std::move(directory), std::move(index_name)) {
    detail::check(MPI_Comm_rank(comm, &rank_), "MPI_Comm_rank");
  }

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
      names[i] = pdd::vtu_directory_sink::piece_name(i);
    write_pvtu(files_.index_path(), names);
  }

  /// Removes the pieces this rank has written (best effort: the run has failed already).
  void remove_written() const {
    for (std::size_t i = 0; i < files_.pieces().size(); ++i)
      if (files_.pieces()[i].delivered) {
        std::error_code ec;
        std::filesystem::remove(
            files_.directory() / pdd::vtu_directory_sink::piece_name(static_cast<index_t>(i)), ec);
      }
  }

  std::filesystem::path index_path() const { return files_.index_path(); }
  /// The sizes of the pieces this rank wrote, by subdomain id.
  const std::vector<piece_counts>& pieces() const noexcept { return files_.pieces(); }

private:
  pdd::vtu_directory_sink files_;
  int rank_ = 0;
  index_t n_ = 0;
};
static_assert(MeshSink<vtu_directory_sink>);

} // namespace pdd::mpi
