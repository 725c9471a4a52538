/// \file subdomain_pslg.hpp
/// Implementation of decoupled_decomposition::input and decouple: a subdomain's loops as a
/// pslg, and loop areas.
#pragma once

#include <pdd/core/decomposition.hpp>
#include <pdd/core/pslg.hpp>
#include <pdd/core/segment_markers.hpp>
#include <pdd/core/triangle_measures.hpp>
#include <pdd/errors.hpp>

#include <cmath>
#include <cstddef>
#include <unordered_map>
#include <vector>

namespace pdd::detail {

/// Adds every loop vertex of sd to g once, in loop order; local maps pool ids to g's ids.
/// Returns the number of loop edges (space for as many segments is reserved in g).
inline std::size_t add_loop_vertices(const decomposition& d, const subdomain& sd, pslg& g,
                                     std::unordered_map<index_t, index_t>& local) {
  std::size_t total = 0;
  for (const auto& loop : sd.loops)
    total += loop.size();
  local.reserve(total);
  g.vertices.reserve(total);
  g.vertex_markers.reserve(total);
  g.segments.reserve(total);
  for (const auto& loop : sd.loops)
    for (const index_t v : loop) {
      PDD_ASSERT(v < d.vertices.size());
      if (local.emplace(v, static_cast<index_t>(g.vertices.size())).second)
        g.add_vertex(d.vertices[v], v < d.vertex_markers.size() ? d.vertex_markers[v] : 0);
    }
  return total;
}

/// Adds the inner constraints of sd (a general PSLG's dangling segments and isolated vertices
/// inside it) to g after its loops: their vertices once (those on the loops are there
/// already), their segments with the input marker (segment_path_edge: no_index).
inline void add_inner_constraints(const decomposition& d, const subdomain& sd, pslg& g,
                                  std::unordered_map<index_t, index_t>& local,
                                  std::vector<index_t>& segment_path_edge) {
  auto vertex = [&](index_t v) {
    const auto [it, added] = local.emplace(v, static_cast<index_t>(g.vertices.size()));
    if (added) g.add_vertex(d.vertices[v], v < d.vertex_markers.size() ? d.vertex_markers[v] : 0);
    return it->second;
  };
  for (const inner_constraint& c : sd.inner) {
    const index_t a = vertex(c.a), b = vertex(c.b);
    if (c.segment == no_index) continue;
    g.add_segment(a, b, c.marker);
    segment_path_edge.push_back(no_index);
  }
}

/// Builds subdomain s of d as a pslg into g: first every loop vertex once (in loop order;
/// a vertex repeated in the loops is added once), then, per loop edge a -> b, the points
/// `on_interface(edge, a, b, g)` appends (in the order a -> b; it returns the path edge id, or
/// no_index to add none) and the segments a -> points -> b. External edges carry their tag's
/// marker, interface edges `interface_mark` (pdd::interface_marker), except that an interface
/// on an input segment (edge_tag::on_segment) carries the segment's marker on the side of the
/// smaller subdomain id, so that the merged mesh keeps the segment once, and the points added on
/// it carry that marker on both sides. For every segment,
/// segment_path_edge receives the id on_interface returned (no_index: external). The inner
/// constraints come last (add_inner_constraints).
/// Complexity: linear in the output (expected).
template <class OnInterface>
void build_subdomain_pslg(const decomposition& d, index_t s, pslg& g, OnInterface&& on_interface,
                          std::vector<index_t>& segment_path_edge, int interface_mark) {
  const subdomain& sd = d.subdomains[s];
  std::unordered_map<index_t, index_t> local;
  segment_path_edge.reserve(add_loop_vertices(d, sd, g, local));
  std::size_t edge = 0;
  for (std::size_t l = 0; l < sd.loops.size(); ++l) {
    const auto& loop = sd.loops[l];
    for (std::size_t i = 0; i < loop.size(); ++i, ++edge) {
      const index_t a = loop[i], b = loop[(i + 1) % loop.size()];
      const edge_tag& tag = sd.tags[l][i];
      if (tag.type == edge_tag::kind::external) {
        g.add_segment(local[a], local[b], tag.marker);
        segment_path_edge.push_back(no_index);
        continue;
      }
      const auto first = static_cast<index_t>(g.vertices.size());
      const index_t e = on_interface(edge, a, b, g);
      const auto last = static_cast<index_t>(g.vertices.size());
      const int mark = tag.on_segment && s < tag.neighbour ? tag.marker : interface_mark;
      if (tag.on_segment) // points on an input segment carry its marker, as in Triangle
        for (index_t q = first; q < last; ++q)
          g.vertex_markers[q] = tag.marker;
      index_t prev = local[a];
      for (index_t q = first; q < last; ++q) {
        g.add_segment(prev, q, mark);
        segment_path_edge.push_back(e);
        prev = q;
      }
      g.add_segment(prev, local[b], mark);
      segment_path_edge.push_back(e);
    }
  }
  add_inner_constraints(d, sd, g, local, segment_path_edge);
}

/// Signed area of one loop of pool vertices (shoelace, pdd::detail::polygon_signed_area;
/// positive when counter-clockwise).
inline double loop_signed_area(const decomposition& d, const std::vector<index_t>& loop) {
  return polygon_signed_area(loop.size(), [&](std::size_t i) { return d.vertices[loop[i]]; });
}

/// Area of subdomain s: its stored area when positive, else outer loop minus holes.
inline double subdomain_area(const decomposition& d, index_t s) {
  const subdomain& sd = d.subdomains[s];
  if (sd.area > 0.0) return sd.area;
  double a = 0.0;
  for (std::size_t l = 0; l < sd.loops.size(); ++l) {
    const double la = std::abs(loop_signed_area(d, sd.loops[l]));
    a += l == 0 ? la : -la;
  }
  return a;
}

} // namespace pdd::detail
