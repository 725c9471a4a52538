/// \file invariance.hpp
/// Implementation of pdd::split_interface_pieces: the interface pieces of a subdomain input
/// keyed by their endpoints, and which of them are edges of the mesh.
#pragma once

#include <pdd/core/triangle_mesh.hpp>
#include <pdd/decoupling/decoupled_decomposition.hpp>
#include <pdd/errors.hpp>

#include <algorithm>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace pdd::detail {

/// The key of the undirected edge ab.
inline std::uint64_t undirected_edge_key(index_t a, index_t b) noexcept {
  return (std::uint64_t{std::min(a, b)} << 32) | std::max(a, b);
}

/// The interface pieces of in.domain as sorted (edge key, segment index) pairs.
/// \throws pdd::decoupling_error when m moved an endpoint of one (not bitwise the input's).
inline std::vector<std::pair<std::uint64_t, index_t>>
interface_pieces_by_edge(const subdomain_input& in, const triangle_mesh& m) {
  const pslg& g = in.domain;
  std::vector<std::pair<std::uint64_t, index_t>> pieces;
  for (index_t s = 0; s < g.segments.size(); ++s) {
    if (in.segment_path_edge[s] == no_index) continue;
    const segment& sg = g.segments[s];
    for (const index_t v : {sg.a, sg.b})
      if (!(m.vertices[v] == g.vertices[v]))
        throw decoupling_error("the kernel moved interface vertex " + std::to_string(v));
    pieces.emplace_back(undirected_edge_key(sg.a, sg.b), s);
  }
  std::sort(pieces.begin(), pieces.end());
  return pieces;
}

/// Per piece (in the order of `pieces`): 1 if some triangle of m with both ends among the
/// first n (input) vertices has it as an edge.
inline std::vector<std::uint8_t>
pieces_in_mesh(const std::vector<std::pair<std::uint64_t, index_t>>& pieces, const triangle_mesh& m,
               std::size_t n) {
  std::vector<std::uint8_t> ok(pieces.size(), 0);
  const auto mark = [&](index_t a, index_t b) {
    if (a >= n || b >= n) return;
    const std::uint64_t key = undirected_edge_key(a, b);
    const auto it =
        std::lower_bound(pieces.begin(), pieces.end(), std::pair<std::uint64_t, index_t>{key, 0});
    for (auto j = it; j != pieces.end() && j->first == key; ++j)
      ok[j - pieces.begin()] = 1;
  };
  for (const auto& t : m.triangles) {
    mark(t[0], t[1]);
    mark(t[1], t[2]);
    mark(t[2], t[0]);
  }
  return ok;
}

} // namespace pdd::detail
