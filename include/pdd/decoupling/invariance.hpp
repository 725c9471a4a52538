/// \file invariance.hpp
/// The invariance check of the decoupling path (Corollary 13): after a subdomain is meshed,
/// every interface piece must still be an edge of its mesh.
#pragma once

#include <pdd/concepts/delaunay_mesher.hpp>
#include <pdd/decoupling/decoupled_decomposition.hpp>
#include <pdd/errors.hpp>

#include <algorithm>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace pdd {

/// The interface pieces of `in` that are not edges of the mesh in `r` (Corollary 13 says there
/// are none): those the kernel reports in split_segments and, independently of that report,
/// those that no triangle of r.mesh has as an edge. Returns their segment indices in
/// `in.domain`, sorted.
/// \pre r is the kernel's result for in.domain (input vertices first).
/// \throws pdd::decoupling_error when the mesh lacks an input vertex or an interface vertex is
/// not bitwise the input one (both sides of an interface would then differ).
/// Complexity O(T + P log P) for T triangles and P pieces. Thread-safety: reentrant.
inline std::vector<index_t> split_interface_pieces(const subdomain_input& in,
                                                   const mesher_result& r) {
  const pslg& g = in.domain;
  const triangle_mesh& m = r.mesh;
  const std::size_t n = g.vertices.size();
  if (m.vertices.size() < n)
    throw decoupling_error("the mesh has fewer vertices than its input (" +
                           std::to_string(m.vertices.size()) + " < " + std::to_string(n) + ")");
  const auto key = [](index_t a, index_t b) {
    return (std::uint64_t{std::min(a, b)} << 32) | std::max(a, b);
  };
  std::vector<std::pair<std::uint64_t, index_t>> pieces; // (edge key, segment index)
  for (index_t s = 0; s < g.segments.size(); ++s) {
    if (in.segment_path_edge[s] == no_index) continue;
    const segment& sg = g.segments[s];
    for (const index_t v : {sg.a, sg.b})
      if (!(m.vertices[v] == g.vertices[v]))
        throw decoupling_error("the kernel moved interface vertex " + std::to_string(v));
    pieces.emplace_back(key(sg.a, sg.b), s);
  }
  std::sort(pieces.begin(), pieces.end());
  std::vector<std::uint8_t> ok(pieces.size(), 0);
  const auto mark = [&](index_t a, index_t b) {
    if (a >= n || b >= n) return;
    const auto it = std::lower_bound(pieces.begin(), pieces.end(),
                                     std::pair<std::uint64_t, index_t>{key(a, b), 0});
    for (auto j = it; j != pieces.end() && j->first == key(a, b); ++j)
      ok[j - pieces.begin()] = 1;
  };
  for (const auto& t : m.triangles) {
    mark(t[0], t[1]);
    mark(t[1], t[2]);
    mark(t[2], t[0]);
  }
  std::vector<index_t> failed;
  for (std::size_t j = 0; j < pieces.size(); ++j)
    if (!ok[j] ||
        std::binary_search(r.split_segments.begin(), r.split_segments.end(), pieces[j].second))
      failed.push_back(pieces[j].second);
  std::sort(failed.begin(), failed.end());
  return failed;
}

} // namespace pdd
