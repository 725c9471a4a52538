/// \file triangulation_levels.hpp
/// pdd::flood_levels: the nesting level of every face of a constrained triangulation, the one
/// flood fill that tells which faces are inside a domain of closed loops.
#pragma once

#include <utility>
#include <vector>

namespace pdd {

/// A flood_levels visitor that does nothing (the default).
struct no_level_visitor {
  /// Called when the flood meets a constrained edge with an unlabelled neighbour; ignores it.
  template <class Face>
  void constraint(Face, int) const noexcept {}
  /// Called right after a face gets its level; ignores it.
  template <class Face>
  void labelled(Face, Face, int) const noexcept {}
};

/// Sets the level of every face of the constrained triangulation `tr`: the number of
/// constrained edges crossed on the way from the infinite face (level 0), found by one flood
/// per level in increasing order (as CGAL's mark_domain_in_triangulation). With Triangle's
/// convention the domain is the faces at odd levels.
/// `level(f)` returns a reference to face f's level, which must be -1 for every face before.
/// `visitor` sees the flood as it runs (for per-face data beyond the level, e.g. which loop
/// encloses a face): `visitor.constraint(f, i)` when the flood meets constrained edge i of
/// face f with its neighbour still unlabelled (that neighbour is queued for level(f) + 1), and
/// `visitor.labelled(n, f, i)` right after face n gets its level, reached from face f across
/// f's edge i (constrained when level(n) = level(f) + 1; f is a default Face_handle and i = -1
/// for the infinite face). Every face is labelled once, after the face it was reached from.
/// \tparam Tr a CGAL constrained triangulation (Face_handle, infinite_face, neighbor,
/// is_constrained). Complexity O(number of faces). Not thread-safe on one triangulation.
template <class Tr, class Level, class Visitor = no_level_visitor>
void flood_levels(const Tr& tr, Level&& level, Visitor&& visitor = {}) {
  using face_handle = typename Tr::Face_handle;
  struct crossing {
    face_handle face, from;
    int edge;
  };
  std::vector<crossing> border{{tr.infinite_face(), face_handle(), -1}}, next_border;
  std::vector<face_handle> stack;
  for (int depth = 0; !border.empty(); ++depth) {
    next_border.clear();
    for (const crossing& start : border) {
      if (level(start.face) != -1) continue;
      level(start.face) = depth;
      visitor.labelled(start.face, start.from, start.edge);
      stack.assign(1, start.face);
      while (!stack.empty()) {
        const face_handle f = stack.back();
        stack.pop_back();
        for (int i = 0; i < 3; ++i) {
          const face_handle n = f->neighbor(i);
          if (level(n) != -1) continue;
          if (f->is_constrained(i)) {
            visitor.constraint(f, i);
            next_border.push_back({n, f, i});
          } else {
            level(n) = depth;
            visitor.labelled(n, f, i);
            stack.push_back(n);
          }
        }
      }
    }
    std::swap(border, next_border);
  }
}

} // namespace pdd
