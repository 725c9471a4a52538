/// \file invariance.hpp
/// The invariance check of the decoupling path (Corollary 13): after a subdomain is meshed,
/// every interface piece must still be an edge of its mesh.
#pragma once

#include <pdd/concepts/delaunay_mesher.hpp>
#include <pdd/decoupling/decoupled_decomposition.hpp>
#include <pdd/decoupling/detail/invariance.hpp>
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
  const auto pieces = detail::interface_pieces_by_edge(in, m);
  const std::vector<std::uint8_t> ok = detail::pieces_in_mesh(pieces, m, n);
  std::vector<index_t> failed;
  for (std::size_t j = 0; j < pieces.size(); ++j)
    if (!ok[j] ||
        std::binary_search(r.split_segments.begin(), r.split_segments.end(), pieces[j].second))
      failed.push_back(pieces[j].second);
  std::sort(failed.begin(), failed.end());
  return failed;
}

} // namespace pdd
