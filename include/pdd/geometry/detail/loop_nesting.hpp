/// \file loop_nesting.hpp
/// Implementation of pdd::find_loops: tracing the loops, and their nesting by a flood of the
/// constrained Delaunay triangulation from the unbounded face.
#pragma once

#include <pdd/core/pslg.hpp>
#include <pdd/core/triangulation_levels.hpp>
#include <pdd/errors.hpp>
#include <pdd/geometry/detail/loops.hpp>
#include <pdd/geometry/loop_structure.hpp>

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace pdd::detail {

/// Traces the loops of a PSLG whose vertices all have degree 2; fills loop_of_segment.
/// Complexity O(V + S).
inline std::vector<polygon_loop> trace_loops(const pslg& g, const segment_incidence& inc,
                                             std::vector<index_t>& loop_of_segment) {
  std::vector<polygon_loop> loops;
  loop_of_segment.assign(g.segments.size(), no_index);
  std::vector<char> seen(g.vertices.size(), 0);
  for (index_t start = 0; start < g.vertices.size(); ++start) {
    if (seen[start]) continue;
    const auto id = static_cast<index_t>(loops.size());
    polygon_loop loop;
    index_t v = start;
    index_t s = std::min(inc.first_two[start][0], inc.first_two[start][1]);
    do {
      seen[v] = 1;
      loop.vertices.push_back(v);
      loop.segments.push_back(s);
      loop_of_segment[s] = id;
      v = other_end(g, s, v);
      s = inc.first_two[v][0] == s ? inc.first_two[v][1] : inc.first_two[v][0];
    } while (v != start);
    if (loop.vertices.size() < 3)
      throw geometry_error("segments " + id_list(loop.segments) +
                               " join the same two vertices (duplicate segments)",
                           std::vector<std::size_t>(loop.segments.begin(), loop.segments.end()));
    loop.signed_area = shoelace_area(g, loop.vertices);
    loop.counterclockwise = cycle_is_ccw(g, loop.vertices);
    loops.push_back(std::move(loop));
  }
  return loops;
}

/// The loop whose segment is the constrained edge i of face f.
/// \throws geometry_error when the edge is only part of a segment (a vertex lies in the
/// segment's interior).
inline index_t loop_across(const pslg& g, const segment_incidence& inc, const loop_triangulation& t,
                           pslg_cdt::Face_handle f, int i) {
  const index_t u = f->vertex(pslg_cdt::cw(i))->info();
  const index_t w = f->vertex(pslg_cdt::ccw(i))->info();
  const index_t s = segment_between(g, inc, u, w);
  if (s == no_index)
    throw geometry_error("a vertex lies in the interior of a segment, at vertex " +
                             std::to_string(u) + " or " + std::to_string(w) +
                             "; pdd::validate names it",
                         {u, w});
  return t.loop_of_segment[s];
}

/// The pdd::flood_levels visitor of flood_nesting: records each loop's depth and parent when
/// the flood first meets one of its segments, and each face's owner (innermost enclosing loop).
struct nesting_visitor {
  using face = pslg_cdt::Face_handle;
  const pslg& graph;
  const segment_incidence& incidence;
  const loop_triangulation& triangulation;
  std::vector<polygon_loop>& loops;

  void constraint(face f, int i) const {
    polygon_loop& l = loops[loop_across(graph, incidence, triangulation, f, i)];
    if (l.depth < 0) {
      l.depth = f->info().level;
      l.parent = f->info().owner;
    }
    PDD_ASSERT(l.depth == f->info().level);
  }
  void labelled(face n, face f, int i) const {
    if (f == face()) return; // the infinite face: owner no_index
    n->info().owner =
        f->is_constrained(i) ? loop_across(graph, incidence, triangulation, f, i) : f->info().owner;
  }
};

/// Sets depth and parent of every loop, and level and owner (innermost enclosing loop) of
/// every face, by pdd::flood_levels from the infinite face: crossing a segment of loop l from
/// a face at level d enters the inside of l, so depth(l) = d and parent(l) = that face's owner.
inline void flood_nesting(const pslg& g, const segment_incidence& inc, loop_triangulation& t,
                          std::vector<polygon_loop>& loops) {
  if (loops.empty()) return;
  if (t.cdt.dimension() < 2)
    throw geometry_error("all vertices are collinear, so the segments overlap; pdd::validate "
                         "names them");
  for (auto& l : loops)
    l.depth = -1;
  flood_levels(
      t.cdt, [](pslg_cdt::Face_handle f) -> int& { return f->info().level; },
      nesting_visitor{g, inc, t, loops});
  for (auto& l : loops) {
    PDD_ASSERT(l.depth >= 0);
    l.bounds_domain_inside = l.depth % 2 == 0;
  }
}

/// Loops plus the labelled triangulation they were nested with (shared by validate, lfs and
/// the angle computations so the CDT is built once).
struct loops_with_triangulation {
  loop_structure structure;
  loop_triangulation triangulation;
};

/// find_loops, keeping the triangulation. \see find_loops
inline void find_loops_into(const pslg& g, loops_with_triangulation& out) {
  const segment_incidence inc = incident_segments(g);
  require_degree_two(g, inc);
  out.structure.loops = trace_loops(g, inc, out.triangulation.loop_of_segment);
  build_cdt(g, out.triangulation);
  flood_nesting(g, inc, out.triangulation, out.structure.loops);
}

/// True if a face of the labelled triangulation belongs to the meshed domain.
inline bool in_domain(pslg_cdt::Face_handle f) {
  return f->info().level % 2 == 1;
}

} // namespace pdd::detail
