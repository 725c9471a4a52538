/// \file region_grid_impl.hpp
/// Definition of detail::layout_region_grid (region_grid.hpp): compiled into libpdd, included by
/// region_grid.hpp in a header-only build.
#pragma once

#include <pdd/core/kernel.hpp>
#include <pdd/sizing/detail/region_grid.hpp>

#include <algorithm>
#include <cmath>
#include <utility>

namespace pdd::detail {

namespace region_grid_parts {

/// The cell (0 .. n - 1) holding coordinate v on an axis from lo with cell size h.
inline std::size_t cell_of(double v, double lo, double h, std::size_t n) {
  const double c = std::floor((v - lo) / h);
  if (!(c > 0.0)) return 0;
  return std::min(static_cast<std::size_t>(c), n - 1);
}

/// The node range [first, last] (clipped to 0 .. n) around the coordinates [a, b], one node
/// wider on each side (the exact tests decide).
inline std::pair<std::size_t, std::size_t> node_range(double a, double b, double lo, double h,
                                                      std::size_t n) {
  const double f = std::floor((a - lo) / h) - 1.0, l = std::ceil((b - lo) / h) + 1.0;
  const auto clip = [n](double v) {
    return v <= 0.0 ? std::size_t{0} : std::min(static_cast<std::size_t>(v), n);
  };
  return {clip(f), clip(l)};
}

/// The x-extent of triangle abc on the line y = y (empty: first > second).
inline std::pair<double, double> row_extent(const point& a, const point& b, const point& c,
                                            double y) {
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (const auto& [u, v] : {std::pair{a, b}, std::pair{b, c}, std::pair{c, a}}) {
    if (y < std::min(u.y, v.y) || y > std::max(u.y, v.y)) continue;
    const double x = u.y == v.y ? u.x : u.x + (y - u.y) * (v.x - u.x) / (v.y - u.y);
    lo = std::min({lo, x, u.y == v.y ? v.x : x});
    hi = std::max({hi, x, u.y == v.y ? v.x : x});
  }
  return {lo, hi};
}

/// True when p lies in the closed triangle abc (exact predicates, either orientation); false
/// for a degenerate triangle (its points are sampled as its edges' crossings).
inline bool in_closed_triangle(const epick::Point_2& a, const epick::Point_2& b,
                               const epick::Point_2& c, const epick::Point_2& p) {
  const CGAL::Orientation o = CGAL::orientation(a, b, c);
  if (o == CGAL::COLLINEAR) return false;
  const auto side = [o](CGAL::Orientation s) { return s == o || s == CGAL::COLLINEAR; };
  return side(CGAL::orientation(a, b, p)) && side(CGAL::orientation(b, c, p)) &&
         side(CGAL::orientation(c, a, p));
}

/// Marks the grid nodes that lie in triangle abc: per node row through the triangle, the
/// nodes around its floating-point extent, each tested exactly.
inline void mark_triangle(region_grid& g, const point& a, const point& b, const point& c) {
  const double hx = (g.box.xmax - g.box.xmin) / static_cast<double>(g.nx);
  const double hy = (g.box.ymax - g.box.ymin) / static_cast<double>(g.ny);
  const epick::Point_2 ea(a.x, a.y), eb(b.x, b.y), ec(c.x, c.y);
  const auto rows =
      node_range(std::min({a.y, b.y, c.y}), std::max({a.y, b.y, c.y}), g.box.ymin, hy, g.ny);
  for (std::size_t j = rows.first; j <= rows.second; ++j) {
    const double y = g.node(0, j).y;
    const auto [xl, xr] = row_extent(a, b, c, y);
    if (!(xl <= xr)) continue;
    const auto cols = node_range(xl, xr, g.box.xmin, hx, g.nx);
    for (std::size_t i = cols.first; i <= cols.second; ++i) {
      std::uint8_t& in = g.inside[j * (g.nx + 1) + i];
      if (in) continue;
      const point p = g.node(i, j);
      in = in_closed_triangle(ea, eb, ec, epick::Point_2(p.x, p.y)) ? 1 : 0;
    }
  }
}

/// The edges that bound the region: those of exactly one triangle (an edge between two of
/// its triangles, such as an interface inside a domain, lies inside it).
inline std::vector<std::pair<index_t, index_t>> boundary_edges(const sizing_region& r) {
  std::vector<std::pair<index_t, index_t>> e;
  e.reserve(3 * r.triangles.size());
  for (const auto& t : r.triangles)
    for (int k = 0; k < 3; ++k)
      e.emplace_back(std::minmax(t[k], t[(k + 1) % 3]));
  std::sort(e.begin(), e.end());
  std::vector<std::pair<index_t, index_t>> once;
  for (std::size_t i = 0; i < e.size();) {
    std::size_t j = i;
    while (j < e.size() && e[j] == e[i])
      ++j;
    if (j - i == 1) once.push_back(e[i]);
    i = j;
  }
  return once;
}

/// Boundary samples with the cells they lie in, before grouping.
struct pending_samples {
  std::vector<point> points;
  std::vector<std::pair<std::size_t, std::size_t>> cell_sample; ///< (cell, point id)
};

/// Adds sample p to the cells (ci, cj) and, when p lies on the grid line x = x_ci or y = y_cj,
/// to the cell before it along that axis as well.
inline void add_sample(const region_grid& g, pending_samples& s, const point& p, std::size_t ci,
                       std::size_t cj, bool on_x_line, bool on_y_line) {
  const std::size_t id = s.points.size();
  s.points.push_back(p);
  for (std::size_t di = 0; di <= (on_x_line && ci > 0 ? 1u : 0u); ++di)
    for (std::size_t dj = 0; dj <= (on_y_line && cj > 0 ? 1u : 0u); ++dj)
      s.cell_sample.emplace_back((cj - dj) * g.nx + (ci - di), id);
}

/// The samples of boundary edge pq: its ends, and its crossings of the grid's lines x = x_i
/// and y = y_j (each in the cells on both sides of the line). The crossings are computed from
/// the lexicographically smaller end, so that they are bitwise the same however the region's
/// vertices are numbered.
inline void add_edge_samples(const region_grid& g, pending_samples& s, point p, point q) {
  if (q < p) std::swap(p, q);
  const double hx = (g.box.xmax - g.box.xmin) / static_cast<double>(g.nx);
  const double hy = (g.box.ymax - g.box.ymin) / static_cast<double>(g.ny);
  for (const point& e : {p, q}) {
    const std::size_t ci = cell_of(e.x, g.box.xmin, hx, g.nx);
    const std::size_t cj = cell_of(e.y, g.box.ymin, hy, g.ny);
    const point corner = g.node(ci, cj);
    add_sample(g, s, e, ci, cj, corner.x == e.x, corner.y == e.y);
  }
  for (int axis = 0; axis < 2; ++axis) {
    const double pu = axis ? p.y : p.x, qu = axis ? q.y : q.x;
    const double pv = axis ? p.x : p.y, qv = axis ? q.x : q.y;
    if (pu == qu) continue;
    const std::size_t n = axis ? g.ny : g.nx, m = axis ? g.nx : g.ny;
    const double lo = axis ? g.box.ymin : g.box.xmin, h = axis ? hy : hx;
    const double vlo = axis ? g.box.xmin : g.box.ymin, vh = axis ? hx : hy;
    const auto [first, last] = node_range(std::min(pu, qu), std::max(pu, qu), lo, h, n);
    for (std::size_t k = first; k <= last; ++k) {
      const point node = g.node(axis ? 0 : k, axis ? k : 0);
      const double u = axis ? node.y : node.x;
      if (u <= std::min(pu, qu) || u >= std::max(pu, qu)) continue;
      const double v =
          std::clamp(pv + (u - pu) * (qv - pv) / (qu - pu), std::min(pv, qv), std::max(pv, qv));
      const std::size_t cu = std::min(k, n - 1), cv = cell_of(v, vlo, vh, m);
      add_sample(g, s, axis ? point{v, u} : point{u, v}, axis ? cv : cu, axis ? cu : cv, axis == 0,
                 axis == 1);
    }
  }
}

/// Groups the pending samples by cell into g.boundary, g.cell_first and g.cell_samples.
inline void group_samples(region_grid& g, pending_samples&& s) {
  std::sort(s.cell_sample.begin(), s.cell_sample.end());
  g.boundary = std::move(s.points);
  g.cell_first.assign(g.nx * g.ny + 1, 0);
  for (const auto& cs : s.cell_sample)
    ++g.cell_first[cs.first + 1];
  for (std::size_t c = 0; c < g.nx * g.ny; ++c)
    g.cell_first[c + 1] += g.cell_first[c];
  g.cell_samples.reserve(s.cell_sample.size());
  for (const auto& cs : s.cell_sample)
    g.cell_samples.push_back(cs.second);
}

} // namespace region_grid_parts

PDD_REGION_GRID_INLINE region_grid layout_region_grid(const sizing_region& r, std::size_t nx,
                                                      std::size_t ny) {
  namespace parts = region_grid_parts;
  region_grid g;
  g.box = r.box();
  g.nx = nx;
  g.ny = ny;
  g.inside.assign((nx + 1) * (ny + 1), 0);
  for (const auto& t : r.triangles)
    parts::mark_triangle(g, r.vertices[t[0]], r.vertices[t[1]], r.vertices[t[2]]);
  parts::pending_samples s;
  for (const auto& [a, b] : parts::boundary_edges(r))
    parts::add_edge_samples(g, s, r.vertices[a], r.vertices[b]);
  parts::group_samples(g, std::move(s));
  return g;
}

} // namespace pdd::detail
