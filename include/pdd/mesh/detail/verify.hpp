/// \file verify.hpp
/// Implementation of pdd::verify: the edge table of a triangle mesh, the vertex lookup by
/// coordinates and the walk of an input segment along mesh edges.
#pragma once

#include <pdd/core/kernel.hpp>
#include <pdd/core/point.hpp>
#include <pdd/core/triangle_mesh.hpp>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>
#include <sstream>
#include <string>
#include <unordered_map>
#include <vector>

namespace pdd::detail::verify_impl {

inline constexpr index_t none = std::numeric_limits<index_t>::max();

inline epick::Point_2 to_cgal(const point& p) {
  return {p.x, p.y};
}

/// "(x, y)" with all significant digits.
inline std::string str(const point& p) {
  std::ostringstream os;
  os.precision(17);
  os << '(' << p.x << ", " << p.y << ')';
  return os.str();
}

/// One undirected edge of the mesh: its endpoints (a < b) and the triangles using it.
struct edge_record {
  index_t a = 0, b = 0;
  index_t count = 0;                      ///< number of triangles using the edge
  std::array<index_t, 2> tri{none, none}; ///< the first two of them
  std::array<bool, 2> forward{};          ///< triangle i runs a -> b (else b -> a)
  bool on_segment = false;                ///< covered by an input segment's chain
};

/// All edges of a mesh, grouped by their smaller endpoint (bucket sort: O(V + T), no
/// hashing, deterministic order), with a vertex -> incident edges index.
class edge_table {
public:
  /// \pre valid[t] says whether triangle t has three distinct in-range vertex indices; other
  ///   triangles are left out.
  edge_table(const triangle_mesh& m, const std::vector<char>& valid) {
    build_edges(m, valid);
    build_incidence(m.vertices.size());
  }

  std::vector<edge_record>& edges() noexcept { return edges_; }
  const std::vector<edge_record>& edges() const noexcept { return edges_; }

  /// Ids of the edges incident to vertex v.
  template <class F>
  void for_each_incident(index_t v, F&& f) const {
    for (index_t k = adj_start_[v]; k < adj_start_[v + 1]; ++k)
      f(adj_[k]);
  }

private:
  /// One side of an edge: its larger endpoint b, the triangle and its direction.
  struct half_edge {
    index_t b, t;
    bool forward;
  };

  static index_t min_end(const std::array<index_t, 3>& tri, int i) {
    return std::min(tri[i], tri[(i + 1) % 3]);
  }

  /// The half-edges of the valid triangles bucket-sorted by their smaller endpoint a: those
  /// of vertex a are halves[start[a] .. start[a + 1]).
  static std::vector<half_edge> bucket_half_edges(const triangle_mesh& m,
                                                  const std::vector<char>& valid,
                                                  std::vector<index_t>& start) {
    const std::size_t nv = m.vertices.size();
    start.assign(nv + 1, 0);
    for (std::size_t t = 0; t < m.triangles.size(); ++t)
      if (valid[t])
        for (int i = 0; i < 3; ++i)
          ++start[min_end(m.triangles[t], i) + 1];
    std::partial_sum(start.begin(), start.end(), start.begin());
    std::vector<half_edge> halves(start[nv]);
    std::vector<index_t> fill(start.begin(), start.end() - 1);
    for (std::size_t t = 0; t < m.triangles.size(); ++t) {
      if (!valid[t]) continue;
      const auto& tri = m.triangles[t];
      for (int i = 0; i < 3; ++i) {
        const index_t u = tri[i], v = tri[(i + 1) % 3];
        halves[fill[std::min(u, v)]++] = {std::max(u, v), static_cast<index_t>(t), u < v};
      }
    }
    return halves;
  }

  /// edges_: the half-edges of each bucket sorted by (b, triangle) and merged into records.
  void build_edges(const triangle_mesh& m, const std::vector<char>& valid) {
    std::vector<index_t> start;
    std::vector<half_edge> halves = bucket_half_edges(m, valid, start);
    edges_.reserve(halves.size() / 2 + 16);
    for (index_t a = 0; a < m.vertices.size(); ++a) {
      auto first = halves.begin() + start[a], last = halves.begin() + start[a + 1];
      std::sort(first, last, [](const half_edge& x, const half_edge& y) {
        return x.b != y.b ? x.b < y.b : x.t < y.t;
      });
      for (auto it = first; it != last; ++it) {
        if (it == first || it->b != (it - 1)->b) edges_.push_back({a, it->b});
        edge_record& e = edges_.back();
        if (e.count < 2) {
          e.tri[e.count] = it->t;
          e.forward[e.count] = it->forward;
        }
        ++e.count;
      }
    }
  }

  /// Vertex -> incident edge ids (both endpoints): adj_[adj_start_[v] .. adj_start_[v + 1]).
  void build_incidence(std::size_t nv) {
    adj_start_.assign(nv + 1, 0);
    for (const edge_record& e : edges_) {
      ++adj_start_[e.a + 1];
      ++adj_start_[e.b + 1];
    }
    std::partial_sum(adj_start_.begin(), adj_start_.end(), adj_start_.begin());
    adj_.resize(adj_start_[nv]);
    std::vector<index_t> pos(adj_start_.begin(), adj_start_.end() - 1);
    for (std::size_t k = 0; k < edges_.size(); ++k) {
      adj_[pos[edges_[k].a]++] = static_cast<index_t>(k);
      adj_[pos[edges_[k].b]++] = static_cast<index_t>(k);
    }
  }

  std::vector<edge_record> edges_;
  std::vector<index_t> adj_start_;
  std::vector<index_t> adj_;
};

/// Hash of a point's coordinates (+0.0 and -0.0 hash alike, as they compare equal).
struct point_hash {
  std::size_t operator()(const point& p) const noexcept {
    const auto bits = [](double v) {
      return v == 0.0 ? std::uint64_t{0} : std::bit_cast<std::uint64_t>(v);
    };
    std::uint64_t h = bits(p.x) * 0x9E3779B97F4A7C15ULL;
    h ^= bits(p.y) + 0x7F4A7C15ULL + (h << 6) + (h >> 2);
    return static_cast<std::size_t>(h ^ (h >> 29));
  }
};

/// Coordinates -> the first mesh vertex at them.
using vertex_lookup = std::unordered_map<point, index_t, point_hash>;

/// True if q is on the supporting line of [a, b]: exactly collinear (CGAL orientation), or
/// off it by at most 128 units in the last place of the largest coordinate involved. The
/// tolerance admits the rounded midpoints a Delaunay refinement mesher puts on a segment
/// (each split rounds by at most half an ulp, nested splits add up): there is no exact
/// predicate for "a rounded representation of a point of the segment".
inline bool on_segment_line(const point& a, const point& b, const point& q) {
  if (CGAL::orientation(to_cgal(a), to_cgal(b), to_cgal(q)) == CGAL::COLLINEAR) return true;
  const double dx = b.x - a.x, dy = b.y - a.y;
  const double len = std::hypot(dx, dy);
  const double dist = std::abs(dx * (q.y - a.y) - dy * (q.x - a.x)) / len;
  const double scale = std::max(
      {std::abs(a.x), std::abs(a.y), std::abs(b.x), std::abs(b.y), std::abs(q.x), std::abs(q.y)});
  return dist <= 128.0 * std::numeric_limits<double>::epsilon() * scale;
}

/// Walks from mesh vertex ma to mb along mesh edges whose far ends lie on segment [a, b]
/// (on_segment_line, strictly advancing along it, nearest first); marks the edges used.
/// \returns true if the walk reaches mb.
inline bool walk_segment(edge_table& table, const triangle_mesh& m, index_t ma, index_t mb,
                         std::vector<index_t>& path) {
  const point& a = m.vertices[ma];
  const point& b = m.vertices[mb];
  const double dx = b.x - a.x, dy = b.y - a.y;
  const double len2 = dx * dx + dy * dy;
  const auto param = [&](const point& q) { return ((q.x - a.x) * dx + (q.y - a.y) * dy) / len2; };
  path.clear();
  index_t cur = ma;
  double t_cur = 0.0;
  const std::size_t max_steps = m.vertices.size();
  for (std::size_t step = 0; step < max_steps && cur != mb; ++step) {
    index_t best_edge = none, best_v = none;
    double best_t = 2.0;
    table.for_each_incident(cur, [&](index_t k) {
      const edge_record& e = table.edges()[k];
      const index_t w = e.a == cur ? e.b : e.a;
      if (w == mb) {
        best_edge = k, best_v = w, best_t = -1.0; // the end is adjacent: take it
        return;
      }
      if (best_t < 0.0) return;
      const point& q = m.vertices[w];
      const double t = param(q);
      if (t <= t_cur || t >= 1.0 || t >= best_t || !on_segment_line(a, b, q)) return;
      best_edge = k, best_v = w, best_t = t;
    });
    if (best_edge == none) return false;
    path.push_back(best_edge);
    cur = best_v;
    t_cur = best_t < 0.0 ? 1.0 : best_t;
  }
  if (cur != mb) return false;
  for (const index_t k : path)
    table.edges()[k].on_segment = true;
  return true;
}

} // namespace pdd::detail::verify_impl
