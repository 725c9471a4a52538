/// \file triangulation_levels.hpp
/// pdd::flood_levels: the nesting level of every face of a constrained triangulation, the one
/// flood fill that tells which faces are inside a domain of closed loops.
#pragma once

#include <utility>
#include <vector>

namespace pdd {

/// Sets the level of every face of the constrained triangulation `tr`: the number of
/// constrained edges crossed on the way from the infinite face (level 0), found by one flood
/// per level in increasing order (as CGAL's mark_domain_in_triangulation). With Triangle's
/// convention the domain is the faces at odd levels.
/// `level(f)` returns a reference to face f's level, which must be -1 for every face before.
/// \tparam Tr a CGAL constrained triangulation (Face_handle, infinite_face, neighbor,
/// is_constrained). Complexity O(number of faces). Not thread-safe on one triangulation.
template <class Tr, class Level>
void flood_levels(const Tr& tr, Level&& level) {
  using face_handle = typename Tr::Face_handle;
  std::vector<face_handle> border{tr.infinite_face()}, next_border, stack;
  for (int depth = 0; !border.empty(); ++depth) {
    next_border.clear();
    for (const face_handle start : border) {
      if (level(start) != -1) continue;
      level(start) = depth;
      stack.assign(1, start);
      while (!stack.empty()) {
        const face_handle f = stack.back();
        stack.pop_back();
        for (int i = 0; i < 3; ++i) {
          const face_handle n = f->neighbor(i);
          if (level(n) != -1) continue;
          if (f->is_constrained(i)) {
            next_border.push_back(n);
          } else {
            level(n) = depth;
            stack.push_back(n);
          }
        }
      }
    }
    std::swap(border, next_border);
  }
}

} // namespace pdd
