/// \file cdt_handles.hpp
/// The handles, circulator and iterators of pdd::constrained_delaunay_2, named and shaped as
/// CGAL's (Vertex_handle, Face_handle, Face_circulator, the finite and all iterators), so that
/// code written against CGAL's Constrained_Delaunay_triangulation_2 reads the same. A handle is
/// the triangulation's address and an id; it stays valid while the vertex or face slot lives
/// (vertices are never removed; face slots are rewritten, never freed).
#pragma once

#include <pdd/triangulation/detail/cdt_engine.hpp>

#include <compare>
#include <cstddef>
#include <iterator>
#include <type_traits>
#include <utility>

namespace pdd::detail::cdt {

/// A vertex: point() and info().
template <class Tr>
class vertex_handle {
public:
  vertex_handle() = default;
  vertex_handle(Tr* tr, index_t v) noexcept : tr_(tr), v_(v) {}
  const vertex_handle* operator->() const noexcept { return this; }
  const epick::Point_2& point() const { return tr_->engine_.s.pts[v_]; }
  typename Tr::vertex_info& info() const { return tr_->vinfo_[v_]; }
  /// A face incident to the vertex.
  typename Tr::Face_handle face() const { return {tr_, tr_->engine_.s.vertex_face[v_]}; }
  /// The vertex's id: 0 the infinite vertex, then in order of insertion.
  index_t id() const noexcept { return v_; }
  friend bool operator==(const vertex_handle&, const vertex_handle&) = default;
  friend auto operator<=>(const vertex_handle&, const vertex_handle&) = default;

private:
  Tr* tr_ = nullptr;
  index_t v_ = no_index;
};

/// A face: vertex(i), neighbor(i), index(), is_constrained(i) and info().
template <class Tr>
class face_handle {
public:
  using Vertex_handle = vertex_handle<Tr>;
  face_handle() = default;
  face_handle(Tr* tr, face_t f) noexcept : tr_(tr), f_(f) {}
  const face_handle* operator->() const noexcept { return this; }
  Vertex_handle vertex(int i) const { return {tr_, store().corner[f_][i]}; }
  face_handle neighbor(int i) const { return {tr_, ref_face(store().adj[f_][i])}; }
  /// The index of vertex v among the face's corners (v must be one).
  int index(const Vertex_handle& v) const { return store().index_of(f_, v.id()); }
  /// The index of the edge shared with neighbour n (n must be one).
  int index(const face_handle& n) const {
    const auto& a = store().adj[f_];
    return ref_face(a[0]) == n.f_ ? 0 : ref_face(a[1]) == n.f_ ? 1 : 2;
  }
  bool has_vertex(const Vertex_handle& v) const {
    const auto& c = store().corner[f_];
    return c[0] == v.id() || c[1] == v.id() || c[2] == v.id();
  }
  bool is_constrained(int i) const { return store().constrained(f_, i); }
  typename Tr::face_info& info() const { return tr_->finfo_[f_]; }
  /// The face's slot: stable while the face is not rewritten by an insertion or a flip.
  face_t id() const noexcept { return f_; }
  friend bool operator==(const face_handle&, const face_handle&) = default;
  friend auto operator<=>(const face_handle&, const face_handle&) = default;

private:
  const storage& store() const { return tr_->engine_.s; }
  Tr* tr_ = nullptr;
  face_t f_ = no_face;
};

/// The faces around a vertex, counter-clockwise (++) or clockwise (--), CGAL's
/// Face_circulator: it converts to the face handle it points at.
template <class Tr>
class face_circulator {
public:
  using Face_handle = face_handle<Tr>;
  face_circulator() = default;
  face_circulator(Face_handle f, typename Face_handle::Vertex_handle v) noexcept : f_(f), v_(v) {}
  const Face_handle& operator*() const noexcept { return f_; }
  const Face_handle* operator->() const noexcept { return &f_; }
  operator Face_handle() const noexcept { return f_; }
  face_circulator& operator++() {
    f_ = f_.neighbor(next3(f_.index(v_)));
    return *this;
  }
  face_circulator& operator--() {
    f_ = f_.neighbor(prev3(f_.index(v_)));
    return *this;
  }
  face_circulator operator++(int) {
    face_circulator old = *this;
    ++*this;
    return old;
  }
  face_circulator operator--(int) {
    face_circulator old = *this;
    --*this;
    return old;
  }
  friend bool operator==(const face_circulator& a, const face_circulator& b) noexcept {
    return a.f_ == b.f_;
  }

private:
  Face_handle f_;
  typename Face_handle::Vertex_handle v_;
};

/// A forward iterator over the ids [first, last) that Keep accepts, yielding Handle(tr, id), or
/// Make(tr, id) with a Make (and converting to it, as CGAL's iterators convert to handles).
template <class Tr, class Handle, class Keep, class Make = void>
class handle_iterator {
public:
  using iterator_category = std::forward_iterator_tag;
  using value_type = Handle;
  using difference_type = std::ptrdiff_t;
  using pointer = const Handle*;
  using reference = const Handle&;

  handle_iterator() = default;
  handle_iterator(Tr* tr, std::size_t id, std::size_t last) : tr_(tr), id_(id), last_(last) {
    skip();
  }
  const Handle& operator*() const noexcept { return h_; }
  const Handle* operator->() const noexcept { return &h_; }
  operator Handle() const noexcept { return h_; }
  handle_iterator& operator++() {
    ++id_;
    skip();
    return *this;
  }
  handle_iterator operator++(int) {
    handle_iterator old = *this;
    ++*this;
    return old;
  }
  friend bool operator==(const handle_iterator& a, const handle_iterator& b) noexcept {
    return a.id_ == b.id_;
  }

private:
  void skip() {
    while (id_ < last_ && !Keep{}(*tr_, id_))
      ++id_;
    if (id_ >= last_) return;
    if constexpr (std::is_void_v<Make>)
      h_ = Handle(tr_, static_cast<index_t>(id_));
    else
      h_ = Make{}(tr_, id_);
  }
  Tr* tr_ = nullptr;
  std::size_t id_ = 0, last_ = 0;
  Handle h_;
};

/// A range of two iterators (for range-for).
template <class It>
struct handle_range {
  It first, last;
  It begin() const { return first; }
  It end() const { return last; }
};

} // namespace pdd::detail::cdt
