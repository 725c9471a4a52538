/// \file resumable_piece_sink.hpp
/// pdd::resumable_piece_sink: a per-subdomain output that keeps its manifest
/// (io/piece_manifest.hpp) as pieces complete, so that a killed run can be resumed (issue 40).
#pragma once

#include <pdd/concepts/mesh_sink.hpp>
#include <pdd/core/triangle_mesh.hpp>
#include <pdd/errors.hpp>
#include <pdd/io/piece_files.hpp>
#include <pdd/io/piece_manifest.hpp>
#include <pdd/mesh/sinks.hpp>

#include <algorithm>
#include <chrono>
#include <cstddef>
#include <filesystem>
#include <functional>
#include <map>
#include <mutex>
#include <string>
#include <utility>
#include <vector>

namespace pdd {

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
  static constexpr bool retains_meshes = false;
  using save_function = std::function<void(const piece_manifest&)>;

  /// \throws as piece_directory_sink's constructor.
  resumable_piece_sink(std::filesystem::path directory, piece_format format,
                       piece_manifest manifest, save_function save)
      : files_(std::move(directory), format), manifest_(std::move(manifest)),
        save_(std::move(save)) {
    for (const auto& [id, record] : manifest_.pieces)
      kept_.push_back(id);
  }

  void start(index_t n) {
    const std::lock_guard lock(mutex_);
    std::erase_if(kept_, [n](index_t id) { return id >= n; });
    std::erase_if(manifest_.pieces, [n](const auto& p) { return p.first >= n; });
    files_.start(n);
  }

  /// Writes the piece, checksums it and saves the manifest with it.
  /// \throws pdd::error when writing or saving fails.
  void consume(index_t id, triangle_mesh&& mesh) {
    const std::size_t triangles = mesh.triangles.size(), vertices = mesh.vertices.size();
    files_.consume(id, std::move(mesh));
    piece_record r = piece_checksum(files_.directory() / piece_file_name(id, files_.format()));
    r.triangles = triangles;
    r.vertices = vertices;
    const std::lock_guard lock(mutex_);
    std::erase(kept_, id);
    manifest_.pieces[id] = std::move(r);
    const auto before = std::chrono::steady_clock::now();
    if (before < next_save_) return; // a later piece's save, or finish(), records this one
    save_(manifest_);
    const auto after = std::chrono::steady_clock::now();
    next_save_ = after + save_spacing * (after - before);
  }

  /// After a save that took t, the next one waits for a piece finishing save_spacing * t later:
  /// the manifest (O(N) bytes) costs at most about 1 / save_spacing of the run instead of
  /// O(N^2) bytes in all; the pieces of the last few saves' time may be meshed again on resume.
  static constexpr int save_spacing = 20;

  /// Writes the index over the kept and delivered pieces and saves the manifest.
  void finish() {
    std::vector<std::string> names;
    for (const auto& [id, record] : manifest_.pieces)
      names.push_back(record.file);
    save_(manifest_);
    write_piece_index(files_.index_path(), names, files_.format());
  }

  /// Removes the pieces this sink has written (not the kept ones) and forgets them in the
  /// manifest, which is saved (best effort, for a failed run).
  void remove_written() {
    files_.remove_written();
    const std::lock_guard lock(mutex_);
    std::erase_if(manifest_.pieces, [this](const auto& p) {
      return std::find(kept_.begin(), kept_.end(), p.first) == kept_.end();
    });
    try {
      save_(manifest_);
    } catch (const error&) { // best effort: the manifest lists pieces that are gone
    }
  }

  /// The ids of the pieces kept from an earlier run (not delivered by this one), sorted.
  const std::vector<index_t>& kept() const noexcept { return kept_; }
  /// The pieces this sink has written.
  std::size_t meshed() const noexcept { return manifest_.pieces.size() - kept_.size(); }
  /// Triangles over the kept and the written pieces.
  std::size_t triangles() const noexcept {
    std::size_t n = 0;
    for (const auto& [id, record] : manifest_.pieces)
      n += record.triangles;
    return n;
  }
  const piece_manifest& manifest() const noexcept { return manifest_; }
  std::filesystem::path index_path() const { return files_.index_path(); }

private:
  piece_directory_sink files_;
  piece_manifest manifest_;
  save_function save_;
  std::vector<index_t> kept_;
  std::mutex mutex_;
  std::chrono::steady_clock::time_point next_save_{}; ///< consume() saves from then on
};
static_assert(MeshSink<resumable_piece_sink>);

} // namespace pdd
