/// \file mesh_tables.hpp
/// What Triangle's outputs need beyond pdd's mesh: input vertices numbered first, in input
/// order (Triangle's .node order); unused vertices dropped (switch j); the neighbour table
/// (switch n); the edge counts of Triangle's statistics.
#pragma once

#include <pdd/core/pslg.hpp>
#include <pdd/core/triangle_mesh.hpp>
#include <pdd/errors.hpp>

#include <algorithm>
#include <array>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

namespace pdd::triangle::detail {

/// One key per undirected edge {a, b} (the smaller id in the high half).
inline std::uint64_t edge_key(index_t a, index_t b) {
  return (std::uint64_t{std::min(a, b)} << 32) | std::max(a, b);
}

/// Applies a vertex renumbering (new_id[old] for every old vertex, no_index: dropped) to the
/// mesh; `count` is the number of new ids.
inline void renumber_vertices(triangle_mesh& m, const std::vector<index_t>& new_id,
                              std::size_t count) {
  std::vector<point> v(count);
  std::vector<int> markers(count, 0);
  for (std::size_t i = 0; i < m.vertices.size(); ++i)
    if (new_id[i] != no_index) {
      v[new_id[i]] = m.vertices[i];
      markers[new_id[i]] = m.vertex_markers.empty() ? 0 : m.vertex_markers[i];
    }
  m.vertices = std::move(v);
  m.vertex_markers = std::move(markers);
  for (auto& t : m.triangles)
    for (index_t& i : t)
      i = new_id[i];
  for (mesh_edge& e : m.segments) {
    e.a = new_id[e.a];
    e.b = new_id[e.b];
  }
}

/// Renumbers the mesh so that the input vertices come first, in input order (found by their
/// exact coordinates: pdd's kernels copy input vertices bit for bit), then the Steiner
/// vertices in mesh order. Input vertex markers are kept.
/// \throws internal_error if an input vertex is missing from the mesh.
inline void input_vertices_first(triangle_mesh& m, const pslg& input) {
  const auto key = [](point p) {
    return std::pair{std::bit_cast<std::uint64_t>(p.x), std::bit_cast<std::uint64_t>(p.y)};
  };
  struct hash {
    std::size_t operator()(const std::pair<std::uint64_t, std::uint64_t>& k) const noexcept {
      return std::hash<std::uint64_t>{}(k.first * 0x9E3779B97F4A7C15ULL ^ k.second);
    }
  };
  std::unordered_map<std::pair<std::uint64_t, std::uint64_t>, index_t, hash> input_id;
  input_id.reserve(input.vertices.size());
  for (std::size_t i = 0; i < input.vertices.size(); ++i)
    input_id.emplace(key(input.vertices[i]), static_cast<index_t>(i));
  std::vector<index_t> new_id(m.vertices.size(), no_index);
  std::size_t next = input.vertices.size(), found = 0;
  for (std::size_t i = 0; i < m.vertices.size(); ++i) {
    const auto it = input_id.find(key(m.vertices[i]));
    if (it != input_id.end() && new_id[i] == no_index) {
      new_id[i] = it->second;
      ++found;
    } else {
      new_id[i] = static_cast<index_t>(next++);
    }
  }
  PDD_ASSERT(found == input.vertices.size());
  renumber_vertices(m, new_id, next);
}

/// Drops the vertices no triangle uses (Triangle's switch j), keeping the order of the rest,
/// and their `width` values in `per_vertex` (vertex by vertex) with them. Returns the number
/// dropped.
inline std::size_t jettison_unused_vertices(triangle_mesh& m,
                                            std::vector<double>* per_vertex = nullptr,
                                            std::size_t width = 0) {
  std::vector<char> used(m.vertices.size(), 0);
  for (const auto& t : m.triangles)
    for (const index_t i : t)
      used[i] = 1;
  std::vector<index_t> new_id(m.vertices.size(), no_index);
  std::size_t next = 0;
  for (std::size_t i = 0; i < used.size(); ++i) {
    if (!used[i]) continue;
    if (per_vertex)
      for (std::size_t k = 0; k < width; ++k)
        (*per_vertex)[next * width + k] = (*per_vertex)[i * width + k];
    new_id[i] = static_cast<index_t>(next++);
  }
  if (per_vertex) per_vertex->resize(next * width);
  const std::size_t dropped = m.vertices.size() - next;
  if (dropped != 0) renumber_vertices(m, new_id, next);
  return dropped;
}

/// Triangle's edge counts: all edges and the boundary edges (edges of one triangle).
struct edge_counts {
  std::size_t edges = 0;
  std::size_t boundary = 0;
};
inline edge_counts count_edges(const std::vector<std::array<long long, 3>>& nb) {
  edge_counts c;
  for (const auto& t : nb)
    for (const long long n : t)
      c.boundary += n < 0;
  c.edges = (3 * nb.size() + c.boundary) / 2;
  return c;
}

} // namespace pdd::triangle::detail
