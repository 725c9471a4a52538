/// \file segments.hpp
/// Which input segment a constrained edge of the native triangulation lies on, and where a
/// subsegment is split (Ruppert's concentric shells).
#pragma once

#include <pdd/core/pslg.hpp>
#include <pdd/core/triangle_measures.hpp>
#include <pdd/kernels/detail/mesher_input.hpp>
#include <pdd/kernels/native/detail/triangulation.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

namespace pdd::detail::native_mesh {

/// Per vertex of the triangulation, the input segment a Steiner vertex was inserted on
/// (no_index for input vertices, the bounding triangle and free Steiner vertices).
struct segment_ids {
  segment_table table;
  std::vector<index_t> of_vertex;
  std::size_t inputs = 0; ///< vertices [0, inputs + 3) are input or bounding vertices

  segment_ids(const pslg& d, std::size_t vertices)
      : table(d), of_vertex(vertices, no_index), inputs(d.vertices.size()) {}

  /// The input segment the constrained edge (u, v) lies on (no_index if none is found).
  index_t of_edge(index_t u, index_t v) const {
    if (of_vertex[u] != no_index) return of_vertex[u];
    if (of_vertex[v] != no_index) return of_vertex[v];
    return table.find(u, v);
  }
  bool is_input(index_t v) const noexcept { return v < inputs; }
};

/// The split point of subsegment [a, b]: Ruppert's concentric shells (Ruppert 1995, sec. 3.3;
/// Shewchuk 1997, sec. 3.5) when exactly one endpoint is an input vertex, so that the pieces
/// at a small input angle have power-of-two lengths and two segments meeting there are split
/// on the same circles instead of encroaching each other forever; the midpoint otherwise.
inline point split_point(const point& a, bool a_input, const point& b, bool b_input) {
  if (a_input != b_input) {
    const point& from = a_input ? a : b;
    const point& to = a_input ? b : a;
    const double length = std::sqrt(squared_distance(from, to));
    const double f = std::exp2(std::round(std::log2(0.5 * length))) / length;
    return {from.x + (to.x - from.x) * f, from.y + (to.y - from.y) * f};
  }
  return {0.5 * (a.x + b.x), 0.5 * (a.y + b.y)};
}

} // namespace pdd::detail::native_mesh
