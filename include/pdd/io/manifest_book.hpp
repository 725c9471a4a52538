/// \file manifest_book.hpp
/// pdd::manifest_book: the bookkeeping of a resumable per-subdomain output's manifest (issue 40),
/// shared by pdd::resumable_piece_sink (threads) and pdd::mpi::resumable_piece_sink (ranks).
#pragma once

#include <pdd/core/index.hpp>
#include <pdd/errors.hpp>
#include <pdd/io/piece_files.hpp>
#include <pdd/io/piece_manifest.hpp>

#include <algorithm>
#include <chrono>
#include <cstddef>
#include <filesystem>
#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace pdd {

/// A manifest as a run fills it: the pieces kept from an earlier run, each finished piece
/// recorded and the manifest saved through `save` (after a piece, unless the last save was
/// less than save_spacing times its duration ago), the index written at the end, and the
/// run's own pieces forgotten after a failure. `save(manifest)` must write the manifest
/// atomically (pdd::write_file_atomically). Not thread-safe: its owner serialises the calls.
class manifest_book {
public:
  /// What saves the manifest: called with the manifest, must write it atomically
  /// (pdd::write_file_atomically); a failure throws pdd::error.
  using save_function = std::function<void(const piece_manifest&)>;
  /// After a save that took t, the next one waits for a piece finishing save_spacing * t
  /// later: the manifest (O(N) bytes) costs at most about 1 / save_spacing of the run instead
  /// of O(N^2) bytes in all; the pieces of the last few saves' time may be meshed again on
  /// resume.
  static constexpr int save_spacing = 20;

  /// `manifest`: the pieces kept from an earlier run (pdd::intact_pieces) with the run's
  /// fingerprint.
  manifest_book(piece_manifest manifest, save_function save)
      : manifest_(std::move(manifest)), save_(std::move(save)) {
    for (const auto& [id, record] : manifest_.pieces)
      kept_.push_back(id);
  }

  /// Forgets the kept pieces with ids from n (a run of n subdomains).
  void start(index_t n) {
    std::erase_if(kept_, [n](index_t id) { return id >= n; });
    std::erase_if(manifest_.pieces, [n](const auto& p) { return p.first >= n; });
  }

  /// Records piece `id` (written again when it was kept) without saving.
  void add(index_t id, piece_record r) {
    std::erase(kept_, id);
    manifest_.pieces[id] = std::move(r);
  }

  /// Records piece `id` and saves the manifest unless the last save was too recent (see
  /// save_spacing). \throws pdd::error when saving fails.
  void record(index_t id, piece_record r) {
    add(id, std::move(r));
    const auto before = std::chrono::steady_clock::now();
    if (before < next_save_) return; // a later piece's save, or finish(), records this one
    save_(manifest_);
    const auto after = std::chrono::steady_clock::now();
    next_save_ = after + save_spacing * (after - before);
  }

  /// True when this run has recorded piece `id` (kept pieces are not this run's).
  bool recorded_here(index_t id) const {
    return manifest_.pieces.contains(id) &&
           std::find(kept_.begin(), kept_.end(), id) == kept_.end();
  }

  /// Saves the manifest, then writes the index over the kept and the recorded pieces in id
  /// order. \throws pdd::error when writing fails.
  void finish(const std::filesystem::path& index, piece_format format) {
    std::vector<std::string> names;
    for (const auto& [id, record] : manifest_.pieces)
      names.push_back(record.file);
    save_(manifest_);
    write_piece_index(index, names, format);
  }

  /// After a failed run: forgets the pieces this run recorded and saves the manifest (best
  /// effort: a manifest that still lists pieces that are gone only makes them be meshed again).
  void forget_recorded() {
    std::erase_if(manifest_.pieces, [this](const auto& p) {
      return std::find(kept_.begin(), kept_.end(), p.first) == kept_.end();
    });
    try {
      save_(manifest_);
    } catch (const error&) {
    }
  }

  /// The ids of the pieces kept from an earlier run (not written by this one), sorted.
  const std::vector<index_t>& kept() const noexcept { return kept_; }
  /// The pieces this run has recorded.
  std::size_t meshed() const noexcept { return manifest_.pieces.size() - kept_.size(); }
  /// Triangles over the kept and the recorded pieces.
  std::size_t triangles() const noexcept {
    std::size_t n = 0;
    for (const auto& [id, record] : manifest_.pieces)
      n += record.triangles;
    return n;
  }
  /// The manifest as it stands: the kept pieces and those recorded so far, with the fingerprint
  /// it was constructed with.
  const piece_manifest& manifest() const noexcept { return manifest_; }

private:
  piece_manifest manifest_;
  save_function save_;
  std::vector<index_t> kept_;
  std::chrono::steady_clock::time_point next_save_{}; ///< record() saves from then on
};

} // namespace pdd
