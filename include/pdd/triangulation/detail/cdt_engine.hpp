/// \file cdt_engine.hpp
/// The operations of pdd::constrained_delaunay_2 on vertex ids: insertion (points on fewer
/// than two dimensions wait until three are not collinear, as CGAL's lower-dimensional
/// triangulations do), constraint insertion by flips (Sloan 1993: flip the edges crossing the
/// segment until it appears; then Lawson's flips restore the constrained Delaunay property
/// around the faces the flips made), and constraint removal.
#pragma once

#include <pdd/triangulation/detail/cdt_insert.hpp>

#include <map>
#include <stdexcept>
#include <utility>
#include <vector>

namespace pdd::detail::cdt {

/// Two constraints cross, or (unless vertices may split constraints) a vertex lies inside one.
struct constraint_intersection : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// The triangulation's state and its operations. Not thread-safe on one object.
class engine {
public:
  explicit engine(bool split_at_vertices) : split_at_vertices_(split_at_vertices) {}

  storage s;

  /// Inserts p (hint: a face near it, or no_face); an existing vertex at p is returned with
  /// `false`.
  std::pair<index_t, bool> insert(const epick::Point_2& p, face_t hint) {
    if (s.dimension < 2) return insert_low(p);
    const located l = locate(s, p, hint == no_face ? last_ : hint);
    if (l.type == location::vertex) return {s.corner[l.face][l.index], false};
    const index_t v = add_vertex(p);
    insert_at(v, l);
    return {v, true};
  }

  /// The faces the last insertion wrote (new faces: their data are reset by the caller).
  const std::vector<face_t>& created() const noexcept { return created_; }

  /// Makes a -> b a constrained edge (a != b). With vertices on the segment, the pieces
  /// between them if vertices may split constraints. \throws constraint_intersection.
  void insert_constraint(index_t a, index_t b) {
    if (a == b) return;
    if (s.dimension < 2) {
      low_constraints_.emplace_back(a, b);
      return;
    }
    const ref_t r = s.find_edge(a, b);
    if (r != no_ref) return s.set_edge_constrained(ref_face(r), ref_edge(r), true);
    const index_t on = crossed_edges(a, b);
    if (on != no_index) {
      if (!split_at_vertices_) throw constraint_intersection("a vertex lies on the constraint");
      insert_constraint(a, on);
      return insert_constraint(on, b);
    }
    flip_crossed(a, b);
    const ref_t e = s.find_edge(a, b);
    s.set_edge_constrained(ref_face(e), ref_edge(e), true);
    restore_delaunay();
  }

  /// Makes edge i of f unconstrained and restores the Delaunay property around it.
  void remove_constraint(face_t f, int i) {
    s.set_edge_constrained(f, i, false);
    lawson_.assign(1, {s.corner[f][next3(i)], s.corner[f][prev3(i)]});
    restore_delaunay();
  }

  /// Whether vertex v is (or waits to be) in the triangulation.
  bool has_vertex(index_t v) const noexcept {
    return v != infinite && v < s.pts.size() &&
           (s.vertex_face[v] != no_face || low_.count({s.pts[v].x(), s.pts[v].y()}) != 0);
  }

private:
  index_t add_vertex(const epick::Point_2& p) {
    s.pts.push_back(p);
    s.vertex_face.push_back(no_face);
    return static_cast<index_t>(s.pts.size() - 1);
  }

  /// Inserts new vertex v at location l (not a vertex).
  void insert_at(index_t v, const located& l) {
    const epick::Point_2& p = s.pts[v];
    seeds_.assign(1, l.face);
    ref_t crossing = cavity::crossing_none;
    if (l.type == location::edge && s.constrained(l.face, l.index)) {
      seeds_.push_back(ref_face(s.adj[l.face][l.index]));
      crossing = make_ref(l.face, l.index);
      cav_.set_split_endpoints(s.corner[l.face][next3(l.index)], s.corner[l.face][prev3(l.index)]);
    }
    cav_.grow(s, p, seeds_, crossing);
    if (!cav_.make_star_shaped(s, p, seeds_.size()))
      throw std::logic_error("pdd::constrained_delaunay_2: a point is not visible from its face");
    cav_.commit(s, v);
    created_ = cav_.created();
    last_ = created_.front();
  }

  /// Fewer than two dimensions so far: p waits, or starts the 2D triangulation.
  std::pair<index_t, bool> insert_low(const epick::Point_2& p) {
    const auto [it, added] = low_.emplace(std::make_pair(p.x(), p.y()), no_index);
    if (!added) return {it->second, false};
    const index_t v = add_vertex(p);
    it->second = v;
    created_.clear();
    if (low_order_.size() < 2 || orient(s.pts[low_order_[0]], s.pts[low_order_[1]], p) == 0) {
      low_order_.push_back(v);
      s.dimension = low_order_.size() == 1 ? 0 : 1;
      return {v, true};
    }
    start_2d(v);
    return {v, true};
  }

  /// The first face (a, b, v) and its three infinite neighbours; then the waiting vertices and
  /// constraints.
  void start_2d(index_t v) {
    index_t a = low_order_[0], b = low_order_[1];
    if (orient(s.pts[a], s.pts[b], s.pts[v]) < 0) std::swap(a, b);
    const face_t f = s.new_slot(), i0 = s.new_slot(), i1 = s.new_slot(), i2 = s.new_slot();
    s.write(f, {a, b, v}, {make_ref(i0, 2), make_ref(i1, 2), make_ref(i2, 2)}, 0);
    s.write(i0, {v, b, infinite}, {make_ref(i2, 1), make_ref(i1, 0), make_ref(f, 0)}, 0);
    s.write(i1, {a, v, infinite}, {make_ref(i0, 1), make_ref(i2, 0), make_ref(f, 1)}, 0);
    s.write(i2, {b, a, infinite}, {make_ref(i1, 1), make_ref(i0, 0), make_ref(f, 2)}, 0);
    s.dimension = 2;
    last_ = f;
    std::vector<face_t> all{f, i0, i1, i2};
    for (std::size_t k = 2; k < low_order_.size(); ++k) {
      const index_t w = low_order_[k];
      insert_at(w, locate(s, s.pts[w], last_));
      all.insert(all.end(), created_.begin(), created_.end());
    }
    low_order_.clear();
    low_.clear();
    const auto constraints = std::move(low_constraints_);
    low_constraints_.clear();
    for (const auto& [x, y] : constraints)
      insert_constraint(x, y);
    created_ = std::move(all);
  }

  /// The edges crossed by segment a -> b (no edge yet) as vertex pairs in crossed_, or the
  /// first vertex strictly inside the segment. \throws constraint_intersection when a crossed
  /// edge is constrained.
  index_t crossed_edges(index_t a, index_t b) {
    crossed_.clear();
    const epick::Point_2 &pa = s.pts[a], &pb = s.pts[b];
    face_t f = s.vertex_face[a];
    for (;;) { // rotate around a to the face the segment leaves a through
      const int k = s.index_of(f, a);
      const index_t q = s.corner[f][next3(k)], r = s.corner[f][prev3(k)];
      const int oq = q == infinite ? 1 : orient(pa, pb, s.pts[q]);
      if (oq == 0 && CGAL::collinear_are_strictly_ordered_along_line(pa, s.pts[q], pb)) return q;
      if (oq < 0 && r != infinite && orient(pa, pb, s.pts[r]) > 0) break;
      f = ref_face(s.adj[f][next3(k)]);
    }
    return walk_crossed(a, b, f);
  }

  index_t walk_crossed(index_t a, index_t b, face_t f) {
    const epick::Point_2 &pa = s.pts[a], &pb = s.pts[b];
    int edge = s.index_of(f, a);
    index_t right = s.corner[f][next3(edge)], left = s.corner[f][prev3(edge)];
    for (;;) {
      if (s.constrained(f, edge)) throw constraint_intersection("two constraints cross");
      crossed_.emplace_back(left, right);
      const ref_t n = s.adj[f][edge];
      f = ref_face(n);
      const index_t apex = s.corner[f][ref_edge(n)];
      if (apex == b) return no_index;
      const int o = orient(pa, pb, s.pts[apex]);
      if (o == 0) return apex;
      edge = s.index_of(f, o > 0 ? left : right); // the next crossed edge: apex to the other side
      (o > 0 ? left : right) = apex;
    }
  }

  /// Flips the crossed edges (Sloan 1993); an edge that cannot be flipped yet (its
  /// quadrilateral not strictly convex) goes to the back of the queue. Every edge of a face
  /// the flips make is queued for Lawson's flips.
  void flip_crossed(index_t a, index_t b) {
    const epick::Point_2 &pa = s.pts[a], &pb = s.pts[b];
    lawson_.clear();
    for (std::size_t head = 0; head < crossed_.size(); ++head) {
      const ref_t e = s.find_edge(crossed_[head].first, crossed_[head].second);
      const face_t f = ref_face(e);
      const int i = ref_edge(e);
      const index_t p = s.corner[f][i], q = s.corner[f][next3(i)], r = s.corner[f][prev3(i)];
      const index_t sv = s.apex_across(f, i);
      if (orient(s.pts[p], s.pts[q], s.pts[sv]) <= 0 ||
          orient(s.pts[sv], s.pts[r], s.pts[p]) <= 0) {
        crossed_.push_back(crossed_[head]); // not convex yet
        continue;
      }
      s.flip(f, i);
      lawson_.insert(lawson_.end(), {{p, sv}, {p, q}, {q, sv}, {sv, r}, {r, p}});
      if (p != a && p != b && sv != a && sv != b &&
          orient(pa, pb, s.pts[p]) * orient(pa, pb, s.pts[sv]) < 0)
        crossed_.emplace_back(p, sv);
    }
  }

  /// Lawson's flips from the queued edges until each is locally constrained Delaunay.
  void restore_delaunay() {
    while (!lawson_.empty()) {
      const auto [u, w] = lawson_.back();
      lawson_.pop_back();
      const ref_t e = s.find_edge(u, w);
      if (e == no_ref) continue; // flipped away
      const face_t f = ref_face(e);
      const int i = ref_edge(e);
      const face_t g = ref_face(s.adj[f][i]);
      if (s.constrained(f, i) || s.is_infinite(f) || s.is_infinite(g)) continue;
      const index_t p = s.corner[f][i], sv = s.apex_across(f, i);
      if (!in_circle(s.at(f, 0), s.at(f, 1), s.at(f, 2), s.pts[sv])) continue;
      s.flip(f, i);
      lawson_.insert(lawson_.end(), {{p, u}, {u, sv}, {sv, w}, {w, p}});
    }
  }

  bool split_at_vertices_;
  cavity cav_;
  face_t last_ = 0;
  std::vector<face_t> seeds_, created_;
  std::vector<std::pair<index_t, index_t>> crossed_, lawson_, low_constraints_;
  std::vector<index_t> low_order_;                   ///< waiting vertices, in order
  std::map<std::pair<double, double>, index_t> low_; ///< waiting vertices by point
};

} // namespace pdd::detail::cdt
