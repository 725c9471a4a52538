/// \file triangulation.hpp
/// The triangle-array triangulation of pdd::native::mesher: a flat array of vertex coordinates
/// and one of triangle slots (corners, neighbours with the neighbour's edge packed in, flag
/// bits: constrained edges, in-domain); exact predicates from CGAL's Epick.
///
/// Conventions: corners are counter-clockwise; edge i of a triangle is the edge opposite its
/// corner i, from corner i+1 to corner i+2 (mod 3). A neighbour reference packs the triangle
/// and the edge index: (t << 2) | i; `no_ref` marks the outer edges of the bounding triangle.
#pragma once

#include <pdd/core/index.hpp>
#include <pdd/core/kernel.hpp>
#include <pdd/core/point.hpp>
#include <pdd/errors.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

namespace pdd::detail::native_mesh {

using ref_t = std::uint32_t;
inline constexpr ref_t no_ref = 0xFFFFFFFFu;
inline constexpr std::uint32_t dead = no_index;

/// Flag bits of a triangle: bit i (i < 3) edge i is constrained; in_domain; in_cavity (scratch).
inline constexpr std::uint8_t in_domain_bit = 8;
inline constexpr std::uint8_t in_cavity_bit = 16;

inline constexpr int next3(int i) noexcept {
  return i == 2 ? 0 : i + 1;
}
inline constexpr int prev3(int i) noexcept {
  return i == 0 ? 2 : i - 1;
}
inline constexpr ref_t make_ref(std::uint32_t t, int i) noexcept {
  return t << 2 | static_cast<ref_t>(i);
}
inline constexpr std::uint32_t ref_tri(ref_t r) noexcept {
  return r >> 2;
}
inline constexpr int ref_edge(ref_t r) noexcept {
  return static_cast<int>(r & 3u);
}

inline epick::Point_2 cp(const point& p) {
  return {p.x, p.y};
}
/// Exact orientation of (a, b, c): > 0 counter-clockwise, 0 collinear, < 0 clockwise.
inline int orient(const point& a, const point& b, const point& c) {
  return static_cast<int>(CGAL::orientation(cp(a), cp(b), cp(c)));
}
/// Exact: d lies strictly inside the circle through the counter-clockwise a, b, c.
inline bool in_circle(const point& a, const point& b, const point& c, const point& d) {
  return CGAL::side_of_oriented_circle(cp(a), cp(b), cp(c), cp(d)) == CGAL::ON_POSITIVE_SIDE;
}
/// Exact: p lies in the closed diametral disk of [a, b] (the angle a p b is not acute).
inline bool in_diametral_disk(const point& a, const point& b, const point& p) {
  return CGAL::angle(cp(a), cp(p), cp(b)) != CGAL::ACUTE;
}

/// One triangle slot: corners, neighbour references and flag bits side by side, so that
/// reading a neighbour's corners and flags (the cavity search) touches one cache line. 32
/// bytes, aligned to 32: two slots to a cache line, never one across two.
struct alignas(32) triangle_slot {
  std::array<index_t, 3> corner;
  std::array<ref_t, 3> adj;
  std::uint8_t flags;
};
static_assert(sizeof(triangle_slot) == 32);

/// The triangulation. Triangle slots are never freed: a cavity of k triangles is replaced by
/// k + 2 triangles in its own k slots and two new ones, and a flip rewrites two slots.
struct triangulation {
  std::vector<point> pts;
  std::vector<triangle_slot> slots;
  /// A triangle incident to each vertex (kept current by every write).
  std::vector<std::uint32_t> vertex_tri;

  std::uint32_t size() const noexcept { return static_cast<std::uint32_t>(slots.size()); }
  std::array<index_t, 3>& corner(std::uint32_t t) noexcept { return slots[t].corner; }
  const std::array<index_t, 3>& corner(std::uint32_t t) const noexcept { return slots[t].corner; }
  std::array<ref_t, 3>& adj(std::uint32_t t) noexcept { return slots[t].adj; }
  const std::array<ref_t, 3>& adj(std::uint32_t t) const noexcept { return slots[t].adj; }
  std::uint8_t& flags(std::uint32_t t) noexcept { return slots[t].flags; }
  std::uint8_t flags(std::uint32_t t) const noexcept { return slots[t].flags; }
  bool constrained(std::uint32_t t, int i) const noexcept { return (flags(t) >> i & 1u) != 0; }
  bool in_domain(std::uint32_t t) const noexcept { return (flags(t) & in_domain_bit) != 0; }
  void set_constrained(std::uint32_t t, int i, bool on) noexcept {
    const auto bit = static_cast<std::uint8_t>(1u << i);
    flags(t) = static_cast<std::uint8_t>(on ? flags(t) | bit : flags(t) & ~bit);
  }
  /// Sets edge i of t and the neighbour's copy of it constrained.
  void constrain(std::uint32_t t, int i) noexcept {
    set_constrained(t, i, true);
    if (adj(t)[i] != no_ref) set_constrained(ref_tri(adj(t)[i]), ref_edge(adj(t)[i]), true);
  }
  const point& at(std::uint32_t t, int i) const noexcept { return pts[corner(t)[i]]; }
  /// The index of vertex v among t's corners (v must be one).
  int index_of(std::uint32_t t, index_t v) const noexcept {
    return corner(t)[0] == v ? 0 : corner(t)[1] == v ? 1 : 2;
  }

  /// Writes triangle t and the back references of its neighbours.
  void write(std::uint32_t t, std::array<index_t, 3> c, std::array<ref_t, 3> n, std::uint8_t f) {
    slots[t] = {c, n, f};
    for (int i = 0; i < 3; ++i) {
      vertex_tri[c[i]] = t;
      if (n[i] != no_ref) adj(ref_tri(n[i]))[ref_edge(n[i])] = make_ref(t, i);
    }
  }
  std::uint32_t new_slot() {
    slots.push_back({{dead, dead, dead}, {no_ref, no_ref, no_ref}, 0});
    return size() - 1;
  }

  /// Starts with the bounding triangle of three new vertices (appended to pts) far around the
  /// points already in pts (all finite).
  void start_bounding_triangle() {
    double x0 = 0, x1 = 0, y0 = 0, y1 = 0;
    if (!pts.empty()) x0 = x1 = pts[0].x, y0 = y1 = pts[0].y;
    for (const point& p : pts)
      x0 = std::min(x0, p.x), x1 = std::max(x1, p.x), y0 = std::min(y0, p.y),
      y1 = std::max(y1, p.y);
    double r = std::max(x1 - x0, y1 - y0);
    if (!(r > 0)) r = std::max({std::abs(x0), std::abs(y0), 1.0});
    const double cx = 0.5 * (x0 + x1), cy = 0.5 * (y0 + y1);
    const auto b = static_cast<index_t>(pts.size());
    pts.push_back({cx - 64 * r, cy - 32 * r});
    pts.push_back({cx + 64 * r, cy - 32 * r});
    pts.push_back({cx, cy + 64 * r});
    vertex_tri.assign(pts.size(), 0);
    write(new_slot(), {b, b + 1, b + 2}, {no_ref, no_ref, no_ref}, 0);
  }

  /// Flips edge i of t (unconstrained, its quadrilateral strictly convex). t = (p, q, r) with
  /// edge i = (q, r), its neighbour u = (s, r, q); afterwards t = (p, q, s), u = (s, r, p).
  void flip(std::uint32_t t, int i) {
    const ref_t nb = adj(t)[i];
    const std::uint32_t u = ref_tri(nb);
    const int j = ref_edge(nb);
    const index_t p = corner(t)[i], q = corner(t)[next3(i)], r = corner(t)[prev3(i)];
    const index_t s = corner(u)[j];
    const ref_t n_q = adj(t)[next3(i)], n_r = adj(t)[prev3(i)];
    const ref_t m_r = adj(u)[next3(j)], m_q = adj(u)[prev3(j)];
    const bool c_nq = constrained(t, next3(i)), c_nr = constrained(t, prev3(i));
    const bool c_mr = constrained(u, next3(j)), c_mq = constrained(u, prev3(j));
    const auto keep = static_cast<std::uint8_t>(flags(t) & in_domain_bit);
    const auto bits = [](bool a, bool b, bool c) {
      return static_cast<std::uint8_t>((a ? 1 : 0) | (b ? 2 : 0) | (c ? 4 : 0));
    };
    write(t, {p, q, s}, {m_r, make_ref(u, 1), n_r}, keep | bits(c_mr, false, c_nr));
    write(u, {s, r, p}, {n_q, make_ref(t, 1), m_q}, keep | bits(c_nq, false, c_mq));
  }

  /// The triangle and edge index of the directed edge a -> b (counter-clockwise in the
  /// returned triangle), or no_ref. Rotates around a, which must have a closed fan or be a
  /// bounding vertex.
  ref_t find_edge(index_t a, index_t b) const {
    const std::uint32_t start = vertex_tri[a];
    std::uint32_t t = start;
    do {
      const int k = index_of(t, a);
      if (corner(t)[next3(k)] == b) return make_ref(t, prev3(k));
      const ref_t n = adj(t)[prev3(k)]; // across edge (a, corner k+1): clockwise around a
      if (n == no_ref) break;
      t = ref_tri(n);
    } while (t != start);
    // Open fan (bounding vertex): the other direction.
    t = start;
    for (;;) {
      const ref_t n = adj(t)[next3(index_of(t, a))];
      if (n == no_ref) return no_ref;
      t = ref_tri(n);
      if (t == start) return no_ref;
      const int k = index_of(t, a);
      if (corner(t)[next3(k)] == b) return make_ref(t, prev3(k));
    }
  }

  /// Visibility walk from triangle `from` to a triangle that contains p (closed), choosing the
  /// first edge to test with a deterministic generator so the walk cannot cycle.
  std::uint32_t locate(const point& p, std::uint32_t from, std::uint32_t& rng) const {
    std::uint32_t t = from;
    for (;;) {
      rng = rng * 1664525u + 1013904223u;
      const int k = static_cast<int>((rng >> 16) % 3);
      bool moved = false;
      for (int e = 0; e < 3 && !moved; ++e) {
        const int i = (k + e) % 3;
        if (adj(t)[i] != no_ref && orient(at(t, next3(i)), at(t, prev3(i)), p) < 0) {
          t = ref_tri(adj(t)[i]);
          moved = true;
        }
      }
      if (!moved) return t;
    }
  }
};

} // namespace pdd::detail::native_mesh
