/// \file region.hpp
/// Implementation detail of MADD (dissertation ch. 3-4): the working representation of one
/// subdomain ("region") while it is being decomposed, and the small geometric helpers every
/// MADD step shares (canonical midpoints, angles, areas).
///
/// Vertices are identified by their exact coordinates throughout MADD: a region stores its
/// loops as points, and two regions that share an edge store bitwise-identical endpoints. Edge
/// splits are exact midpoint bisections computed from the edge's canonical orientation
/// (lexicographically smaller endpoint first), so every region that refines the same edge
/// produces the same points.
#pragma once

#include <pdd/core/decomposition.hpp>
#include <pdd/core/point.hpp>
#include <pdd/core/triangle_measures.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <numbers>
#include <utility>
#include <vector>

namespace pdd::detail {

/// What a region edge lies on while MADD runs: a piece of an input segment (external) or of
/// a separator inserted earlier (the neighbour is found at the end, from the shared edges).
struct madd_edge_tag {
  bool external = false;
  index_t segment = no_index; ///< external: the input segment
  int marker = 0;             ///< external: the input segment's marker
  friend bool operator==(const madd_edge_tag&, const madd_edge_tag&) = default;
};

/// One closed loop of a region; the region lies to the left of the traversal.
struct madd_loop {
  std::vector<point> points;
  std::vector<int> markers;        ///< vertex markers, as decomposition::vertex_markers
  std::vector<madd_edge_tag> tags; ///< tags[i]: edge points[i] -> points[(i + 1) % n]
  std::size_t size() const noexcept { return points.size(); }
};

/// A constraint inside a region of a general PSLG (issue 13) that no separator may touch, so
/// that it lies inside one subdomain and its kernel meshes it: a segment with the region on
/// both sides (a dangling segment, or one joining two points of the region's boundary), or an
/// isolated vertex (`b == a`, `segment == no_index`). Its ends may lie on the region's loops.
struct madd_feature {
  point a, b;
  int marker_a = 0, marker_b = 0; ///< vertex markers
  index_t segment = no_index;     ///< the input segment, no_index for an isolated vertex
  int marker = 0;                 ///< the segment's marker
  bool is_vertex() const noexcept { return segment == no_index; }
  friend bool operator==(const madd_feature&, const madd_feature&) = default;
};

/// A region: loops[0] is the outer loop (counter-clockwise), loops[1..] the holes (clockwise),
/// and the features inside it (general PSLGs only).
struct madd_region {
  std::vector<madd_loop> loops;
  double area = 0.0;
  std::vector<madd_feature> features;
  /// Never split: a cap around a small angle between faces (detail::cap_corners).
  bool keep_whole = false;
};

/// A vertex that a split kept on an edge of its region (a separator ends there). Every region
/// that has the edge (lo, hi) must get m as well (madd_registry).
struct madd_edge_split {
  point lo, hi;   ///< the region edge, canonical orientation (lo < hi)
  double t = 0.0; ///< dyadic parameter of m on lo -> hi (0 < t < 1, exact)
  point m;        ///< the vertex
  int marker = 0; ///< its marker (the segment's marker on external edges, else 0)
};

/// The midpoint of segment pq computed from its canonical orientation: bitwise identical for
/// (p, q) and (q, p).
inline point canonical_midpoint(point p, point q) noexcept {
  if (q < p) std::swap(p, q);
  return {p.x + 0.5 * (q.x - p.x), p.y + 0.5 * (q.y - p.y)};
}

/// Euclidean distance.
inline double distance(point a, point b) noexcept {
  return std::hypot(b.x - a.x, b.y - a.y);
}

/// The angle at v between the rays v->a and v->b, in degrees, in [0, 180].
inline double angle_deg(point v, point a, point b) noexcept {
  const double ux = a.x - v.x, uy = a.y - v.y, wx = b.x - v.x, wy = b.y - v.y;
  return std::atan2(std::abs(ux * wy - uy * wx), ux * wx + uy * wy) * (180.0 / std::numbers::pi);
}

/// The interior angle at v of a loop traversed prev -> v -> next with the inside on the left,
/// in degrees, in [0, 360): the counter-clockwise angle from v->next to v->prev.
inline double interior_angle_deg(point prev, point v, point next) noexcept {
  const double a1 = std::atan2(next.y - v.y, next.x - v.x);
  const double a2 = std::atan2(prev.y - v.y, prev.x - v.x);
  double d = (a2 - a1) * (180.0 / std::numbers::pi);
  while (d < 0.0)
    d += 360.0;
  while (d >= 360.0)
    d -= 360.0;
  return d;
}

/// Area of a region: outer loop area minus the holes' (sum of the signed loop areas).
inline double region_area(const madd_region& r) noexcept {
  double a = 0.0;
  for (const madd_loop& l : r.loops)
    a += polygon_signed_area(l.points);
  return a;
}

/// Number of vertices of a region (all loops).
inline std::size_t region_vertex_count(const madd_region& r) noexcept {
  std::size_t n = 0;
  for (const madd_loop& l : r.loops)
    n += l.size();
  return n;
}

/// Total boundary length of a region.
inline double region_perimeter(const madd_region& r) noexcept {
  double s = 0.0;
  for (const madd_loop& l : r.loops)
    for (std::size_t i = 0; i < l.size(); ++i)
      s += distance(l.points[i], l.points[(i + 1) % l.size()]);
  return s;
}

/// Tiny union-find with path halving and union by size (deterministic: the representative of
/// a merged class depends only on the sequence of unite calls).
class union_find {
public:
  explicit union_find(std::size_t n = 0) { reset(n); }
  void reset(std::size_t n) {
    parent_.resize(n);
    size_.assign(n, 1);
    for (std::size_t i = 0; i < n; ++i)
      parent_[i] = static_cast<std::uint32_t>(i);
  }
  std::uint32_t find(std::uint32_t x) noexcept {
    while (parent_[x] != x) {
      parent_[x] = parent_[parent_[x]];
      x = parent_[x];
    }
    return x;
  }
  /// Merges the classes of a and b; returns false if they were one class already.
  bool unite(std::uint32_t a, std::uint32_t b) noexcept {
    a = find(a);
    b = find(b);
    if (a == b) return false;
    if (size_[a] < size_[b] || (size_[a] == size_[b] && b < a)) std::swap(a, b);
    parent_[b] = a;
    size_[a] += size_[b];
    return true;
  }
  std::size_t size() const noexcept { return parent_.size(); }

private:
  std::vector<std::uint32_t> parent_;
  std::vector<std::uint32_t> size_;
};

} // namespace pdd::detail
