/// \file graph.hpp
/// Implementation detail of MADD: junction triangles (Definition 4), the MADD graph of the
/// first algorithm (3.4, Algorithms 3.1-3.2) and of the second (3.5, Algorithms 3.4-3.5), and
/// its contraction.
///
/// Both algorithms are expressed on one structure. A *cell* is a triangle of the
/// triangulation, or one of the three sub-triangles a_i c a_j of a junction triangle split at
/// its circumcentre c. A *cell face* is a piece of candidate separator between two adjacent
/// cells: a Delaunay edge a_i a_j or a circumcentre segment c a_k. Faces that may not be cut
/// are contracted (union-find); the classes of cells are the nodes of the contracted graph
/// G'_T, the remaining faces between different classes its edges.
///  - Algorithm 1 (3.4): no Delaunay edge may be cut; in a junction triangle only the partial
///    separator with the largest minimum angle may (its two segments), the third segment is
///    contracted. This is Algorithm 3.2's graph: the node d_ij of a triangle edge is the class
///    of the cells on both sides of it.
///  - Algorithm 2 (3.5): a Delaunay edge may be cut if it forms angles >= Phi0 with the
///    boundary at both ends, a circumcentre segment c a_k if it does at a_k (Algorithm 3.5);
///    if a pair of acceptable segments meets at c at an angle < Phi0, the segment of the
///    weaker remaining partial separator is contracted too, so every cut is acceptable.
#pragma once

#include <pdd/concepts/graph_partitioner.hpp>
#include <pdd/core/kernel.hpp>
#include <pdd/core/triangle_measures.hpp>
#include <pdd/madd/detail/region.hpp>
#include <pdd/madd/detail/triangulation.hpp>

#include <algorithm>
#include <array>
#include <cstdint>
#include <numbers>
#include <utility>
#include <vector>

namespace pdd::detail {

/// Classification of one triangle by Definition 4 (dissertation 3.2).
struct junction_info {
  bool junction = false;
  bool contains_circumcentre = false; ///< condition 1 (exact: acute, c strictly inside)
  int boundary_edges = 0;             ///< edges in Z (condition 2 needs <= 1)
  point c;                            ///< circumcentre (floating point)
  double radius = 0.0;
  /// end_angle[k]: smallest angle of segment c a_k with the boundary at a_k (degrees).
  std::array<double, 3> end_angle{};
  /// central[k]: angle at c between c a_{k+1} and c a_{k+2} (degrees).
  std::array<double, 3> central{};
  /// pair_ok[k]: the partial separator a_{k+1} c a_{k+2} (it cuts off sub-triangle k) forms
  /// angles >= Phi0 with the boundary and at c (condition 3).
  std::array<bool, 3> pair_ok{};
  std::array<double, 3> pair_score{}; ///< its smallest angle
  int best_pair = -1;                 ///< acceptable pair with the largest smallest angle
};

/// Smallest angle (degrees) that the segment v -> q forms with the boundary at v, whose two
/// boundary directions point at far_prev and far_next.
inline double boundary_angle(point v, point q, point far_prev, point far_next) noexcept {
  return std::min(angle_deg(v, q, far_prev), angle_deg(v, q, far_next));
}

/// Classifies triangle p (counter-clockwise) by Definition 4. on_boundary[k]: the edge
/// opposite p[k] is in Z. far[k]: the points the two boundary directions at p[k] aim at.
/// Angles are accepted when >= phi0_accept (degrees). Exact predicates decide condition 1.
inline junction_info classify_triangle(const std::array<point, 3>& p,
                                       const std::array<bool, 3>& on_boundary,
                                       const std::array<std::array<point, 2>, 3>& far,
                                       double phi0_accept) {
  junction_info j;
  for (int k = 0; k < 3; ++k)
    j.boundary_edges += on_boundary[k] ? 1 : 0;
  const epick::Point_2 q[3] = {{p[0].x, p[0].y}, {p[1].x, p[1].y}, {p[2].x, p[2].y}};
  bool acute = true;
  for (int k = 0; k < 3; ++k)
    acute = acute && CGAL::angle(q[(k + 1) % 3], q[k], q[(k + 2) % 3]) == CGAL::ACUTE;
  if (!acute) return j;
  const epick::Point_2 cc = CGAL::circumcenter(q[0], q[1], q[2]);
  bool inside = true;
  for (int k = 0; k < 3; ++k)
    inside = inside && CGAL::orientation(q[k], q[(k + 1) % 3], cc) == CGAL::LEFT_TURN;
  if (!inside) return j;
  j.contains_circumcentre = true;
  j.c = {cc.x(), cc.y()};
  j.radius = (distance(j.c, p[0]) + distance(j.c, p[1]) + distance(j.c, p[2])) / 3.0;
  for (int k = 0; k < 3; ++k) {
    j.end_angle[k] = boundary_angle(p[k], j.c, far[k][0], far[k][1]);
    j.central[k] = angle_deg(j.c, p[(k + 1) % 3], p[(k + 2) % 3]);
  }
  double best = -1.0;
  for (int k = 0; k < 3; ++k) {
    const int a = (k + 1) % 3, b = (k + 2) % 3;
    j.pair_score[k] = std::min({j.end_angle[a], j.end_angle[b], j.central[k]});
    j.pair_ok[k] = j.pair_score[k] >= phi0_accept;
    if (j.pair_ok[k] && j.pair_score[k] > best) {
      best = j.pair_score[k];
      j.best_pair = k;
    }
  }
  j.junction = j.boundary_edges <= 1 && j.best_pair >= 0;
  return j;
}

/// A cell: a whole triangle (sub = -1) or sub-triangle `sub` of a junction triangle, the
/// triangle (v[sub+1], v[sub+2], c). side[s] is the cell face on side s (-1: boundary);
/// whole triangle: side s is the edge opposite v[s]; sub-triangle: side 0 is the triangle's
/// edge, side 1 the segment v[sub+2] -> c, side 2 the segment c -> v[sub+1].
struct madd_cell {
  std::uint32_t tri = 0;
  int sub = -1;
  double area = 0.0;
  std::array<std::int32_t, 3> side{-1, -1, -1};
};

/// A cell face: a candidate piece of separator between cells a and b.
struct madd_cell_face {
  std::uint32_t a = 0, b = 0;
  std::uint32_t z0 = 0;         ///< its end on the boundary (a vertex of Z)
  std::uint32_t z1 = no_index;  ///< Delaunay edge: the other end; else no_index
  std::uint32_t tri = no_index; ///< circumcentre segment: the junction triangle
  double length = 0.0;
  double min_angle = 0.0; ///< smallest angle it forms with the boundary (degrees)
  double weight = 0.0;    ///< edge weight given to the partitioner
  bool cuttable = false;
};

/// The cells, faces and their contraction for one region.
struct madd_graph {
  std::vector<junction_info> info;       ///< per triangle
  std::vector<std::uint32_t> first_cell; ///< per triangle
  std::vector<madd_cell> cells;
  std::vector<madd_cell_face> faces;
  std::vector<std::uint32_t> node; ///< contracted-graph node of each cell
  std::size_t nodes = 0;
  std::size_t junctions = 0;
};

/// Options of the graph construction.
struct madd_graph_options {
  int algorithm = 2;
  double phi0 = 60.0;        ///< degrees
  double phi0_accept = 60.0; ///< degrees: phi0 plus a safety margin
  bool smoothing = false;    ///< 4.2 first step: angle-quality and conformity weights
};

/// Conformity factor f1 of a boundary point (4.2): 0.5 for a vertex of the region (an input
/// vertex or the end of an earlier separator), 0.85 for the midpoint of a region edge.
inline double conformity_factor(const madd_zvertex& v) noexcept {
  if (v.original) return 0.5;
  if (v.t == 0.5) return 0.85;
  return 1.0;
}

/// Angle-quality factor f0 = 1 / (min(phi, pi/2) - Phi0 + 1), angles in radians (4.2).
inline double angle_factor(double phi_deg, double phi0_deg) noexcept {
  const double d2r = std::numbers::pi / 180.0;
  return 1.0 / (std::min(phi_deg, 90.0) * d2r - phi0_deg * d2r + 1.0);
}

/// Recomputes the contraction: cells joined by non-cuttable faces form one node.
inline void contract(madd_graph& g) {
  union_find uf(g.cells.size());
  for (const madd_cell_face& f : g.faces)
    if (!f.cuttable) uf.unite(f.a, f.b);
  std::vector<std::uint32_t> id(g.cells.size(), no_index);
  g.node.assign(g.cells.size(), 0);
  std::uint32_t n = 0;
  for (std::uint32_t c = 0; c < g.cells.size(); ++c) {
    const std::uint32_t r = uf.find(c);
    if (id[r] == no_index) id[r] = n++;
    g.node[c] = id[r];
  }
  g.nodes = n;
}

/// Classifies every triangle of `tr` (junction or not, Algorithm 3.4) and creates its cells:
/// three sub-triangles around the circumcentre for a junction, the triangle itself otherwise.
inline void build_cells(const madd_triangulation& tr, const madd_graph_options& o, madd_graph& g) {
  const auto nt = tr.faces.size();
  g.info.resize(nt);
  g.first_cell.resize(nt);
  for (std::uint32_t t = 0; t < nt; ++t) {
    const madd_face& f = tr.faces[t];
    std::array<point, 3> p;
    std::array<bool, 3> bnd;
    std::array<std::array<point, 2>, 3> far;
    for (int k = 0; k < 3; ++k) {
      const madd_zvertex& zv = tr.z[f.v[k]];
      p[k] = zv.p;
      bnd[k] = f.nb[k] < 0;
      far[k] = {zv.far_prev, zv.far_next};
    }
    junction_info& j = g.info[t];
    j = classify_triangle(p, bnd, far, o.phi0_accept);
    g.first_cell[t] = static_cast<std::uint32_t>(g.cells.size());
    if (j.junction) {
      ++g.junctions;
      for (int k = 0; k < 3; ++k) {
        madd_cell c;
        c.tri = t;
        c.sub = k;
        c.area = triangle_area(p[(k + 1) % 3], p[(k + 2) % 3], j.c);
        g.cells.push_back(c);
      }
    } else {
      madd_cell c;
      c.tri = t;
      c.area = triangle_area(p[0], p[1], p[2]);
      g.cells.push_back(c);
    }
  }
}

/// The cell of triangle t adjacent to its edge k, and the side index of that edge in the cell.
inline std::pair<std::uint32_t, int> edge_cell(const madd_graph& g, std::uint32_t t, int k) {
  if (g.info[t].junction) return {g.first_cell[t] + static_cast<std::uint32_t>(k), 0};
  return {g.first_cell[t], k};
}

/// Appends face f between side sa of cell ca and side sb of cell cb.
inline void add_face(madd_graph& g, madd_cell_face f, std::uint32_t ca, int sa, std::uint32_t cb,
                     int sb) {
  const auto id = static_cast<std::int32_t>(g.faces.size());
  f.a = ca;
  f.b = cb;
  g.cells[ca].side[sa] = id;
  g.cells[cb].side[sb] = id;
  g.faces.push_back(f);
}

/// The weight of a face: its length, times the angle and conformity factors when smoothing.
inline double face_weight(const madd_triangulation& tr, const madd_graph_options& o,
                          const madd_cell_face& f) {
  if (!o.smoothing) return f.length;
  double f1 = conformity_factor(tr.z[f.z0]);
  if (f.z1 != no_index) f1 = std::min(f1, conformity_factor(tr.z[f.z1]));
  return f.length * angle_factor(f.min_angle, o.phi0) * f1;
}

/// Adds the faces on the Delaunay edges between triangles (type a of Algorithm 3.5).
inline void add_delaunay_faces(const madd_triangulation& tr, const madd_graph_options& o,
                               madd_graph& g) {
  for (std::uint32_t t = 0; t < tr.faces.size(); ++t) {
    const madd_face& f = tr.faces[t];
    for (int k = 0; k < 3; ++k) {
      if (f.nb[k] < 0 || static_cast<std::uint32_t>(f.nb[k]) < t) continue;
      const auto u = static_cast<std::uint32_t>(f.nb[k]);
      const madd_face& fu = tr.faces[u];
      int ku = 0;
      while (fu.nb[ku] != static_cast<std::int32_t>(t))
        ++ku;
      madd_cell_face cf;
      cf.z0 = f.v[(k + 1) % 3];
      cf.z1 = f.v[(k + 2) % 3];
      const madd_zvertex& a = tr.z[cf.z0];
      const madd_zvertex& b = tr.z[cf.z1];
      cf.length = distance(a.p, b.p);
      cf.min_angle = std::min(boundary_angle(a.p, b.p, a.far_prev, a.far_next),
                              boundary_angle(b.p, a.p, b.far_prev, b.far_next));
      cf.cuttable = o.algorithm == 2 && cf.min_angle >= o.phi0_accept;
      cf.weight = face_weight(tr, o, cf);
      const auto [ca, sa] = edge_cell(g, t, k);
      const auto [cb, sb] = edge_cell(g, u, ku);
      add_face(g, cf, ca, sa, cb, sb);
    }
  }
}

/// Which of the three circumcentre segments of junction j may be cut: the best pair's two
/// (Algorithm 3.2), or those with large end angles that do not meet at a small angle (3.5).
inline std::array<bool, 3> cuttable_segments(const junction_info& j, const madd_graph_options& o) {
  std::array<bool, 3> cut{};
  if (o.algorithm == 1) {
    cut[(j.best_pair + 1) % 3] = cut[(j.best_pair + 2) % 3] = true;
    return cut;
  }
  for (int k = 0; k < 3; ++k)
    cut[k] = j.end_angle[k] >= o.phi0_accept;
  for (int k = 0; k < 3; ++k) {
    const int a = (k + 1) % 3, b = (k + 2) % 3;
    if (!cut[a] || !cut[b] || j.central[k] >= o.phi0_accept) continue;
    // Pair k would meet at c at a small angle: contracting segment a leaves pair a
    // (segments b and k), contracting b leaves pair b (segments k and a).
    const double keep_a = j.pair_ok[a] ? j.pair_score[a] : -1.0;
    const double keep_b = j.pair_ok[b] ? j.pair_score[b] : -1.0;
    if (keep_a >= keep_b)
      cut[a] = false;
    else
      cut[b] = false;
  }
  return cut;
}

/// Adds the circumcentre segments (type b of Algorithm 3.5) inside junction triangles.
inline void add_circumcentre_faces(const madd_triangulation& tr, const madd_graph_options& o,
                                   madd_graph& g) {
  for (std::uint32_t t = 0; t < tr.faces.size(); ++t) {
    const junction_info& j = g.info[t];
    if (!j.junction) continue;
    const madd_face& f = tr.faces[t];
    const std::array<bool, 3> cut = cuttable_segments(j, o);
    const std::uint32_t base = g.first_cell[t];
    for (int k = 0; k < 3; ++k) {
      // Segment c a_k separates sub-triangles k+1 (side 1: a_k -> c, as a_k = v[(k+1)+2])
      // and k+2 (side 2: c -> a_k, as a_k = v[(k+2)+1]).
      madd_cell_face cf;
      cf.z0 = f.v[k];
      cf.tri = t;
      cf.length = distance(j.c, tr.z[f.v[k]].p);
      cf.min_angle = j.end_angle[k];
      cf.cuttable = cut[k];
      cf.weight = face_weight(tr, o, cf);
      add_face(g, cf, base + static_cast<std::uint32_t>((k + 1) % 3), 1,
               base + static_cast<std::uint32_t>((k + 2) % 3), 2);
    }
  }
}

/// Builds cells, faces and the contraction of a region's triangulation (Algorithms 3.1-3.2 or
/// 3.4-3.5). Complexity O(T) for T triangles. Thread-safe.
inline madd_graph build_madd_graph(const madd_triangulation& tr, const madd_graph_options& o) {
  madd_graph g;
  build_cells(tr, o, g);
  add_delaunay_faces(tr, o, g);
  add_circumcentre_faces(tr, o, g);
  contract(g);
  return g;
}

/// The contracted graph G'_T as a partition_graph: node weights are areas, parallel cuttable
/// faces between two nodes are merged into one edge (weights add). Faces inside a node
/// (self loops) are dropped: they can never be cut.
inline partition_graph contracted_graph(const madd_graph& g) {
  partition_graph pg(g.nodes);
  for (std::size_t c = 0; c < g.cells.size(); ++c)
    pg[g.node[c]].weight += g.cells[c].area;
  struct e {
    std::uint32_t u, v;
    double w;
  };
  std::vector<e> es;
  for (const madd_cell_face& f : g.faces) {
    if (!f.cuttable) continue;
    std::uint32_t u = g.node[f.a], v = g.node[f.b];
    if (u == v) continue;
    if (v < u) std::swap(u, v);
    es.push_back({u, v, f.weight});
  }
  std::sort(es.begin(), es.end(),
            [](const e& x, const e& y) { return x.u != y.u ? x.u < y.u : x.v < y.v; });
  for (std::size_t i = 0; i < es.size();) {
    double w = 0.0;
    std::size_t k = i;
    for (; k < es.size() && es[k].u == es[i].u && es[k].v == es[i].v; ++k)
      w += es[k].w;
    boost::add_edge(es[i].u, es[i].v, partition_edge{w}, pg);
    i = k;
  }
  return pg;
}

} // namespace pdd::detail
