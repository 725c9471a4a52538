/// \file resumable_piece_sink.hpp
/// pdd::resumable_piece_sink: a per-subdomain output that keeps its manifest
/// (io/piece_manifest.hpp) as pieces complete, so that a killed run can be resumed (issue 40).
#pragma once

#include <pdd/concepts/mesh_sink.hpp>
#include <pdd/core/triangle_mesh.hpp>
#include <pdd/errors.hpp>
#include <pdd/io/manifest_book.hpp>
#include <pdd/io/piece_files.hpp>
#include <pdd/io/piece_manifest.hpp>
#include <pdd/mesh/sinks.hpp>

#include <cstddef>
#include <filesystem>
#include <mutex>
#include <utility>
#include <vector>

namespace pdd {

/// Writes piece `id` through `files` and reads it back: its record for the manifest (file,
/// size, checksum: pdd::piece_checksum) with its triangle and vertex counts.
/// \throws pdd::error when writing or reading fails.
inline piece_record write_piece_and_checksum(piece_directory_sink& files, index_t id,
                                             triangle_mesh&& mesh) {
  const std::size_t triangles = mesh.triangles.size(), vertices = mesh.vertices.size();
  files.consume(id, std::move(mesh));
  piece_record r = piece_checksum(files.directory() / piece_file_name(id, files.format()));
  r.triangles = triangles;
  r.vertices = vertices;
  return r;
}

/// A MeshSink over a piece_directory_sink that records every piece it writes in a manifest
/// (its size and checksum, pdd::piece_checksum, read back from the file) and saves the
/// manifest through `save` as pieces complete (after a piece, unless the last save was too
/// recent, see save_spacing) and at finish(): a run killed at any moment leaves a manifest that
/// lists only complete pieces. A resumed run passes the manifest of the pieces
/// it keeps (pdd::intact_pieces; they are not meshed again, see
/// pipeline::keep_subdomains): the index written at finish() lists the kept and the delivered
/// pieces in id order, so that the directory is byte for byte the one of an uninterrupted run.
/// A kept piece that is delivered after all (an invariance repair, or N == 1 after a fallback)
/// is written again and counts as meshed; start(n) forgets kept pieces with ids from n.
/// `save(manifest)` must write the manifest atomically (pdd::write_file_atomically); it is
/// called under a lock, one call at a time.
/// Thread-safety: consume() may run concurrently; the rest from one thread.
class resumable_piece_sink {
public:
  /// False: a piece is on disk, not in memory, once consume returns (see MeshSink).
  static constexpr bool retains_meshes = false;
  /// What saves the manifest: called with the manifest, must write it atomically.
  using save_function = manifest_book::save_function;
  /// The spacing of the manifest's saves during the run (manifest_book::save_spacing: after a
  /// save that took t, the next waits for a piece finishing save_spacing * t later).
  static constexpr int save_spacing = manifest_book::save_spacing;

  /// \throws as piece_directory_sink's constructor.
  resumable_piece_sink(std::filesystem::path directory, piece_format format,
                       piece_manifest manifest, save_function save)
      : files_(std::move(directory), format), book_(std::move(manifest), std::move(save)) {}

  /// Forgets the kept pieces with ids from n (a run of n subdomains) and reserves room for n
  /// pieces' sizes.
  void start(index_t n) {
    const std::lock_guard lock(mutex_);
    book_.start(n);
    files_.start(n);
  }

  /// Writes the piece, checksums it and saves the manifest with it (manifest_book::record).
  /// \throws pdd::error when writing or saving fails.
  void consume(index_t id, triangle_mesh&& mesh) {
    piece_record r = write_piece_and_checksum(files_, id, std::move(mesh));
    const std::lock_guard lock(mutex_);
    book_.record(id, std::move(r));
  }

  /// Saves the manifest and writes the index over the kept and delivered pieces.
  void finish() { book_.finish(files_.index_path(), files_.format()); }

  /// Removes the pieces this sink has written (not the kept ones) and forgets them in the
  /// manifest, which is saved (best effort, for a failed run).
  void remove_written() {
    files_.remove_written();
    const std::lock_guard lock(mutex_);
    book_.forget_recorded();
  }

  /// The ids of the pieces kept from an earlier run (not delivered by this one), sorted.
  const std::vector<index_t>& kept() const noexcept { return book_.kept(); }
  /// The pieces this sink has written.
  std::size_t meshed() const noexcept { return book_.meshed(); }
  /// Triangles over the kept and the written pieces.
  std::size_t triangles() const noexcept { return book_.triangles(); }
  /// The manifest as it stands: the kept pieces and those written so far, with the
  /// fingerprint it was constructed with (what the last save wrote, or newer).
  const piece_manifest& manifest() const noexcept { return book_.manifest(); }
  /// `<directory>/<index name of the format>`: where finish() writes the index.
  std::filesystem::path index_path() const { return files_.index_path(); }

private:
  piece_directory_sink files_;
  manifest_book book_;
  std::mutex mutex_;
};
static_assert(MeshSink<resumable_piece_sink>);

} // namespace pdd
