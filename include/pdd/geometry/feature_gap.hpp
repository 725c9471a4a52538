/// \file feature_gap.hpp
/// pdd::feature_gap_field: the local feature size at every point of a PSLG domain, in the form
/// a mesh-size estimate needs (the feature gap), with the two features that give it.
#pragma once

#include <pdd/core/point.hpp>
#include <pdd/core/pslg.hpp>
#include <pdd/geometry/detail/feature_gap.hpp>
#include <pdd/geometry/loops.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

namespace pdd {

/// The two features whose distances from a point give its feature gap; `apex` is the vertex
/// the two segments share when they meet there at a domain-side angle below 60 deg
/// (no_index otherwise).
struct feature_pair {
  /// \var first
  /// One of the two features (a vertex or a segment of the PSLG).
  /// \var second
  /// The other feature; when the gap comes through a vertex's own gap, that vertex's nearest
  /// non-incident feature.
  pslg_feature first, second;
  /// The vertex shared by two segments meeting at a domain-side angle below 60 deg (the gap
  /// across their wedge); no_index otherwise.
  index_t apex = no_index;
};

/// The feature gap at a point and the features that give it.
struct gap_sample {
  /// The feature gap at the point, in input units (0 at the apex of a small angle; infinity
  /// when no two separated features are near).
  double gap = std::numeric_limits<double>::infinity();
  /// The two features that give `gap` (meaningless while gap is infinity).
  feature_pair pair;
};

/// The feature gap of a PSLG domain: at a point x, the smallest d(x, f) + d(x, h) over two
/// separated features f, h near x. Two features are separated when they are not incident
/// (Ruppert's local feature size, dissertation Definition 1), and also when they are the two
/// segments of a domain-side angle below 60 deg and x is nearer to both than to their apex
/// (across a narrow wedge the quality mesh must resolve the wedge's width; Ruppert's lfs
/// ignores incident segments, which is why it says nothing about a needle). The gap lies
/// between Ruppert's lfs(x) and 2 lfs(x) where no small angle is near, is 2-Lipschitz, and
/// across a corridor or wedge of width w it is w at every point of the cross-section.
///
/// Computed on the domain's constrained Delaunay triangulation (CGAL, exact predicates):
/// "near x" is the features (vertices, constrained edges) of the domain triangle holding x and
/// of its neighbours across unconstrained edges; a segment counts only from its domain side.
/// Farther features enter through the vertices' own gaps: gap(x) <= gap(v) + 2 |x - v| for
/// the triangle's vertices v (gap(v): distance from v to the nearest non-incident feature
/// near v). This is an estimate of the local feature size, not a bound in either direction:
/// features seen only beyond the neighbours of a triangle are missed.
/// Thread-safety: const member functions may be called concurrently.
class feature_gap_field {
public:
  /// Domain-side angles below this are small (pdd shields them, dissertation 8.1).
  static constexpr double small_angle_deg = 60.0;

  /// \pre g is valid (pdd::validate). \throws pdd::geometry_error as pdd::find_loops.
  /// Complexity O(n log n) expected.
  explicit feature_gap_field(const pslg& g) : g_(&g) {
    detail::loops_with_triangulation lt;
    detail::find_loops_into(g, lt);
    sides_ = detail::orient_loops(g, lt.structure);
    const detail::segment_incidence inc = detail::incident_segments(g);
    const detail::pslg_cdt& cdt = lt.triangulation.cdt;
    std::vector<std::vector<index_t>> faces_at(g.vertices.size());
    offsets_.push_back(0);
    for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
      if (!detail::in_domain(f)) continue;
      const auto t = static_cast<index_t>(corners_.size());
      corners_.push_back({f->vertex(0)->info(), f->vertex(1)->info(), f->vertex(2)->info()});
      for (const index_t v : corners_.back())
        faces_at[v].push_back(t);
      std::size_t own = 0;
      const auto near = detail::face_features(g, inc, lt.triangulation, f, own);
      own_.push_back(features_.size() + own);
      features_.insert(features_.end(), near.begin(), near.end());
      offsets_.push_back(features_.size());
    }
    compute_vertex_gaps(faces_at);
  }

  /// The triangles of the domain's constrained Delaunay triangulation (deterministic order).
  std::size_t size() const noexcept { return corners_.size(); }
  /// The PSLG vertex ids of triangle t (counter-clockwise).
  const std::array<index_t, 3>& triangle(std::size_t t) const { return corners_[t]; }
  /// The PSLG this field was built for.
  const pslg& domain() const noexcept { return *g_; }
  /// The domain-side angle at vertex v in degrees.
  double angle_deg(index_t v) const { return sides_.angle_deg[v]; }
  /// gap(v): the distance from v to the nearest non-incident feature near it (infinity: none).
  double vertex_gap(index_t v) const { return vertex_gap_[v]; }
  /// The smallest vertex gap: an estimate of lfs_min (Definition 7) from the local features.
  double min_vertex_gap() const {
    return vertex_gap_.empty() ? std::numeric_limits<double>::infinity()
                               : *std::min_element(vertex_gap_.begin(), vertex_gap_.end());
  }

  /// The gap at x, a point of triangle t (or near it). Complexity O(k^2) for the k <= 15
  /// features near t.
  /// At the apex of a small angle itself the gap is 0 (the limit inside the wedge), given by
  /// the angle's two segments.
  gap_sample at(const point& x, std::size_t t) const {
    for (const index_t v : corners_[t])
      if (x == g_->vertices[v] && sides_.angle_deg[v] < small_angle_deg)
        return {0.0,
                {{pslg_feature::kind::segment, sides_.segments_at[v][0]},
                 {pslg_feature::kind::segment, sides_.segments_at[v][1]},
                 v}};
    const std::size_t b = offsets_[t], e = offsets_[t + 1];
    std::array<double, 32> d{};
    const std::size_t k = std::min<std::size_t>(e - b, d.size());
    for (std::size_t i = 0; i < k; ++i)
      d[i] = detail::feature_distance(*g_, sides_, x, features_[b + i], b + i < own_[t]);
    gap_sample best;
    for (std::size_t i = 0; i < k; ++i)
      for (std::size_t j = i + 1; j < k; ++j) {
        if (!(d[i] + d[j] < best.gap)) continue;
        const index_t apex = separation(x, features_[b + i], features_[b + j], d[i], d[j]);
        if (apex == not_separated) continue;
        best = {d[i] + d[j], {features_[b + i], features_[b + j], apex}};
      }
    for (const index_t v : corners_[t]) {
      const double through_v = vertex_gap_[v] + 2.0 * distance(x, g_->vertices[v]);
      if (through_v < best.gap)
        best = {through_v, {{pslg_feature::kind::vertex, v}, vertex_nearest_[v], no_index}};
    }
    return best;
  }

private:
  static constexpr index_t not_separated = no_index - 1;

  static double distance(const point& p, const point& q) {
    return std::hypot(p.x - q.x, p.y - q.y);
  }

  /// no_index when f and h are separated as non-incident features, their apex when they are
  /// the segments of a small angle that x sees as separated, not_separated otherwise.
  index_t separation(const point& x, pslg_feature f, pslg_feature h, double df, double dh) const {
    using k = pslg_feature::kind;
    if (f.type == k::vertex && h.type == k::vertex) return no_index;
    if (f.type == k::vertex) return detail::is_end(*g_, h.id, f.id) ? not_separated : no_index;
    if (h.type == k::vertex) return detail::is_end(*g_, f.id, h.id) ? not_separated : no_index;
    const index_t apex = detail::shared_end(*g_, f.id, h.id);
    if (apex == no_index) return no_index;
    if (sides_.angle_deg[apex] < small_angle_deg &&
        std::max(df, dh) < distance(x, g_->vertices[apex]))
      return apex;
    return not_separated;
  }

  /// gap(v) and the feature giving it, from the features near the triangles at v.
  void compute_vertex_gaps(const std::vector<std::vector<index_t>>& faces_at) {
    const std::size_t n = g_->vertices.size();
    vertex_gap_.assign(n, std::numeric_limits<double>::infinity());
    vertex_nearest_.assign(n, pslg_feature{});
    for (index_t v = 0; v < n; ++v)
      for (const index_t t : faces_at[v])
        for (std::size_t i = offsets_[t]; i < offsets_[t + 1]; ++i) {
          const pslg_feature f = features_[i];
          if ((f.type == pslg_feature::kind::vertex && f.id == v) ||
              (f.type == pslg_feature::kind::segment && detail::is_end(*g_, f.id, v)))
            continue;
          const double dv = detail::feature_distance(*g_, sides_, g_->vertices[v], f, false);
          if (dv < vertex_gap_[v]) {
            vertex_gap_[v] = dv;
            vertex_nearest_[v] = f;
          }
        }
  }

  const pslg* g_;
  detail::loop_sides sides_;
  std::vector<std::array<index_t, 3>> corners_;
  std::vector<pslg_feature> features_; ///< features near triangle t: [offsets_[t], offsets_[t+1])
  std::vector<std::size_t> offsets_;
  std::vector<std::size_t> own_; ///< triangle t's own features end at own_[t]
  std::vector<double> vertex_gap_;
  std::vector<pslg_feature> vertex_nearest_;
};

} // namespace pdd
