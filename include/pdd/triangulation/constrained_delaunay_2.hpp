/// \file constrained_delaunay_2.hpp
/// pdd::constrained_delaunay_2: pdd's own constrained Delaunay triangulation of points and
/// segments in the plane, with the interface of the part of CGAL's
/// Constrained_Delaunay_triangulation_2 that pdd uses (handles, an infinite vertex, the
/// finite and all iterators, constraints, point location). It uses CGAL's kernel predicates
/// and spatial sorting (LGPL) and none of CGAL's triangulation packages (GPL), so that MADD,
/// the geometry and the Triangle front end build without them (PDD_PERMISSIVE).
#pragma once

#include <pdd/triangulation/detail/cdt_handles.hpp>

#include <CGAL/Spatial_sort_traits_adapter_2.h>
#include <CGAL/property_map.h>
#include <CGAL/spatial_sort.h>

#include <cstddef>
#include <numeric>
#include <type_traits>
#include <utility>
#include <vector>

namespace pdd {

/// What a constraint may meet: `refuse` throws on any vertex inside it or constraint crossing
/// it (CGAL's No_constraint_intersection_tag); `split_at_vertices` makes a constraint through
/// vertices the pieces between them and throws on crossing constraints (CGAL's
/// Exact_predicates_tag would construct the crossing point: pdd never needs it).
enum class constraint_crossing { refuse, split_at_vertices };

/// No data on a vertex or face.
struct no_cdt_info {};

/// A constrained Delaunay triangulation (Chew 1989) built incrementally: vertices by
/// Bowyer-Watson insertion, constraints by flips, exact predicates throughout. Vertices are
/// never removed. `VertexInfo` and `FaceInfo` are data kept on each vertex and face (a face's
/// data is default-constructed when an insertion makes it, kept through flips).
/// Complexity: insert of n points O(n log n) expected (spatially sorted); a constraint
/// O(faces it crosses) flips. Not thread-safe on one object; separate objects are independent.
template <class VertexInfo = no_cdt_info, class FaceInfo = no_cdt_info>
class constrained_delaunay_2 {
  using self = constrained_delaunay_2;

public:
  /// The data kept on each vertex.
  using vertex_info = VertexInfo;
  /// The data kept on each face.
  using face_info = FaceInfo;
  /// The point type (CGAL's Epick point).
  using Point = epick::Point_2;
  /// A vertex: point(), info(), face().
  using Vertex_handle = detail::cdt::vertex_handle<self>;
  /// A face: vertex(i), neighbor(i), index(), is_constrained(i), info().
  using Face_handle = detail::cdt::face_handle<self>;
  /// An edge: the face and the index of the vertex opposite it.
  using Edge = std::pair<Face_handle, int>;
  /// The faces around a vertex (incident_faces).
  using Face_circulator = detail::cdt::face_circulator<self>;
  /// Thrown when constraints cross (or meet a vertex, under constraint_crossing::refuse).
  using Intersection_of_constraints_exception = detail::cdt::constraint_intersection;
  /// Where a point lies, as CGAL's Locate_type.
  enum Locate_type { VERTEX = 0, EDGE, FACE, OUTSIDE_CONVEX_HULL, OUTSIDE_AFFINE_HULL };

private:
  struct finite_face {
    bool operator()(const self& t, std::size_t f) const {
      return !t.engine_.s.is_infinite(static_cast<detail::cdt::face_t>(f));
    }
  };
  struct any_face {
    bool operator()(const self&, std::size_t) const { return true; }
  };
  struct finite_vertex {
    bool operator()(const self& t, std::size_t v) const {
      return t.engine_.has_vertex(static_cast<index_t>(v));
    }
  };
  struct finite_edge {
    bool operator()(const self& t, std::size_t e) const;
  };
  struct make_edge {
    Edge operator()(self* t, std::size_t e) const {
      return {Face_handle(t, static_cast<detail::cdt::face_t>(e / 3)), static_cast<int>(e % 3)};
    }
  };

public:
  /// The faces not incident to the infinite vertex.
  using Finite_faces_iterator = detail::cdt::handle_iterator<self, Face_handle, finite_face>;
  /// Every face, the infinite ones included.
  using All_faces_iterator = detail::cdt::handle_iterator<self, Face_handle, any_face>;
  /// The vertices but the infinite one.
  using Finite_vertices_iterator = detail::cdt::handle_iterator<self, Vertex_handle, finite_vertex>;
  /// Each edge between two finite vertices once.
  using Finite_edges_iterator = detail::cdt::handle_iterator<self, Edge, finite_edge, make_edge>;

  /// An empty triangulation whose constraints follow `c`.
  explicit constrained_delaunay_2(constraint_crossing c = constraint_crossing::refuse)
      : engine_(c == constraint_crossing::split_at_vertices) {}
  constrained_delaunay_2(const constrained_delaunay_2&) = delete; // handles hold its address
  constrained_delaunay_2& operator=(const constrained_delaunay_2&) = delete;

  /// The index after i, counter-clockwise: i + 1 (mod 3) (CGAL's index arithmetic).
  static int ccw(int i) noexcept { return detail::cdt::next3(i); }
  /// The index before i, clockwise: i + 2 (mod 3).
  static int cw(int i) noexcept { return detail::cdt::prev3(i); }

  /// -1 empty, 0 one vertex, 1 collinear vertices (no faces yet), 2.
  int dimension() const noexcept { return engine_.s.dimension; }
  /// The finite vertices (a point inserted twice counts once).
  std::size_t number_of_vertices() const noexcept { return vertices_; }
  /// The finite faces (linear time).
  std::size_t number_of_faces() const {
    std::size_t n = 0;
    for (detail::cdt::face_t f = 0; f < engine_.s.size(); ++f)
      n += engine_.s.is_infinite(f) ? 0 : 1;
    return n;
  }

  /// Inserts p; the vertex already at p if there is one. `hint`: a face near p.
  Vertex_handle insert(const Point& p, Face_handle hint = Face_handle()) {
    const auto [v, added] =
        engine_.insert(p, hint == Face_handle() ? detail::cdt::no_face : hint.id());
    sync(added);
    return {this, v};
  }
  /// Inserts a range of points, or of (point, vertex info) pairs, in spatial order (CGAL's
  /// spatial_sort); a point already present keeps its vertex and info. \returns the vertices
  /// added.
  template <class It>
  std::ptrdiff_t insert(It first, It last);

  /// Makes the segment between a and b a constrained edge (see constraint_crossing).
  /// \throws Intersection_of_constraints_exception
  void insert_constraint(Vertex_handle a, Vertex_handle b) {
    engine_.insert_constraint(a.id(), b.id());
  }
  /// Inserts a and b (or finds them) and the constraint between them.
  void insert_constraint(const Point& a, const Point& b) {
    insert_constraint(insert(a), insert(b));
  }
  /// Makes edge i of f unconstrained; Delaunay flips around it follow.
  void remove_constrained_edge(Face_handle f, int i) { engine_.remove_constraint(f.id(), i); }

  /// Whether a and b are joined by an edge; if so, (f, i) is that edge.
  bool is_edge(Vertex_handle a, Vertex_handle b, Face_handle& f, int& i) const;
  /// Whether a and b are joined by an edge.
  bool is_edge(Vertex_handle a, Vertex_handle b) const {
    Face_handle f;
    int i = 0;
    return is_edge(a, b, f, i);
  }

  /// The face containing p (closed), its Locate_type, and the vertex or edge index li.
  Face_handle locate(const Point& p, Locate_type& lt, int& li, Face_handle hint = {}) const;
  /// The face containing p (see the overload with the Locate_type).
  Face_handle locate(const Point& p, Face_handle hint = {}) const {
    Locate_type lt{};
    int li = 0;
    return locate(p, lt, li, hint);
  }

  /// The infinite vertex: every hull edge has an infinite face (a, b, infinite vertex).
  Vertex_handle infinite_vertex() const { return {mut(), detail::cdt::infinite}; }
  /// An infinite face (2D).
  Face_handle infinite_face() const {
    return {mut(), engine_.s.vertex_face[detail::cdt::infinite]};
  }
  /// Whether v is the infinite vertex.
  bool is_infinite(Vertex_handle v) const noexcept { return v.id() == detail::cdt::infinite; }
  /// Whether f has the infinite vertex as a corner.
  bool is_infinite(Face_handle f) const { return engine_.s.is_infinite(f.id()); }
  /// Whether the face f points at is infinite.
  bool is_infinite(const Face_circulator& f) const { return is_infinite(Face_handle(f)); }
  /// Whether an end of e is the infinite vertex.
  bool is_infinite(const Edge& e) const {
    return is_infinite(e.first->vertex(ccw(e.second))) ||
           is_infinite(e.first->vertex(cw(e.second)));
  }
  /// The faces around v (2D only), starting at v->face().
  Face_circulator incident_faces(Vertex_handle v) const { return {v->face(), v}; }

  /// The first finite face.
  Finite_faces_iterator finite_faces_begin() const { return {mut(), 0, faces()}; }
  /// Past the last finite face.
  Finite_faces_iterator finite_faces_end() const { return {mut(), faces(), faces()}; }
  /// The first face.
  All_faces_iterator all_faces_begin() const { return {mut(), 0, faces()}; }
  /// Past the last face.
  All_faces_iterator all_faces_end() const { return {mut(), faces(), faces()}; }
  /// The first finite vertex.
  Finite_vertices_iterator finite_vertices_begin() const { return {mut(), 1, ids()}; }
  /// Past the last finite vertex.
  Finite_vertices_iterator finite_vertices_end() const { return {mut(), ids(), ids()}; }
  /// The first finite edge.
  Finite_edges_iterator finite_edges_begin() const { return {mut(), 0, 3 * faces()}; }
  /// Past the last finite edge.
  Finite_edges_iterator finite_edges_end() const { return {mut(), 3 * faces(), 3 * faces()}; }
  /// The finite faces, for range-for.
  detail::cdt::handle_range<Finite_faces_iterator> finite_face_handles() const {
    return {finite_faces_begin(), finite_faces_end()};
  }
  /// Every face, for range-for.
  detail::cdt::handle_range<All_faces_iterator> all_face_handles() const {
    return {all_faces_begin(), all_faces_end()};
  }
  /// The finite vertices, for range-for.
  detail::cdt::handle_range<Finite_vertices_iterator> finite_vertex_handles() const {
    return {finite_vertices_begin(), finite_vertices_end()};
  }

private:
  template <class>
  friend class detail::cdt::vertex_handle;
  template <class>
  friend class detail::cdt::face_handle;

  self* mut() const noexcept { return const_cast<self*>(this); }
  std::size_t faces() const noexcept { return engine_.s.size(); }
  std::size_t ids() const noexcept { return engine_.s.pts.size(); }
  /// After an insertion: sizes the data arrays, resets the data of the faces it made.
  void sync(bool added) {
    vertices_ += added ? 1 : 0;
    vinfo_.resize(engine_.s.pts.size());
    finfo_.resize(engine_.s.size());
    if (added)
      for (const detail::cdt::face_t f : engine_.created())
        finfo_[f] = FaceInfo{};
  }

  detail::cdt::engine engine_;
  std::vector<VertexInfo> vinfo_{VertexInfo{}};
  std::vector<FaceInfo> finfo_;
  std::size_t vertices_ = 0;
};

template <class VI, class FI>
bool constrained_delaunay_2<VI, FI>::finite_edge::operator()(const self& t, std::size_t e) const {
  const auto& s = t.engine_.s;
  const auto f = static_cast<detail::cdt::face_t>(e / 3);
  const int i = static_cast<int>(e % 3);
  if (s.is_infinite(f)) return false;
  const detail::cdt::face_t g = detail::cdt::ref_face(s.adj[f][i]);
  return s.is_infinite(g) || f < g;
}

template <class VI, class FI>
template <class It>
std::ptrdiff_t constrained_delaunay_2<VI, FI>::insert(It first, It last) {
  constexpr bool with_info = !std::is_convertible_v<decltype(*first), Point>;
  std::vector<Point> points;
  std::vector<VI> infos;
  for (It it = first; it != last; ++it) {
    if constexpr (with_info) {
      points.push_back(it->first);
      infos.push_back(it->second);
    } else {
      points.push_back(*it);
    }
  }
  std::vector<std::size_t> order(points.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  using map = CGAL::Pointer_property_map<Point>::type;
  CGAL::spatial_sort(
      order.begin(), order.end(),
      CGAL::Spatial_sort_traits_adapter_2<epick, map>(CGAL::make_property_map(points)));
  const std::size_t before = vertices_;
  Face_handle hint;
  for (const std::size_t i : order) {
    const std::size_t n = vertices_;
    const Vertex_handle v = insert(points[i], hint);
    if constexpr (with_info)
      if (vertices_ != n) v->info() = infos[i];
    hint = v->face();
  }
  return static_cast<std::ptrdiff_t>(vertices_ - before);
}

template <class VI, class FI>
bool constrained_delaunay_2<VI, FI>::is_edge(Vertex_handle a, Vertex_handle b, Face_handle& f,
                                             int& i) const {
  if (dimension() < 2 || a == b) return false;
  const detail::cdt::ref_t r = engine_.s.find_edge(a.id(), b.id());
  if (r == detail::cdt::no_ref) return false;
  f = Face_handle(mut(), detail::cdt::ref_face(r));
  i = detail::cdt::ref_edge(r);
  return true;
}

template <class VI, class FI>
typename constrained_delaunay_2<VI, FI>::Face_handle
constrained_delaunay_2<VI, FI>::locate(const Point& p, Locate_type& lt, int& li,
                                       Face_handle hint) const {
  if (dimension() < 2) {
    lt = OUTSIDE_AFFINE_HULL;
    li = 0;
    return {};
  }
  const detail::cdt::located l =
      detail::cdt::locate(engine_.s, p, hint == Face_handle() ? 0 : hint.id());
  lt = static_cast<Locate_type>(l.type);
  li = l.index;
  return {mut(), l.face};
}

} // namespace pdd
