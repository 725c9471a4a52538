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
  enum class kind : std::uint8_t { external, interface };
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
  index_t a = no_index, b = no_index; ///< pool vertex ids
  index_t segment = no_index;         ///< the input segment; no_index for a vertex
  int marker = 0;                     ///< the segment's marker
  friend bool operator==(const inner_constraint&, const inner_constraint&) = default;
};

/// One subdomain: loops[0] is the outer boundary (counter-clockwise), loops[1..] the holes
/// (clockwise). tags[l][i] describes the edge loops[l][i] -> loops[l][(i + 1) % size].
struct subdomain {
  std::vector<std::vector<index_t>> loops;
  std::vector<std::vector<edge_tag>> tags;
  double area = 0.0;
  std::vector<inner_constraint> inner; ///< general PSLGs only, in input segment order
};

/// An interface: the polyline shared by two subdomains (a < b), as vertex ids in the pool (a
/// separator, or an internal constraint of a general PSLG).
struct interface_curve {
  index_t a = no_index;
  index_t b = no_index;
  std::vector<index_t> vertices; ///< the chain, from its lexicographically smaller end
};

/// A decomposition of a domain into subdomains with a shared vertex pool: both sides of an
/// interface refer to the same vertex ids, so their coordinates are bitwise identical.
struct decomposition {
  std::vector<point> vertices;
  std::vector<int> vertex_markers; ///< marker of the input vertex or segment, 0 on separators
  std::vector<subdomain> subdomains;
  std::vector<interface_curve> interfaces;
};

} // namespace pdd
