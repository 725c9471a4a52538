/// \file resumable_piece_sink.hpp
/// pdd::mpi::resumable_piece_sink: pdd::resumable_piece_sink over the ranks of an MPI job
/// (issue 40): every rank writes the pieces it meshes, and rank 0 keeps the manifest as the
/// ranks report their finished pieces, so that a killed job can be resumed.
#pragma once

#include <pdd/concepts/mesh_sink.hpp>
#include <pdd/core/triangle_mesh.hpp>
#include <pdd/errors.hpp>
#include <pdd/io/manifest_book.hpp>
#include <pdd/io/piece_files.hpp>
#include <pdd/io/piece_manifest.hpp>
#include <pdd/mesh/resumable_piece_sink.hpp>
#include <pdd/mesh/sinks.hpp>
#include <pdd/mpi/detail/wire.hpp>

#include <mpi.h>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <map>
#include <mutex>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace pdd::mpi {

/// A MeshSink and reporter for pdd::mpi::mesh_subdomains (pass it as both): on every rank,
/// consume() writes the piece exactly as pdd::piece_directory_sink does and reads it back for
/// its size and checksum (pdd::piece_checksum); report(id) sends that record, and rank 0's
/// recorded(id, bytes) adds it to the manifest and saves it through `save` (after a piece,
/// unless the last save was less than save_spacing times its duration ago, as
/// pdd::resumable_piece_sink does), so that a job killed at any moment leaves a manifest that
/// lists complete pieces only. A resumed run passes, on rank 0, the manifest of the pieces it
/// keeps (the same ids go to meshing_options::kept on every rank); finish() writes, on rank 0,
/// the manifest and then the index over the kept and the delivered pieces in id order: the
/// directory is byte for byte the one of pdd::resumable_piece_sink in a threaded run.
/// Pieces rank 0 consumes outside mesh_subdomains (N == 1: rank 0 meshes the whole domain) are
/// recorded at finish(). The manifest and `save` matter on rank 0 only.
/// Thread-safety: consume() and report() may run concurrently; the rest from one thread.
class resumable_piece_sink {
public:
  /// False: a piece is on disk, not in memory, once consume returns (see MeshSink).
  static constexpr bool retains_meshes = false;
  /// What saves the manifest on rank 0: called with the manifest, must write it atomically.
  using save_function = manifest_book::save_function;
  /// After a save that took t, the next one waits for a piece reported save_spacing * t later.
  static constexpr int save_spacing = manifest_book::save_spacing;

  /// \throws as pdd::piece_directory_sink's constructor.
  resumable_piece_sink(MPI_Comm comm, std::filesystem::path directory, piece_format format,
                       piece_manifest manifest, save_function save)
      : files_(std::move(directory), format), book_(std::move(manifest), std::move(save)) {
    detail::check(MPI_Comm_rank(comm, &rank_), "MPI_Comm_rank");
  }

  /// Every rank; rank 0 forgets kept pieces with ids from n.
  void start(index_t n) {
    book_.start(n);
    files_.start(n);
  }

  /// Writes the piece and checksums it. \throws pdd::error when writing or reading fails.
  void consume(index_t id, triangle_mesh&& mesh) {
    piece_record r = write_piece_and_checksum(files_, id, std::move(mesh));
    const std::lock_guard lock(mutex_);
    written_[id] = std::move(r);
  }

  /// The record of piece `id` (consumed on this rank) as bytes for recorded().
  std::string report(index_t id) {
    const std::lock_guard lock(mutex_);
    const piece_record& r = written_.at(id);
    detail::byte_writer w;
    w.put_string(r.file);
    w.put(static_cast<std::uint64_t>(r.size));
    w.put(r.checksum);
    w.put(static_cast<std::uint64_t>(r.triangles));
    w.put(static_cast<std::uint64_t>(r.vertices));
    return std::move(w.bytes);
  }

  /// Rank 0: adds the piece report(id) described to the manifest and saves it (see above).
  /// \throws pdd::error when saving fails.
  void recorded(index_t id, std::string_view bytes) {
    const std::string copy(bytes);
    detail::byte_reader in(copy);
    piece_record r;
    r.file = in.get_string();
    r.size = static_cast<std::uintmax_t>(in.get<std::uint64_t>());
    r.checksum = in.get<std::uint64_t>();
    r.triangles = static_cast<std::size_t>(in.get<std::uint64_t>());
    r.vertices = static_cast<std::size_t>(in.get<std::uint64_t>());
    book_.record(id, std::move(r));
  }

  /// Rank 0 (every rank calls it once all have succeeded): records its own pieces not recorded
  /// yet, saves the manifest, then writes the index over the kept and delivered pieces.
  void finish() {
    if (rank_ != 0) return;
    for (auto& [id, record] : written_)
      if (!book_.recorded_here(id)) book_.add(id, record);
    book_.finish(files_.index_path(), files_.format());
  }

  /// Every rank after a failed run: removes the pieces this rank has written; rank 0 also
  /// forgets in the manifest the pieces not kept and saves it (best effort).
  void remove_written() {
    files_.remove_written();
    if (rank_ == 0) book_.forget_recorded();
  }

  /// Rank 0: the ids of the pieces kept from an earlier run (not delivered by this one), sorted.
  const std::vector<index_t>& kept() const noexcept { return book_.kept(); }
  /// Rank 0: the pieces of this run in the manifest.
  std::size_t meshed() const noexcept { return book_.meshed(); }
  /// Rank 0: triangles over the kept and the recorded pieces.
  std::size_t triangles() const noexcept { return book_.triangles(); }
  /// Rank 0: the manifest as it stands (the kept pieces and those recorded so far, with the
  /// fingerprint it was constructed with); on other ranks, the one passed to the constructor.
  const piece_manifest& manifest() const noexcept { return book_.manifest(); }
  /// `<directory>/<index name of the format>`: where rank 0's finish() writes the index (the
  /// same path on every rank).
  std::filesystem::path index_path() const { return files_.index_path(); }

private:
  pdd::piece_directory_sink files_;
  manifest_book book_;
  std::map<index_t, piece_record> written_; ///< this rank's pieces
  std::mutex mutex_;
  int rank_ = 0;
};
static_assert(MeshSink<resumable_piece_sink>);

} // namespace pdd::mpi
