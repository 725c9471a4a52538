/// \file encroachment.hpp
/// The encroachment rule both refinement kernels share (pdd::segment_encroachment): which
/// segments of a kernel's input take the diametral lens, and the lens test.
#pragma once

#include <pdd/core/mesh_criteria.hpp>
#include <pdd/core/point.hpp>
#include <pdd/core/pslg.hpp>
#include <pdd/core/segment_markers.hpp>

#include <cstddef>
#include <vector>

namespace pdd::detail {

/// Per segment of d: 1 where the lens rule applies (criteria asking for diametral_lens, and
/// an input segment: not an interface piece or a shield edge, whose disks must stay empty
/// for the union of the subdomain meshes to be Delaunay); empty under diametral_circle.
inline std::vector<char> lens_segments(const pslg& d, const mesh_criteria& c) {
  std::vector<char> lens;
  if (c.encroachment != segment_encroachment::diametral_lens) return lens;
  lens.resize(d.segments.size(), 0);
  for (std::size_t s = 0; s < d.segments.size(); ++s)
    lens[s] = is_reserved_marker(d.segments[s].marker) ? 0 : 1;
  return lens;
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
