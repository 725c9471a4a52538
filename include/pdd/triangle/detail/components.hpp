/// \file components.hpp
/// The connected components of a PSLG's domain (one outer loop and the hole loops directly
/// inside it) as separate PSLGs, and which component each regional seed point lies in: what
/// Triangle's regional attributes and area bounds (switches A and a) flood, since pdd's
/// domains have no internal segments (pdd::validate).
#pragma once

#include <pdd/core/pslg.hpp>
#include <pdd/errors.hpp>
#include <pdd/geometry/loops.hpp>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_2_algorithms.h>

#include <algorithm>
#include <cstddef>
#include <limits>
#include <vector>

namespace pdd::triangle::detail {

using epick = CGAL::Exact_predicates_inexact_constructions_kernel;

/// One component of the domain: its outer loop and its hole loops (indices into loops).
struct domain_component {
  index_t outer = 0;
  std::vector<index_t> holes;
};

inline constexpr std::size_t no_component = std::numeric_limits<std::size_t>::max();

/// The loop as CGAL points (for the exact point-in-polygon test).
inline std::vector<epick::Point_2> loop_points(const pslg& g, const polygon_loop& l) {
  std::vector<epick::Point_2> pts;
  pts.reserve(l.vertices.size());
  for (const index_t v : l.vertices)
    pts.emplace_back(g.vertices[v].x, g.vertices[v].y);
  return pts;
}

/// True when p lies strictly inside the loop (exact predicates).
inline bool strictly_inside(const std::vector<epick::Point_2>& loop, point p) {
  return CGAL::bounded_side_2(loop.begin(), loop.end(), epick::Point_2(p.x, p.y), epick()) ==
         CGAL::ON_BOUNDED_SIDE;
}

/// The components of a valid PSLG's domain, in the order of their outer loops.
inline std::vector<domain_component> domain_components(const loop_structure& ls) {
  std::vector<domain_component> out;
  std::vector<std::size_t> of_loop(ls.loops.size(), no_component);
  for (std::size_t l = 0; l < ls.loops.size(); ++l)
    if (ls.loops[l].bounds_domain_inside) {
      of_loop[l] = out.size();
      out.push_back({static_cast<index_t>(l), {}});
    }
  for (std::size_t l = 0; l < ls.loops.size(); ++l)
    if (!ls.loops[l].bounds_domain_inside && ls.loops[l].parent != no_index)
      out[of_loop[ls.loops[l].parent]].holes.push_back(static_cast<index_t>(l));
  return out;
}

/// The component that holds p in its interior (inside the outer loop, outside its holes), or
/// no_component (p in a hole, outside the domain or on a segment).
inline std::size_t component_of(const pslg& g, const loop_structure& ls,
                                const std::vector<domain_component>& comps, point p) {
  for (std::size_t c = 0; c < comps.size(); ++c) {
    if (!strictly_inside(loop_points(g, ls.loops[comps[c].outer]), p)) continue;
    bool in_hole = false;
    for (const index_t h : comps[c].holes) {
      const std::vector<epick::Point_2> hole = loop_points(g, ls.loops[h]);
      in_hole = in_hole || CGAL::bounded_side_2(hole.begin(), hole.end(), epick::Point_2(p.x, p.y),
                                                epick()) != CGAL::ON_UNBOUNDED_SIDE;
    }
    if (!in_hole) return c;
  }
  return no_component;
}

/// Component c as a PSLG of its own: the vertices and segments of its loops (vertices in
/// increasing input order, so `input_ids[i]` is the input index of its vertex i) and the hole
/// points strictly inside its outer loop. Regions are not copied.
inline pslg component_pslg(const pslg& g, const loop_structure& ls, const domain_component& c,
                           std::vector<index_t>& input_ids) {
  std::vector<index_t> loops{c.outer};
  loops.insert(loops.end(), c.holes.begin(), c.holes.end());
  input_ids.clear();
  for (const index_t l : loops)
    input_ids.insert(input_ids.end(), ls.loops[l].vertices.begin(), ls.loops[l].vertices.end());
  std::sort(input_ids.begin(), input_ids.end());
  std::vector<index_t> local(g.vertices.size(), no_index);
  pslg out;
  for (std::size_t i = 0; i < input_ids.size(); ++i) {
    local[input_ids[i]] = static_cast<index_t>(i);
    out.add_vertex(g.vertices[input_ids[i]],
                   g.vertex_markers.empty() ? 0 : g.vertex_markers[input_ids[i]]);
  }
  for (const index_t l : loops)
    for (const index_t s : ls.loops[l].segments)
      out.add_segment(local[g.segments[s].a], local[g.segments[s].b], g.segments[s].marker);
  const std::vector<epick::Point_2> outer = loop_points(g, ls.loops[c.outer]);
  for (const point& h : g.holes)
    if (strictly_inside(outer, h)) out.holes.push_back(h);
  return out;
}

} // namespace pdd::triangle::detail
