/// \file merge.hpp
/// Implementation of pdd::merge_meshes: a deterministic, parallel merge of subdomain meshes
/// whose shared vertices are identified by exact coordinates.
#pragma once

#include <pdd/core/triangle_mesh.hpp>
#include <pdd/decoupling/decoupled_decomposition.hpp>
#include <pdd/errors.hpp>
#include <pdd/parallel/parallel_for.hpp>

#include <algorithm>
#include <bit>
#include <cstdint>
#include <limits>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

namespace pdd::detail {

/// Exact hash of a point (-0.0 and +0.0 hash alike, as they compare equal).
struct exact_point_hash {
  std::size_t operator()(const point& p) const noexcept {
    const auto bits = [](double v) { return std::bit_cast<std::uint64_t>(v == 0.0 ? 0.0 : v); };
    std::uint64_t h = bits(p.x) * 0x9E3779B97F4A7C15ull;
    h ^= bits(p.y) + 0x7F4A7C159E3779B9ull + (h << 6) + (h >> 2);
    return static_cast<std::size_t>(h ^ (h >> 31));
  }
};

/// A boundary vertex of part s that an earlier part owns: local id b, owner (part, local id).
struct shared_vertex {
  index_t local;
  index_t owner_part;
  index_t owner_local;
};

/// Per part: sorted unique local ids of its segment endpoints (its boundary vertices, the only
/// ones another part can share) and its number of non-interface segments.
inline void boundary_vertices(const triangle_mesh& m, std::vector<index_t>& out,
                              std::size_t& kept_segments) {
  out.clear();
  out.reserve(2 * m.segments.size());
  kept_segments = 0;
  for (const mesh_edge& e : m.segments) {
    out.push_back(e.a);
    out.push_back(e.b);
    if (e.marker != interface_marker) ++kept_segments;
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
}

/// Where each part goes in the merged mesh: its vertices shared with earlier parts (by local
/// id), and the offsets of its own vertices, its triangles and its kept segments.
struct merge_layout {
  std::vector<std::vector<shared_vertex>> shared;
  std::vector<std::size_t> voff, toff, soff;
};

/// Finds the shared vertices, in part order (sequential: only boundary vertices are hashed),
/// and the offsets of every part. \throws decoupling_error on two vertices of one part at the
/// same point, limit_error when the merged mesh needs more than 32-bit indices.
inline merge_layout plan_merge(const std::vector<triangle_mesh>& parts,
                               const std::vector<std::vector<index_t>>& boundary,
                               const std::vector<std::size_t>& kept) {
  const std::size_t np = parts.size();
  merge_layout ml{std::vector<std::vector<shared_vertex>>(np), std::vector<std::size_t>(np + 1, 0),
                  std::vector<std::size_t>(np + 1, 0), std::vector<std::size_t>(np + 1, 0)};
  std::unordered_map<point, std::pair<index_t, index_t>, exact_point_hash> owner;
  std::size_t nb = 0;
  for (const auto& b : boundary)
    nb += b.size();
  owner.reserve(nb);
  for (std::size_t s = 0; s < np; ++s) {
    const triangle_mesh& m = parts[s];
    for (const index_t b : boundary[s]) {
      PDD_ASSERT(b < m.vertices.size());
      const auto [it, fresh] = owner.try_emplace(m.vertices[b], static_cast<index_t>(s), b);
      if (!fresh) {
        if (it->second.first == s)
          throw decoupling_error("merge: subdomain " + std::to_string(s) +
                                 " has two vertices at the same point");
        ml.shared[s].push_back({b, it->second.first, it->second.second});
      }
    }
    ml.voff[s + 1] = ml.voff[s] + m.vertices.size() - ml.shared[s].size();
    ml.toff[s + 1] = ml.toff[s] + m.triangles.size();
    ml.soff[s + 1] = ml.soff[s] + kept[s];
  }
  if (ml.voff[np] >= std::numeric_limits<index_t>::max() ||
      ml.toff[np] >= std::numeric_limits<index_t>::max())
    throw limit_error("merged mesh too large for 32-bit indices (" + std::to_string(ml.voff[np]) +
                      " vertices, " + std::to_string(ml.toff[np]) + " triangles)");
  return ml;
}

/// The global id of vertex v of part s, a vertex that part s owns.
inline index_t global_of_owned(const merge_layout& ml, std::size_t s, index_t v) {
  const auto& sh = ml.shared[s];
  const auto below =
      std::lower_bound(sh.begin(), sh.end(), v,
                       [](const shared_vertex& x, index_t y) { return x.local < y; }) -
      sh.begin();
  return static_cast<index_t>(ml.voff[s] + v - static_cast<std::size_t>(below));
}

/// Copies part s into its place in `out` (sized by plan_merge), renumbering its vertices.
inline void copy_part(const merge_layout& ml, std::size_t s, const triangle_mesh& m,
                      triangle_mesh& out) {
  const auto& shared = ml.shared[s];
  std::vector<index_t> map(m.vertices.size());
  std::size_t j = 0, rank = ml.voff[s];
  for (index_t v = 0; v < m.vertices.size(); ++v) {
    if (j < shared.size() && shared[j].local == v) {
      map[v] = global_of_owned(ml, shared[j].owner_part, shared[j].owner_local);
      ++j;
      continue;
    }
    map[v] = static_cast<index_t>(rank++);
    out.vertices[map[v]] = m.vertices[v];
    out.vertex_markers[map[v]] = v < m.vertex_markers.size() ? m.vertex_markers[v] : 0;
  }
  for (std::size_t t = 0; t < m.triangles.size(); ++t) {
    const auto& tri = m.triangles[t];
    out.triangles[ml.toff[s] + t] = {map[tri[0]], map[tri[1]], map[tri[2]]};
    out.triangle_markers[ml.toff[s] + t] = static_cast<int>(s);
  }
  std::size_t k = ml.soff[s];
  for (const mesh_edge& e : m.segments)
    if (e.marker != interface_marker)
      out.segments[k++] = {std::min(map[e.a], map[e.b]), std::max(map[e.a], map[e.b]), e.marker};
}

/// Merges parts (part i: triangle marker i) into one mesh. Global numbering: part 0's
/// vertices in its order, then each later part's vertices that no earlier part has, in its
/// order; triangles and non-interface segments in part order. Deterministic for any `threads`.
inline triangle_mesh merge_parts(std::vector<triangle_mesh>& parts, unsigned threads) {
  const std::size_t np = parts.size();
  std::vector<std::vector<index_t>> boundary(np);
  std::vector<std::size_t> kept(np);
  parallel_for_index(np, threads,
                     [&](std::size_t s) { boundary_vertices(parts[s], boundary[s], kept[s]); });
  const merge_layout ml = plan_merge(parts, boundary, kept);
  triangle_mesh out;
  out.vertices.resize(ml.voff[np]);
  out.vertex_markers.resize(ml.voff[np]);
  out.triangles.resize(ml.toff[np]);
  out.triangle_markers.resize(ml.toff[np]);
  out.segments.resize(ml.soff[np]);
  parallel_for_index(np, threads, [&](std::size_t s) {
    copy_part(ml, s, parts[s], out);
    parts[s] = triangle_mesh{}; // release the part as soon as it is copied
  });
  return out;
}

} // namespace pdd::detail
