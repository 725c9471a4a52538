/// \file detail/validate.hpp
/// Implementation of pdd/geometry/validate.hpp: the individual checks.
#pragma once

#include <pdd/core/bbox.hpp>
#include <pdd/core/pslg.hpp>
#include <pdd/errors.hpp>
#include <pdd/geometry/box_pairs.hpp>
#include <pdd/geometry/detail/loops.hpp>
#include <pdd/geometry/detail/pslg_faces.hpp>
#include <pdd/geometry/loops.hpp>

#include <CGAL/intersections.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <numeric>
#include <optional>
#include <string>
#include <tuple>
#include <vector>

namespace pdd::detail {

inline std::string seg_text(const pslg& g, std::size_t s) {
  return "segment " + std::to_string(s) + " (vertices " + std::to_string(g.segments[s].a) + " " +
         pdd::to_string(g.vertices[g.segments[s].a]) + " and " + std::to_string(g.segments[s].b) +
         " " + pdd::to_string(g.vertices[g.segments[s].b]) + ")";
}

/// At least 3 vertices; finite coordinates of vertices, hole points and region points.
inline void check_coordinates(const pslg& g) {
  if (g.vertices.size() < 3)
    throw geometry_error("a PSLG needs at least 3 vertices, this one has " +
                         std::to_string(g.vertices.size()));
  auto finite = [](const point& p) { return std::isfinite(p.x) && std::isfinite(p.y); };
  for (std::size_t i = 0; i < g.vertices.size(); ++i)
    if (!finite(g.vertices[i]))
      throw geometry_error("vertex " + std::to_string(i) + " has a non-finite coordinate " +
                               pdd::to_string(g.vertices[i]),
                           {i});
  for (std::size_t i = 0; i < g.holes.size(); ++i)
    if (!finite(g.holes[i]))
      throw geometry_error("hole point " + std::to_string(i) + " has a non-finite coordinate " +
                               pdd::to_string(g.holes[i]),
                           {i});
  for (std::size_t i = 0; i < g.regions.size(); ++i)
    if (!finite(g.regions[i].p))
      throw geometry_error("region point " + std::to_string(i) + " has a non-finite coordinate " +
                               pdd::to_string(g.regions[i].p),
                           {i});
}

/// No two vertices with exactly equal coordinates. O(V log V).
inline void check_duplicate_vertices(const pslg& g) {
  std::vector<index_t> order(g.vertices.size());
  std::iota(order.begin(), order.end(), index_t{0});
  std::sort(order.begin(), order.end(), [&](index_t a, index_t b) {
    return std::tie(g.vertices[a], a) < std::tie(g.vertices[b], b);
  });
  std::optional<std::pair<index_t, index_t>> first;
  for (std::size_t k = 1; k < order.size(); ++k)
    if (g.vertices[order[k]] == g.vertices[order[k - 1]]) {
      const std::pair<index_t, index_t> p{order[k - 1], order[k]};
      if (!first || p < *first) first = p;
    }
  if (first)
    throw geometry_error("duplicate vertices " + std::to_string(first->first) + " and " +
                             std::to_string(first->second) + " have the same coordinates " +
                             pdd::to_string(g.vertices[first->first]),
                         {first->first, first->second});
}

/// No two segments joining the same two vertices (in either direction). O(S log S).
inline void check_duplicate_segments(const pslg& g) {
  std::vector<std::tuple<index_t, index_t, index_t>> keys;
  keys.reserve(g.segments.size());
  for (std::size_t s = 0; s < g.segments.size(); ++s)
    keys.emplace_back(std::min(g.segments[s].a, g.segments[s].b),
                      std::max(g.segments[s].a, g.segments[s].b), static_cast<index_t>(s));
  std::sort(keys.begin(), keys.end());
  for (std::size_t k = 1; k < keys.size(); ++k)
    if (std::get<0>(keys[k]) == std::get<0>(keys[k - 1]) &&
        std::get<1>(keys[k]) == std::get<1>(keys[k - 1])) {
      const std::size_t s = std::get<2>(keys[k - 1]), t = std::get<2>(keys[k]);
      throw geometry_error("duplicate segments " + std::to_string(s) + " and " + std::to_string(t) +
                               " both join vertices " + std::to_string(std::get<0>(keys[k])) +
                               " and " + std::to_string(std::get<1>(keys[k])),
                           {s, t});
    }
}

/// How two segments meet improperly.
struct segment_clash {
  enum class kind { cross, overlap, touch } type = kind::cross;
  index_t s = 0, t = 0;      ///< the two segments, s < t
  index_t vertex = no_index; ///< touch: the vertex lying in the interior of `on`
  index_t on = no_index;     ///< touch: the segment whose interior holds `vertex`
};

/// Classifies two segments exactly (EPICK predicates); nothing if they only share an
/// endpoint at an angle or are disjoint. \pre distinct vertices, no duplicate segments.
inline std::optional<segment_clash> classify_pair(const pslg& g, index_t s, index_t t) {
  if (s > t) std::swap(s, t);
  const segment &u = g.segments[s], &w = g.segments[t];
  const auto pt = [&](index_t v) { return to_cgal(g.vertices[v]); };
  using kind = segment_clash::kind;
  const bool shared_a = u.a == w.a || u.a == w.b, shared_b = u.b == w.a || u.b == w.b;
  if (shared_a || shared_b) {
    const index_t p = shared_a ? u.a : u.b, q = shared_a ? u.b : u.a;
    const index_t r = w.a == p ? w.b : w.a;
    if (CGAL::collinear(pt(p), pt(q), pt(r)) && CGAL::angle(pt(q), pt(p), pt(r)) == CGAL::ACUTE)
      return segment_clash{kind::overlap, s, t};
    return std::nullopt;
  }
  const epick::Segment_2 su(pt(u.a), pt(u.b)), sw(pt(w.a), pt(w.b));
  if (!CGAL::do_intersect(su, sw)) return std::nullopt;
  if (CGAL::collinear(pt(u.a), pt(u.b), pt(w.a)) && CGAL::collinear(pt(u.a), pt(u.b), pt(w.b)))
    return segment_clash{kind::overlap, s, t};
  for (index_t v : {w.a, w.b})
    if (CGAL::collinear(pt(u.a), pt(u.b), pt(v))) return segment_clash{kind::touch, s, t, v, s};
  for (index_t v : {u.a, u.b})
    if (CGAL::collinear(pt(w.a), pt(w.b), pt(v))) return segment_clash{kind::touch, s, t, v, t};
  return segment_clash{kind::cross, s, t};
}

/// No two segments cross, overlap, or touch in the interior of one of them. Candidate pairs
/// come from pdd::for_each_box_pair on the segments' bounding boxes (O(S log S + K) for K box
/// pairs); each is decided with exact predicates. Reports the clash with the smallest pair of
/// segment ids (deterministic).
inline void check_intersections(const pslg& g) {
  std::vector<bbox> boxes;
  boxes.reserve(g.segments.size());
  for (const segment& sg : g.segments)
    boxes.push_back(segment_box(g.vertices[sg.a], g.vertices[sg.b]));
  std::optional<segment_clash> first;
  std::size_t count = 0;
  for_each_box_pair(boxes, [&](std::size_t x, std::size_t y) {
    const auto c = classify_pair(g, static_cast<index_t>(x), static_cast<index_t>(y));
    if (!c) return;
    ++count;
    if (!first || std::tie(c->s, c->t) < std::tie(first->s, first->t)) first = c;
  });
  if (!first) return;
  const std::string more =
      count > 1 ? " (and " + std::to_string(count - 1) + " more intersecting pairs)" : "";
  using kind = segment_clash::kind;
  if (first->type == kind::touch)
    throw geometry_error("vertex " + std::to_string(first->vertex) + " " +
                             pdd::to_string(g.vertices[first->vertex]) +
                             " lies in the interior of " + seg_text(g, first->on) + more,
                         {first->vertex, first->on});
  throw geometry_error(
      std::string(first->type == kind::cross ? "segments cross: " : "segments overlap: ") +
          seg_text(g, first->s) + " and " + seg_text(g, first->t) + more,
      {first->s, first->t});
}

} // namespace pdd::detail
