/// \file cdt_core.hpp
/// The storage and the local operations of pdd::constrained_delaunay_2: flat arrays of vertex
/// points, face corners, neighbours with the neighbour's edge packed in and per-face flag
/// bits, around one infinite vertex (vertex 0) as in CGAL's Triangulation_2, so that the faces
/// outside the convex hull are the infinite faces (a, b, infinity) of its edges. Exact
/// predicates from CGAL's Epick (LGPL), no CGAL triangulation package.
///
/// Conventions: corners are counter-clockwise; edge i of a face is the one opposite its corner
/// i, from corner i+1 to corner i+2 (mod 3). A neighbour reference packs the face and the edge
/// index: (f << 2) | i. An infinite face (a, b, inf) lies left of a -> b: outside the hull.
#pragma once

#include <pdd/core/index.hpp>
#include <pdd/core/kernel.hpp>

#include <algorithm>
#include <array>
#include <cstdint>
#include <vector>

namespace pdd::detail::cdt {

using ref_t = std::uint32_t;
using face_t = std::uint32_t;
inline constexpr face_t no_face = 0xFFFFFFFFu;
/// No edge (find_edge), no crossing edge (an insertion that splits none).
inline constexpr ref_t no_ref = 0xFFFFFFFFu;
inline constexpr index_t infinite = 0;
/// Flag bits of a face: bit i (i < 3) edge i is constrained; in_cavity (scratch).
inline constexpr std::uint8_t in_cavity_bit = 8;

inline constexpr int next3(int i) noexcept {
  return i == 2 ? 0 : i + 1;
}
inline constexpr int prev3(int i) noexcept {
  return i == 0 ? 2 : i - 1;
}
inline constexpr ref_t make_ref(face_t f, int i) noexcept {
  return f << 2 | static_cast<ref_t>(i);
}
inline constexpr face_t ref_face(ref_t r) noexcept {
  return r >> 2;
}
inline constexpr int ref_edge(ref_t r) noexcept {
  return static_cast<int>(r & 3u);
}

/// Exact orientation of (a, b, c): > 0 counter-clockwise, 0 collinear, < 0 clockwise.
inline int orient(const epick::Point_2& a, const epick::Point_2& b, const epick::Point_2& c) {
  return static_cast<int>(CGAL::orientation(a, b, c));
}

/// Exact: d lies inside the circle through the counter-clockwise a, b, c, with ties broken by
/// a symbolic perturbation (Devillers and Teillaud 2003: the points perturbed in decreasing
/// lexicographic order), so that the Delaunay triangulation of cocircular points is one and
/// the same whatever the order of insertion, and the same as CGAL's.
inline bool in_circle(const epick::Point_2& a, const epick::Point_2& b, const epick::Point_2& c,
                      const epick::Point_2& d) {
  const CGAL::Oriented_side side = CGAL::side_of_oriented_circle(a, b, c, d);
  if (side != CGAL::ON_ORIENTED_BOUNDARY) return side == CGAL::ON_POSITIVE_SIDE;
  std::array<const epick::Point_2*, 4> by_xy{&a, &b, &c, &d};
  std::sort(by_xy.begin(), by_xy.end(), [](const epick::Point_2* x, const epick::Point_2* y) {
    return CGAL::compare_xy(*x, *y) == CGAL::LARGER;
  });
  for (const epick::Point_2* q : by_xy) { // the largest first: its perturbation decides
    int o = 0;
    if (q == &d) return false;
    if (q == &c) o = orient(a, b, d);
    if (q == &b) o = orient(a, d, c);
    if (q == &a) o = orient(d, b, c);
    if (o != 0) return o > 0;
  }
  return false;
}

/// The arrays. Face slots are never freed: a cavity of k faces is replaced by k + 2 faces in
/// its own k slots and two new ones, and a flip rewrites two slots.
struct storage {
  std::vector<epick::Point_2> pts{epick::Point_2(0, 0)}; ///< pts[0]: the infinite vertex
  /// A face incident to each vertex in the triangulation; no_face for one not (yet) in it.
  std::vector<face_t> vertex_face{no_face};
  std::vector<std::array<index_t, 3>> corner;
  std::vector<std::array<ref_t, 3>> adj;
  std::vector<std::uint8_t> flags;
  int dimension = -1; ///< -1 empty, 0 one point, 1 collinear points, 2

  face_t size() const noexcept { return static_cast<face_t>(corner.size()); }
  bool constrained(face_t f, int i) const noexcept { return (flags[f] >> i & 1u) != 0; }
  void set_constrained(face_t f, int i, bool on) noexcept {
    const auto bit = static_cast<std::uint8_t>(1u << i);
    flags[f] = static_cast<std::uint8_t>(on ? flags[f] | bit : flags[f] & ~bit);
  }
  /// Sets or clears edge i of f and its twin in the neighbour.
  void set_edge_constrained(face_t f, int i, bool on) noexcept {
    set_constrained(f, i, on);
    set_constrained(ref_face(adj[f][i]), ref_edge(adj[f][i]), on);
  }
  bool is_infinite(face_t f) const noexcept {
    return corner[f][0] == infinite || corner[f][1] == infinite || corner[f][2] == infinite;
  }
  const epick::Point_2& at(face_t f, int i) const noexcept { return pts[corner[f][i]]; }
  /// The index of vertex v among f's corners (v must be one).
  int index_of(face_t f, index_t v) const noexcept {
    return corner[f][0] == v ? 0 : corner[f][1] == v ? 1 : 2;
  }
  /// The corner of the neighbour across edge i of f that is not on that edge.
  index_t apex_across(face_t f, int i) const noexcept {
    return corner[ref_face(adj[f][i])][ref_edge(adj[f][i])];
  }

  /// Writes face f and the back references of its neighbours.
  void write(face_t f, std::array<index_t, 3> c, std::array<ref_t, 3> n, std::uint8_t bits) {
    corner[f] = c;
    adj[f] = n;
    flags[f] = bits;
    for (int i = 0; i < 3; ++i) {
      vertex_face[c[i]] = f;
      adj[ref_face(n[i])][ref_edge(n[i])] = make_ref(f, i);
    }
  }
  face_t new_slot() {
    corner.push_back({infinite, infinite, infinite});
    adj.push_back({0, 0, 0});
    flags.push_back(0);
    return size() - 1;
  }

  /// Flips edge i of f (unconstrained, its quadrilateral strictly convex). f = (p, q, r) with
  /// edge i = (q, r), its neighbour u = (s, r, q); afterwards f = (p, q, s), u = (s, r, p).
  void flip(face_t f, int i) {
    const ref_t nb = adj[f][i];
    const face_t u = ref_face(nb);
    const int j = ref_edge(nb);
    const index_t p = corner[f][i], q = corner[f][next3(i)], r = corner[f][prev3(i)];
    const index_t s = corner[u][j];
    const ref_t n_q = adj[f][next3(i)], n_r = adj[f][prev3(i)];
    const ref_t m_r = adj[u][next3(j)], m_q = adj[u][prev3(j)];
    const auto bits = [](bool a, bool c) {
      return static_cast<std::uint8_t>((a ? 1 : 0) | (c ? 4 : 0));
    };
    const std::uint8_t f_bits = bits(constrained(u, next3(j)), constrained(f, prev3(i)));
    const std::uint8_t u_bits = bits(constrained(f, next3(i)), constrained(u, prev3(j)));
    write(f, {p, q, s}, {m_r, make_ref(u, 1), n_r}, f_bits);
    write(u, {s, r, p}, {n_q, make_ref(f, 1), m_q}, u_bits);
  }

  /// The face and edge index of the directed edge a -> b (counter-clockwise in the returned
  /// face), or no_ref when a and b are not joined. a is in the triangulation (2D).
  ref_t find_edge(index_t a, index_t b) const {
    const face_t start = vertex_face[a];
    face_t f = start;
    do {
      const int k = index_of(f, a);
      if (corner[f][next3(k)] == b) return make_ref(f, prev3(k));
      f = ref_face(adj[f][next3(k)]); // counter-clockwise around a
    } while (f != start);
    return no_ref;
  }

  /// Exact: p conflicts with face f (Bowyer-Watson): strictly inside the circumcircle of a
  /// finite face; for an infinite face (a, b, inf), strictly left of a -> b or strictly inside
  /// the segment [a, b] (CGAL's convention, so that a point on the hull splits its edge).
  bool in_conflict(face_t f, const epick::Point_2& p) const {
    const int k = corner[f][0] == infinite   ? 0
                  : corner[f][1] == infinite ? 1
                  : corner[f][2] == infinite ? 2
                                             : -1;
    if (k < 0) return in_circle(at(f, 0), at(f, 1), at(f, 2), p);
    const epick::Point_2 &a = at(f, next3(k)), &b = at(f, prev3(k));
    const int o = orient(a, b, p);
    return o > 0 || (o == 0 && CGAL::collinear_are_strictly_ordered_along_line(a, p, b));
  }
};

} // namespace pdd::detail::cdt
