/// \file shield_triangle.hpp
/// pdd::shield_triangle: one shielded triangle b'ac' of dissertation 8.1 (Algorithm 8.2,
/// steps 8-9); the reserved marker of shield edges is pdd::shield_marker
/// (core/segment_markers.hpp).
#pragma once

#include <pdd/core/point.hpp>
#include <pdd/core/segment_markers.hpp>

namespace pdd {

/// A shielded triangle (apex, b, c), counter-clockwise: apex is the vertex a of an input angle
/// theta < 60 deg, b and c are the shield points on its two segments (|ab| = |ac|, eq. 8.1),
/// bc is the shield edge. It becomes one mesh element as it is: its angle at the apex is the
/// input angle and its circumradius-to-shortest-edge ratio is 1 / (2 sin theta) (Theorem 24).
struct shield_triangle {
  /// The apex a: the vertex of the input angle theta < 60 deg.
  point apex;
  /// The shield point on the first segment from the apex (counter-clockwise order apex, b, c).
  point b;
  /// The shield point on the second segment from the apex, |ac| = |ab|.
  point c;
  int apex_marker = 0;     ///< the apex's vertex marker
  int marker_ab = 0;       ///< marker of the input segment through a and b
  int marker_ac = 0;       ///< marker of the input segment through a and c
  double angle_deg = 0.0;  ///< theta, the input angle at the apex (degrees)
  index_t apex_vertex = 0; ///< the apex's vertex id in the source (pslg or vertex pool)
  index_t b_vertex = 0;    ///< b's vertex id in the shielded domain (pslg or vertex pool)
  index_t c_vertex = 0;    ///< c's vertex id in the shielded domain (pslg or vertex pool)
};

} // namespace pdd
