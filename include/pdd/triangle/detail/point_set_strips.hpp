/// \file point_set_strips.hpp
/// Implementation of pdd::triangle::triangulate's quality mesh of a large vertex set on the
/// decoupled engine (issue 35 item 1). MADD keeps its separators away from isolated vertices,
/// so it cannot split the hull of a dense vertex set; here the separators go through the
/// vertices instead: paths of Gabriel edges of the vertices' Delaunay triangulation (the disk
/// on such an edge as diameter holds no other vertex, so no input vertex encroaches a piece of
/// it), each from one side of the hull to the other near a cut line that balances the strips'
/// areas, at >= 61 deg to itself at every vertex and (by a perpendicular to a hull edge) at 90
/// deg to the hull at its ends: no angle below 60 deg for the kernels. The hull and the paths
/// make a PSLG of N faces (strips), which the pipeline decouples from its faces.
#pragma once

#include <pdd/core/kernel.hpp>
#include <pdd/core/point.hpp>
#include <pdd/triangle/detail/point_set.hpp>
#include <pdd/triangle/detail/point_set_cuts.hpp>

#include <CGAL/enum.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <functional>
#include <limits>
#include <queue>
#include <utility>
#include <vector>

namespace pdd::triangle::detail {

/// What the search for the cut paths knows: the Gabriel graph (the i-th neighbour of a is
/// directed edge first[a] + i, whose tail is a), which vertices no path may enter (the hull's,
/// those of earlier paths), the bounds on a path, and Dijkstra's labels per directed edge
/// (reset through `touched`): a label on a -> w is a path ending with that edge, so that the
/// turn at w is known where the path goes on.
struct strip_search {
  const std::vector<point>& v;
  const std::vector<std::vector<index_t>>& gabriel;
  std::vector<std::size_t> first;
  std::vector<index_t> tail;
  std::vector<char> blocked;
  cut_candidates candidates; ///< the axis, the shortest edge, the nearest neighbours
  double half_band = 0.0;    ///< how far from its cut line a path may go
  double max_length = 0.0;   ///< the longest path edge (its disk reaches no band but the next)
  std::vector<double> cost;
  std::vector<std::size_t> pred; ///< the edge before; tail.size() + i: start candidate i
  std::vector<std::size_t> touched;
};

/// The search state for the vertices v, their Gabriel graph and the cut candidates.
inline strip_search make_strip_search(const std::vector<point>& v,
                                      const std::vector<std::vector<index_t>>& gabriel,
                                      cut_candidates candidates) {
  strip_search s{v,   gabriel, {}, {}, std::vector<char>(v.size(), 0), std::move(candidates), 0.0,
                 0.0, {},      {}, {}};
  for (std::size_t a = 0; a < v.size(); ++a) {
    s.first.push_back(s.tail.size());
    s.tail.insert(s.tail.end(), gabriel[a].size(), static_cast<index_t>(a));
  }
  s.cost.assign(s.tail.size(), std::numeric_limits<double>::infinity());
  s.pred.assign(s.tail.size(), 0);
  return s;
}

/// One cut's search: its line, the candidate ends on either side of the hull, and the points
/// no disk on a path edge may hold (the candidate ends of this cut and of its neighbours).
struct cut_task {
  double line = 0.0;
  std::array<std::vector<cut_end>, 2> ends;
  std::vector<point> guarded;
};

/// Whether a point of t.guarded lies strictly inside the disk with diameter w-x (exact, after
/// a floating-point filter).
inline bool holds_cut_end(const strip_search& s, const cut_task& t, index_t w, index_t x) {
  const point p = s.v[w], q = s.v[x], mid{0.5 * (p.x + q.x), 0.5 * (p.y + q.y)};
  const double reach = 0.5 * std::hypot(q.x - p.x, q.y - p.y) * (1.0 + 1e-9) + 1e-300;
  for (const point e : t.guarded)
    if (std::hypot(e.x - mid.x, e.y - mid.y) < reach &&
        CGAL::side_of_bounded_circle(epick::Point_2(p.x, p.y), epick::Point_2(q.x, q.y),
                                     epick::Point_2(e.x, e.y)) == CGAL::ON_BOUNDED_SIDE)
      return true;
  return false;
}

/// Whether a path at w, reached from the point `prev`, may go on to x: x is free, inside the
/// band and no nearer than min_length to any vertex; the edge is between min_length and
/// max_length long, turns by >= `min_angle` at w and holds no cut end in its disk. (A vertex
/// nearer than a piece's length to a path vertex would be a feature smaller than k beside the
/// path: the kernels refine there and split the pieces.)
inline bool path_step_ok(const strip_search& s, const cut_task& t, point prev, index_t w, index_t x,
                         double min_angle) {
  const cut_candidates& cc = s.candidates;
  if (s.blocked[x] || cc.nearest[x] < cc.min_length ||
      std::abs(along(s.v[x], cc.axis) - t.line) > s.half_band)
    return false;
  const double length = std::hypot(s.v[x].x - s.v[w].x, s.v[x].y - s.v[w].y);
  if (length < cc.min_length || length > s.max_length) return false;
  return angle_deg(prev, s.v[w], s.v[x]) >= min_angle && !holds_cut_end(s, t, w, x);
}

/// The weight of the path edge a-b: its length times 1 + 4 |distance of its middle to the
/// line| / half_band, which keeps the path near its line.
inline double path_weight(const strip_search& s, double line, index_t a, index_t b) {
  const point pa = s.v[a], pb = s.v[b];
  const int axis = s.candidates.axis;
  const double off = std::abs(0.5 * (along(pa, axis) + along(pb, axis)) - line);
  return std::hypot(pb.x - pa.x, pb.y - pa.y) * (1.0 + 4.0 * off / s.half_band);
}

/// The head of directed edge e.
inline index_t edge_head(const strip_search& s, std::size_t e) {
  return s.gabriel[s.tail[e]][e - s.first[s.tail[e]]];
}

} // namespace pdd::triangle::detail

namespace pdd::triangle::detail {

/// A path found for one cut: its vertices (input ids, from its end on side 1 to its start on
/// side 0) and its two cut ends; no vertices when none was found.
struct cut_path_result {
  std::vector<index_t> vertices;
  cut_end start, end;
};

/// The path back from edge `found` (its last edge, arriving at end candidate `j`'s vertex).
inline cut_path_result trace_path(const strip_search& s, const cut_task& t, std::size_t found,
                                  std::size_t j) {
  cut_path_result r;
  r.end = t.ends[1][j];
  for (std::size_t e = found;; e = s.pred[e]) {
    r.vertices.push_back(edge_head(s, e));
    if (s.pred[e] >= s.tail.size()) {
      r.vertices.push_back(s.tail[e]);
      r.start = t.ends[0][s.pred[e] - s.tail.size()];
      return r;
    }
  }
}

/// The end candidate of side 1 that a path arriving at w from a may end at (turning by >=
/// min_angle at w), or none.
inline std::size_t end_at(const strip_search& s, const cut_task& t, index_t a, index_t w,
                          double min_angle) {
  for (std::size_t j = 0; j < t.ends[1].size(); ++j)
    if (t.ends[1][j].w == w && angle_deg(s.v[a], s.v[w], t.ends[1][j].at) >= min_angle) return j;
  return static_cast<std::size_t>(-1);
}

/// Whether no vertex repeats on a path.
inline bool simple_path(std::vector<index_t> path) {
  std::sort(path.begin(), path.end());
  return std::adjacent_find(path.begin(), path.end()) == path.end();
}

/// The cheapest path of Gabriel edges from a cut end on side 0 to one on side 1 (through
/// their vertices) under path_step_ok, by Dijkstra on directed edges (a path that would visit a
/// vertex twice is dropped); no vertices when none.
inline cut_path_result cut_path(strip_search& s, const cut_task& t, double min_angle) {
  using entry = std::pair<double, std::size_t>;
  std::priority_queue<entry, std::vector<entry>, std::greater<>> queue;
  const auto relax = [&](point prev, index_t w, double c, std::size_t before) {
    for (std::size_t i = 0; i < s.gabriel[w].size(); ++i) {
      const index_t x = s.gabriel[w][i];
      const std::size_t e = s.first[w] + i;
      const double next = c + path_weight(s, t.line, w, x);
      if (!(next < s.cost[e]) || !path_step_ok(s, t, prev, w, x, min_angle)) continue;
      if (s.cost[e] == std::numeric_limits<double>::infinity()) s.touched.push_back(e);
      s.cost[e] = next;
      s.pred[e] = before;
      queue.emplace(next, e);
    }
  };
  for (std::size_t i = 0; i < t.ends[0].size(); ++i)
    if (!s.blocked[t.ends[0][i].w]) relax(t.ends[0][i].at, t.ends[0][i].w, 0.0, s.tail.size() + i);
  cut_path_result r;
  while (!queue.empty() && r.vertices.empty()) {
    const auto [c, e] = queue.top();
    queue.pop();
    if (c > s.cost[e]) continue;
    const index_t a = s.tail[e], w = edge_head(s, e);
    const std::size_t j = end_at(s, t, a, w, min_angle);
    if (j == static_cast<std::size_t>(-1)) {
      relax(s.v[a], w, c, e);
    } else {
      r = trace_path(s, t, e, j);
      if (!simple_path(r.vertices)) r.vertices.clear(); // labels per edge allow a loop
    }
  }
  for (const std::size_t e : s.touched)
    s.cost[e] = std::numeric_limits<double>::infinity();
  s.touched.clear();
  return r;
}

/// A decomposition of a vertex set's hull into strips: the cut ends (Steiner vertices on hull
/// edges; end k has id v.size() + k in `paths`) and the separators, each a path of ids from
/// one end of its cut to the other. Empty when some cut found no path.
struct strip_plan {
  std::vector<cut_end> ends;
  std::vector<std::vector<index_t>> paths;
};

/// The cuts of strip_separators: their lines (balanced_cuts across the longer side of the
/// hull's bounding box: cc.axis, which it sets) with their bands (0.35 of the narrower
/// neighbouring strip's width) and candidate ends (find_cut_ends). False when a cut has none.
inline bool strip_cuts(const std::vector<point>& v, const std::vector<index_t>& hull, std::size_t n,
                       cut_candidates& cc, std::vector<double>& bands,
                       std::vector<cut_task>& tasks) {
  std::vector<point> poly;
  for (const index_t h : hull)
    poly.push_back(v[h]);
  double x0 = poly[0].x, x1 = x0, y0 = poly[0].y, y1 = y0;
  for (const point p : poly) {
    x0 = std::min(x0, p.x), x1 = std::max(x1, p.x), y0 = std::min(y0, p.y), y1 = std::max(y1, p.y);
  }
  cc.axis = x1 - x0 >= y1 - y0 ? 0 : 1;
  const auto by_axis = [&](index_t i, index_t j) {
    return along(v[i], cc.axis) < along(v[j], cc.axis);
  };
  std::sort(cc.inner.begin(), cc.inner.end(), by_axis);
  std::sort(cc.all.begin(), cc.all.end(), by_axis);
  std::vector<double> lines = balanced_cuts(poly, cc.axis, n);
  lines.insert(lines.begin(), cc.axis == 0 ? x0 : y0);
  lines.push_back(cc.axis == 0 ? x1 : y1);
  for (std::size_t j = 1; j + 1 < lines.size(); ++j) {
    bands.push_back(0.35 * std::min(lines[j] - lines[j - 1], lines[j + 1] - lines[j]));
    tasks.push_back({lines[j], {}, {}});
    if (!find_cut_ends(v, hull, cc, lines[j], bands.back(), tasks.back().ends)) return false;
  }
  return true;
}

/// The candidates' vertex lists and each distinct vertex's distance to its nearest neighbour
/// (along an edge of d).
inline cut_candidates candidates_of(const std::vector<point>& v, const std::vector<index_t>& kept,
                                    const point_set_delaunay& d, double min_length) {
  cut_candidates cc;
  cc.min_length = min_length;
  cc.all = kept;
  cc.nearest.assign(v.size(), std::numeric_limits<double>::infinity());
  for (const auto& t : d.triangles)
    for (int i = 0; i < 3; ++i) {
      const index_t a = t[i], b = t[(i + 1) % 3];
      const double length = std::hypot(v[b].x - v[a].x, v[b].y - v[a].y);
      cc.nearest[a] = std::min(cc.nearest[a], length);
      cc.nearest[b] = std::min(cc.nearest[b], length);
    }
  std::vector<char> on_hull(v.size(), 0);
  for (const index_t h : d.hull)
    on_hull[h] = 1;
  for (const index_t k : kept)
    if (!on_hull[k]) cc.inner.push_back(k);
  return cc;
}

/// Whether point x lies strictly inside the disk on an edge of `path` (ids: below v.size()
/// vertices of v, above them the plan's cut ends), exactly.
inline bool in_path_disk(const std::vector<point>& v, const strip_plan& plan,
                         const std::vector<index_t>& path, point x) {
  const auto at = [&](index_t i) { return i < v.size() ? v[i] : plan.ends[i - v.size()].at; };
  for (std::size_t i = 0; i + 1 < path.size(); ++i) {
    const point p = at(path[i]), q = at(path[i + 1]);
    if (CGAL::side_of_bounded_circle(epick::Point_2(p.x, p.y), epick::Point_2(q.x, q.y),
                                     epick::Point_2(x.x, x.y)) == CGAL::ON_BOUNDED_SIDE)
      return true;
  }
  return false;
}

/// Cut j again on its line shifted by +-0.3 of its band (its candidate ends found anew and
/// guarded, as its neighbours' are; added to the next cut's guard), for a path whose ends lie
/// in no disk on an edge of the previous path. No vertices when neither shift finds one.
inline cut_path_result shifted_cut(strip_search& s, const std::vector<index_t>& hull,
                                   std::vector<cut_task>& tasks, std::size_t j,
                                   const strip_plan& plan) {
  for (const double shift : {0.3, -0.3}) {
    cut_task t{tasks[j].line + shift * s.half_band, {}, tasks[j].guarded};
    if (!find_cut_ends(s.v, hull, s.candidates, t.line, s.half_band, t.ends)) continue;
    for (const auto& side : t.ends)
      for (const cut_end& e : side)
        t.guarded.push_back(e.at);
    cut_path_result r = cut_path(s, t, 61.0);
    if (r.vertices.empty() || (j > 0 && (in_path_disk(s.v, plan, plan.paths.back(), r.start.at) ||
                                         in_path_disk(s.v, plan, plan.paths.back(), r.end.at))))
      continue;
    if (j + 1 < tasks.size())
      tasks[j + 1].guarded.insert(tasks[j + 1].guarded.end(), t.guarded.begin(), t.guarded.end());
    return r;
  }
  return {};
}

/// Adds the path found for a cut to the plan (its ends as the next two cut ends) and blocks
/// its vertices.
inline void add_path(strip_search& s, cut_path_result r, strip_plan& plan) {
  for (const index_t x : r.vertices)
    s.blocked[x] = 1;
  const auto first_end = static_cast<index_t>(s.v.size() + plan.ends.size());
  r.vertices.insert(r.vertices.begin(), first_end + 1); // the end on side 1
  r.vertices.push_back(first_end);                      // the start on side 0
  plan.ends.push_back(r.start);
  plan.ends.push_back(r.end);
  plan.paths.push_back(std::move(r.vertices));
}

/// Separators that cut the hull of the distinct vertices `kept` of v (their Delaunay
/// triangulation d) into n strips of equal area: for each of the n - 1 cut lines, a path of
/// Gabriel edges (cut_path, within its band and no longer than half the narrower strip's
/// width, so that no two paths meet and the disk on a path edge reaches no band beyond the
/// neighbouring ones, whose candidate ends it must not hold either; where none is found, on the
/// line shifted within its band, shifted_cut) between perpendiculars to the hull at either end,
/// meeting no hull vertex, with its edges and its vertices' nearest neighbours no nearer than
/// `min_length`. Empty when a cut has no path. Complexity O(n log n).
inline strip_plan strip_separators(const std::vector<point>& v, const std::vector<index_t>& kept,
                                   const point_set_delaunay& d, std::size_t n, double min_length) {
  cut_candidates cc = candidates_of(v, kept, d, min_length);
  std::vector<double> bands;
  std::vector<cut_task> tasks;
  if (!strip_cuts(v, d.hull, n, cc, bands, tasks)) return {};
  const std::vector<std::vector<index_t>> gabriel = gabriel_neighbours(v, d);
  strip_search s = make_strip_search(v, gabriel, std::move(cc));
  for (const index_t h : d.hull)
    s.blocked[h] = 1;
  for (std::size_t j = 0; j < tasks.size(); ++j)
    for (std::size_t i = j == 0 ? 0 : j - 1; i < std::min(j + 2, tasks.size()); ++i)
      for (const auto& side : tasks[i].ends)
        for (const cut_end& e : side)
          tasks[j].guarded.push_back(e.at);
  strip_plan plan;
  for (std::size_t j = 0; j < tasks.size(); ++j) {
    s.half_band = bands[j];
    s.max_length = bands[j] * (0.5 / 0.35);
    cut_path_result r = cut_path(s, tasks[j], 61.0);
    if (r.vertices.empty()) r = shifted_cut(s, d.hull, tasks, j, plan);
    if (r.vertices.empty()) return {};
    add_path(s, std::move(r), plan);
  }
  return plan;
}

} // namespace pdd::triangle::detail
