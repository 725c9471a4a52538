/// \file statistics_sink.hpp
/// pdd::statistics_sink: a MeshSink decorator that measures every subdomain mesh on its way to
/// another sink, so that runs which keep nothing in memory (vtu_directory_sink,
/// counting_sink) still report angles, ratios, areas and the shielded triangles.
#pragma once

#include <pdd/concepts/mesh_sink.hpp>
#include <pdd/concepts/sizing_field.hpp>
#include <pdd/core/pslg.hpp>
#include <pdd/core/triangle_mesh.hpp>
#include <pdd/mesh/quality.hpp>
#include <pdd/shielding/shield_statistics.hpp>
#include <pdd/sizing/uniform.hpp>

#include <algorithm>
#include <mutex>
#include <utility>
#include <vector>

namespace pdd {

/// Adds the statistics of a part to `total`: extremes, area, histogram and counts. The vertex
/// count is summed, so vertices on an interface count once per part that has them.
/// Complexity O(1). Thread-safety: reentrant.
inline void accumulate(mesh_statistics& total, const mesh_statistics& part) {
  if (part.triangles == 0) return;
  total.min_angle_deg =
      total.triangles == 0 ? part.min_angle_deg : std::min(total.min_angle_deg, part.min_angle_deg);
  total.max_angle_deg = std::max(total.max_angle_deg, part.max_angle_deg);
  total.max_ratio = std::max(total.max_ratio, part.max_ratio);
  total.max_area = std::max(total.max_area, part.max_area);
  total.max_area_ratio = std::max(total.max_area_ratio, part.max_area_ratio);
  for (std::size_t k = 0; k < total.angle_histogram.size(); ++k)
    total.angle_histogram[k] += part.angle_histogram[k];
  total.area += part.area;
  total.triangles += part.triangles;
  total.vertices += part.vertices;
}

/// Adds the shielding statistics of a part (of the same domain) to `total`. A part without
/// unshielded triangles (max_ratio_unshielded == 0: every triangle has a positive ratio) leaves
/// the unshielded minimum angle alone. Complexity O(1). Thread-safety: reentrant.
inline void accumulate(shielding_statistics& total, const shielding_statistics& part) {
  if (part.max_ratio_unshielded > 0.0)
    total.min_angle_unshielded_deg =
        total.max_ratio_unshielded == 0.0
            ? part.min_angle_unshielded_deg
            : std::min(total.min_angle_unshielded_deg, part.min_angle_unshielded_deg);
  total.max_ratio_unshielded = std::max(total.max_ratio_unshielded, part.max_ratio_unshielded);
  total.shielded_triangles += part.shielded_triangles;
  total.min_input_angle_deg = std::min(total.min_input_angle_deg, part.min_input_angle_deg);
  total.max_ratio_shielded = std::max(total.max_ratio_shielded, part.max_ratio_shielded);
  total.max_shield_angle_error_deg =
      std::max(total.max_shield_angle_error_deg, part.max_shield_angle_error_deg);
}

/// compute_shielding_statistics(m, angles), given s = compute_statistics(m, ...): a domain
/// without small input angles has no shielded triangle, so the unshielded extremes are the
/// mesh's own (the same triangle chosen by the same key in the same order: bitwise the same
/// values), and no second pass over the triangles is made (it had been 6 % of pdd-mesh's time
/// on the pipe at 16M triangles). With small angles: compute_shielding_statistics.
/// Complexity O(1) without small angles, else O(T log s). Thread-safe.
inline shielding_statistics shielding_statistics_of(const triangle_mesh& m,
                                                    const small_input_angles& angles,
                                                    const mesh_statistics& s) {
  if (!angles.apexes.empty()) return compute_shielding_statistics(m, angles);
  shielding_statistics st;
  st.min_input_angle_deg = angles.min_input_angle_deg;
  st.min_angle_unshielded_deg = s.min_angle_deg;
  st.max_ratio_unshielded = s.max_ratio;
  return st;
}

/// A MeshSink that computes compute_statistics (against `sizing`) and
/// compute_shielding_statistics (against `domain`) of every subdomain mesh and passes the mesh
/// on to `inner`. The totals (statistics(), shielding()) are combined in subdomain id order at
/// finish(), so they are bitwise the same for any thread count; a repeated id (invariance
/// repair) replaces its part. Shielded triangles lie inside one subdomain, so the per-part
/// shielding statistics add up to those of the merged mesh; so do the angles, ratios, areas and
/// histogram (vertices: see accumulate).
/// \tparam Inner a MeshSink. \tparam S a SizingField.
/// Thread-safety: consume() may run concurrently (as the inner sink's); the rest from one thread.
/// `inner` must outlive the sink (the domain's small input angles are found once, in the
/// constructor).
template <MeshSink Inner, SizingField S = uniform_sizing>
class statistics_sink {
public:
  /// The inner sink's: this decorator keeps per-subdomain statistics, not meshes.
  static constexpr bool retains_meshes = sink_retains_meshes<Inner>;

  /// Measures every mesh against `sizing` (area ratios) and the small input angles of
  /// `domain` (found here, once) before passing it on to `inner`.
  statistics_sink(Inner& inner, const pslg& domain, S sizing = {})
      : inner_(inner), angles_(find_small_input_angles(domain)), sizing_(std::move(sizing)) {}

  /// Reserves room for n subdomains' statistics and passes start(n) on to the inner sink.
  void start(index_t n) {
    {
      const std::lock_guard lock(mutex_);
      if (parts_.size() < n) parts_.resize(n);
    }
    start_sink(inner_, n);
  }

  /// Measures the mesh, then hands it to the inner sink.
  void consume(index_t id, triangle_mesh&& mesh) {
    part p{true, compute_statistics(mesh, sizing_), {}};
    p.shielding = shielding_statistics_of(mesh, angles_, p.stats);
    {
      const std::lock_guard lock(mutex_);
      if (parts_.size() <= id) parts_.resize(id + std::size_t{1});
      parts_[id] = std::move(p);
    }
    inner_.consume(id, std::move(mesh));
  }

  /// Combines the parts in id order, then finishes the inner sink.
  void finish() {
    total_ = {};
    shielding_ = {};
    for (const part& p : parts_) {
      if (!p.delivered) continue;
      accumulate(total_, p.stats);
      accumulate(shielding_, p.shielding);
    }
    inner_.finish();
  }

  /// The statistics of all parts (after finish()).
  const mesh_statistics& statistics() const noexcept { return total_; }
  /// The shielding statistics of all parts (after finish()).
  const shielding_statistics& shielding() const noexcept { return shielding_; }

private:
  struct part {
    bool delivered = false;
    mesh_statistics stats;
    shielding_statistics shielding;
  };
  Inner& inner_;
  small_input_angles angles_; ///< the domain's, found once (not per subdomain)
  S sizing_;
  std::mutex mutex_;
  std::vector<part> parts_;
  mesh_statistics total_;
  shielding_statistics shielding_;
};

} // namespace pdd
