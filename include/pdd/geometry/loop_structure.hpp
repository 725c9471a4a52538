/// \file loop_structure.hpp
/// pdd::polygon_loop and pdd::loop_structure: the closed loops of a PSLG as pdd::find_loops
/// (geometry/loops.hpp) finds them.
#pragma once

#include <pdd/core/index.hpp>

#include <vector>

namespace pdd {

/// One closed loop of segments of a PSLG.
struct polygon_loop {
  /// The loop's vertices in traversal order; vertices[0] is the smallest vertex id of the
  /// loop, and the traversal leaves it along its incident segment with the smaller id.
  std::vector<index_t> vertices;
  /// segments[i] joins vertices[i] -> vertices[(i + 1) % n].
  std::vector<index_t> segments;
  /// Shoelace area of the traversal order (> 0: counter-clockwise).
  double signed_area = 0.0;
  /// Exact orientation of the traversal order (CGAL orientation predicate at the
  /// lexicographically smallest vertex); agrees with the sign of signed_area except when
  /// rounding makes a near-degenerate loop's area meaningless.
  bool counterclockwise = true;
  /// Number of other loops enclosing this loop (0 = outermost).
  int depth = 0;
  /// The innermost enclosing loop, or no_index.
  index_t parent = no_index;
  /// True if the region just inside the loop belongs to the domain (depth even).
  bool bounds_domain_inside = true;

  /// True if the domain lies to the left of the traversal direction.
  bool domain_on_left() const noexcept { return counterclockwise == bounds_domain_inside; }
};

/// All loops of a PSLG, in the order of their smallest vertex id.
struct loop_structure {
  /// Every closed loop of the PSLG, with its orientation and nesting, in the order of its
  /// smallest vertex id; polygon_loop::parent indexes this vector.
  std::vector<polygon_loop> loops;
};

} // namespace pdd
