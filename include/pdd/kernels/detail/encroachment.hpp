/// \file encroachment.hpp
/// The encroachment rule both refinement kernels share (pdd::segment_encroachment): which
/// segments of a kernel's input take the diametral lens, and the lens test.
#pragma once

#include <pdd/core/mesh_criteria.hpp>
#include <pdd/core/point.hpp>
#include <pdd/core/pslg.hpp>
#include <pdd/core/segment_markers.hpp>

#include <algorithm>

namespace pdd::detail {

/// Whether d is refined under the lens: criteria asking for diametral_lens and no interface
/// piece or shield edge in d (whose disks must stay empty for the union of the subdomain meshes
/// to be Delaunay). An input that has them is refined under the circle throughout: an interface
/// piece under the circle and an input segment under the lens meeting at a small angle
/// encroached each other in turn, split down to the floating-point resolution (a fuzz finding:
/// a quadrilateral's diagonal, an interface at N = 2, at 18.4 deg to a side).
inline bool uses_diametral_lens(const pslg& d, const mesh_criteria& c) {
  return c.encroachment == segment_encroachment::diametral_lens &&
         std::none_of(d.segments.begin(), d.segments.end(),
                      [](const segment& s) { return is_reserved_marker(s.marker); });
}

/// For p in the closed diametral disk of [a, b] (tested exactly before): p lies in the
/// segment's diametral lens, the angle a p b exceeding 180 - 2 theta (cosine = cos 2 theta,
/// mesh_criteria::lens_cosine). Floating point, as Triangle's test: the lens's boundary is a
/// rule, not a guarantee, and the exact disk test keeps the lens inside the disk.
inline bool in_diametral_lens(const point& a, const point& b, const point& p, double cosine) {
  if (!(cosine > 0.0)) return true; // theta >= 45 deg: the lens covers the disk
  const double ax = a.x - p.x, ay = a.y - p.y, bx = b.x - p.x, by = b.y - p.y;
  const double dot = ax * bx + ay * by;
  return dot < 0.0 && dot * dot >= cosine * cosine * (ax * ax + ay * ay) * (bx * bx + by * by);
}

} // namespace pdd::detail
