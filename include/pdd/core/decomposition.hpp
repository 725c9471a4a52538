/// \file decomposition.hpp
/// pdd::decomposition: the result of MADD (dissertation ch. 3-4): N subdomains as loops over a
/// shared vertex pool, each loop edge tagged external (an input segment) or interface (a
/// separator edge shared with exactly one neighbour subdomain).
#pragma once

#include <pdd/core/point.hpp>

#include <cstdint>
#include <vector>

namespace pdd {

/// What a subdomain loop edge lies on.
struct edge_tag {
  /// Where a subdomain loop edge lies.
  enum class kind : std::uint8_t {
    external, ///< on an input segment (the domain's boundary or a constraint of it)
    interface ///< on an interface shared with one neighbour subdomain (see interface_curve)
  };
  /// Whether the edge is external or interface; `id`, `marker` and `neighbour` depend on it.
  kind type = kind::external;
  /// external: index of the input segment the edge is part of; interface: the interface id.
  index_t id = no_index;
  /// external, and an interface on an input segment (on_segment): the segment's boundary
  /// marker; a separator's interface edge: unused (0).
  int marker = 0;
  /// interface: the subdomain on the other side; external: no_index.
  index_t neighbour = no_index;
  /// interface: it lies on an input segment between two faces of a general PSLG (an internal
  /// constraint, see pdd::decompose) rather than on a separator; the merged mesh keeps it as a
  /// segment with `marker`.
  bool on_segment = false;
};

/// A constraint inside a subdomain of a general PSLG (pdd::decompose keeps every separator
/// away from it, so the subdomain's kernel meshes it): a segment with one face of the domain
/// on both sides (dangling, or joining two boundary points of that face), or an isolated
/// vertex (b == a, segment == no_index). Its ends may lie on the subdomain's loops.
struct inner_constraint {
  /// \var a
  /// First end: a vertex id in decomposition::vertices (the vertex itself when isolated).
  /// \var b
  /// Second end: a vertex id in decomposition::vertices; equal to `a` for an isolated vertex.
  index_t a = no_index, b = no_index;
  index_t segment = no_index; ///< the input segment; no_index for a vertex
  int marker = 0;             ///< the segment's marker
  /// Memberwise equality (same ends in the same order, same segment and marker).
  friend bool operator==(const inner_constraint&, const inner_constraint&) = default;
};

/// One subdomain: loops[0] is the outer boundary (counter-clockwise), loops[1..] the holes
/// (clockwise). tags[l][i] describes the edge loops[l][i] -> loops[l][(i + 1) % size].
struct subdomain {
  /// The boundary loops as vertex ids in decomposition::vertices: loops[0] the outer boundary
  /// (counter-clockwise), loops[1..] the holes (clockwise); no vertex repeats the first.
  std::vector<std::vector<index_t>> loops;
  /// One tag per loop edge, the same shape as `loops`: tags[l][i] for loops[l][i] ->
  /// loops[l][(i + 1) % loops[l].size()].
  std::vector<std::vector<edge_tag>> tags;
  /// The subdomain's area (outer loop less its holes), in squared input units.
  double area = 0.0;
  std::vector<inner_constraint> inner; ///< general PSLGs only, in input segment order
};

/// An interface: the polyline shared by two subdomains (a < b), as vertex ids in the pool (a
/// separator, or an internal constraint of a general PSLG).
struct interface_curve {
  /// The subdomain on one side, an index in decomposition::subdomains; the smaller of the two.
  index_t a = no_index;
  /// The subdomain on the other side, an index in decomposition::subdomains; b > a.
  index_t b = no_index;
  std::vector<index_t> vertices; ///< the chain, from its lexicographically smaller end
};

/// A decomposition of a domain into subdomains with a shared vertex pool: both sides of an
/// interface refer to the same vertex ids, so their coordinates are bitwise identical.
struct decomposition {
  /// The shared vertex pool: every loop, interface and inner constraint refers to it by index.
  std::vector<point> vertices;
  std::vector<int> vertex_markers; ///< marker of the input vertex or segment, 0 on separators
  /// The subdomains; a subdomain's index here is its id (edge_tag::neighbour,
  /// interface_curve::a and b, the triangle marker of a decoupled mesh).
  std::vector<subdomain> subdomains;
  /// The interfaces; an interface's index here is its id (edge_tag::id of an interface edge).
  std::vector<interface_curve> interfaces;
};

} // namespace pdd
