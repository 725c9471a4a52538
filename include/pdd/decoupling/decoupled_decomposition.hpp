/// \file decoupled_decomposition.hpp
/// pdd::decoupled_decomposition: a decomposition whose separators are refined into a
/// decoupling path (dissertation 6.2), ready to be meshed subdomain by subdomain.
#pragma once

#include <pdd/core/decomposition.hpp>
#include <pdd/core/pslg.hpp>
#include <pdd/decoupling/interface_split.hpp>
#include <pdd/errors.hpp>
#include <pdd/madd/subdomain_pslg.hpp>
#include <pdd/shielding/shield_triangle.hpp>

#include <array>
#include <cstddef>
#include <limits>
#include <vector>

namespace pdd {

/// One separator segment of H (an edge of an interface chain) and its refinement into pieces
/// of the decoupling path P (Lemma 9).
struct path_edge {
  index_t u = no_index; ///< pool vertex: the lexicographically smaller endpoint
  index_t v = no_index; ///< pool vertex: the lexicographically larger endpoint
  /// The interface whose chain holds the edge, an index in decomposition::interfaces.
  index_t interface_id = no_index;
  std::array<index_t, 2> sides{no_index, no_index}; ///< the two subdomains, smaller id first
  /// The edge's length |uv|, in input units.
  double length = 0.0;
  double k = 0.0;              ///< the k it is split with: the global k, halved by each repair
  index_t pieces = 1;          ///< nu: the number of pieces (nu - 1 split points)
  std::size_t first_point = 0; ///< its split points are points[first_point + 0 .. nu - 2], u to v
};

/// What the kernel meshes for one subdomain: the pslg of its loops with every interface
/// segment replaced by its pieces, and which segments are interface pieces.
struct subdomain_input {
  /// Vertices: the subdomain's loop vertices and the split points, in loop order. Segments:
  /// external edges with their input marker, interface pieces with pdd::interface_marker.
  pslg domain;
  /// Per segment of `domain`: the path edge it is a piece of, or no_index (external edge).
  std::vector<index_t> segment_path_edge;
};

/// A decomposition with its decoupling path (dissertation 6.2-6.3). Plain value type.
/// Both subdomains beside an interface read the same stored split points, computed once from
/// the canonical orientation (interface_split_point), so interface vertices are bitwise
/// identical on both sides.
struct decoupled_decomposition {
  decomposition parts;             ///< the decomposition (MADD's result)
  double k = 0.0;                  ///< the decoupling parameter used (Theorem 15)
  double lfs_min = 0.0;            ///< min over subdomains of lfs_min of the loops
  double shortest_separator = 0.0; ///< L: shortest separator segment (inf: none)
  double area_term = 0.0;          ///< (1/2) sqrt(A / sqrt 2) (inf: no area bound)
  std::vector<path_edge> path;     ///< the separator segments, in order of discovery
  std::vector<point> points;       ///< split points of all path edges (see first_point)
  /// Per subdomain, per loop edge (loops concatenated in order): its path edge or no_index.
  std::vector<std::vector<index_t>> loop_edge_path;
  /// Per subdomain, its shielded triangles (dissertation 8.1; see pdd::shield_decomposition):
  /// the loops in `parts` are then the shielded D_i', whose shield edges carry
  /// pdd::shield_marker, and each triangle is added to the subdomain's mesh as it is. Empty
  /// (or empty per subdomain) when there are none.
  std::vector<std::vector<shield_triangle>> shields;

  /// The number of shielded triangles.
  std::size_t num_shielded_triangles() const noexcept {
    std::size_t n = 0;
    for (const auto& s : shields)
      n += s.size();
    return n;
  }

  /// N, the number of subdomains (parts.subdomains.size()).
  std::size_t num_subdomains() const noexcept { return parts.subdomains.size(); }

  /// The number of split points currently on the path (vertices added to the separators).
  std::size_t num_split_points() const noexcept {
    std::size_t n = 0;
    for (const path_edge& e : path)
      n += e.pieces - 1;
    return n;
  }

  /// Builds the kernel input of subdomain s.
  /// \pre s < num_subdomains(). Complexity: linear in the size of the subdomain's loops and
  /// split points (expected O(1) hash operations per loop vertex). Thread-safety: const; may be
  /// called concurrently.
  subdomain_input input(index_t s) const {
    PDD_ASSERT(s < num_subdomains());
    subdomain_input in;
    detail::build_subdomain_pslg(
        parts, s, in.domain,
        [&](std::size_t edge, index_t a, index_t b, pslg& g) {
          const index_t e = loop_edge_path[s][edge];
          if (e == no_index) return no_index;
          const path_edge& pe = path[e];
          PDD_ASSERT((a == pe.u && b == pe.v) || (a == pe.v && b == pe.u));
          const bool forward = a == pe.u;
          for (index_t j = 1; j < pe.pieces; ++j) {
            const index_t idx = forward ? j - 1 : pe.pieces - 1 - j;
            g.add_vertex(points[pe.first_point + idx], 0);
          }
          return e;
        },
        in.segment_path_edge, interface_marker);
    return in;
  }

  /// Re-splits path edge e with parameter k_new (an invariance repair halves k). The new split
  /// points are appended to `points`.
  /// \throws as interface_split_count. Complexity O(nu).
  void resplit(index_t e, double k_new) {
    path_edge& pe = path.at(e);
    pe.k = k_new;
    pe.pieces = interface_split_count(pe.length, k_new);
    pe.first_point = points.size();
    const point a = parts.vertices[pe.u], b = parts.vertices[pe.v];
    for (index_t i = 1; i < pe.pieces; ++i)
      points.push_back(interface_split_point(a, b, i, pe.pieces));
  }
};

} // namespace pdd
