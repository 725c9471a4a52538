/// \file corner_caps.hpp
/// Implementation detail of MADD on a general PSLG (issue 13): caps around the vertices where
/// an angle below 60 deg lies on a segment between two faces (an internal constraint), or a
/// segment inside a face leaves a vertex at below 60 deg to one.
///
/// Such a segment cannot be an interface: it would meet the boundary of its subdomains at an
/// angle below Phi0, the kernel's refinement of the small angle would split it, and no shield
/// fits between two faces. So every segment at such a vertex v is split at the circle of
/// radius r around v (a quarter of the distance from v to every other vertex and every segment
/// not at v), and each run of consecutive sectors of the domain at v (all of them around an
/// inner vertex) is closed by chords of that circle: the cap. Each chord spans at most
/// cap_arc_deg of arc, so it meets the segment pieces and the next chord at >= 65 deg on
/// both sides. The cap is one region that MADD never splits (madd_region::keep_whole): the
/// pieces of the segments inside it are its inner constraints, and its kernel meshes the small
/// angles at v with its clusters (as a crack at a sharp corner, detail::subdomain_small_angles
/// leaves v unshielded). Outside the caps the pieces are interfaces as before, and the chords
/// are separators between the cap and its faces, which the decoupling path splits.
#pragma once

#include <pdd/core/pslg.hpp>
#include <pdd/core/ray_order.hpp>
#include <pdd/geometry/domain_faces.hpp>
#include <pdd/madd/detail/features.hpp>
#include <pdd/madd/detail/region.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <numbers>
#include <utility>
#include <vector>

namespace pdd::detail {

/// The widest arc of the cap's circle one chord spans (degrees): its ends meet the segment
/// pieces at >= (180 - 50) / 2 = 65 deg.
inline constexpr double cap_arc_deg = 50.0;

/// A general PSLG with caps at some of its vertices.
struct capped_domain {
  /// The input with every segment at a cap's apex split on the cap's circle and the caps'
  /// chords added as segments (holes kept; no regions: they are read on the input).
  pslg g;
  /// Of each segment of g: the input segment it is a piece of, no_index for a chord.
  std::vector<index_t> input_segment;
  /// Of each cap: a point inside each of its sectors (to find their faces in g).
  std::vector<std::vector<point>> cap_samples;
  /// Of each cap: its apex and radius.
  std::vector<std::pair<point, double>> caps;
};

/// A quarter of the distance from vertex v of g to every other vertex and to every segment
/// not at v: the radius of v's cap, so that caps at two vertices stay apart and a cap holds
/// nothing but v and the segments at v. Complexity O(n).
inline double cap_radius(const pslg& g, index_t v) {
  const point p = g.vertices[v];
  double d = std::numeric_limits<double>::infinity();
  for (index_t w = 0; w < g.vertices.size(); ++w)
    if (w != v) d = std::min(d, distance(p, g.vertices[w]));
  for (const segment& s : g.segments)
    if (s.a != v && s.b != v)
      d = std::min(d, point_segment_distance(p, g.vertices[s.a], g.vertices[s.b]));
  return 0.25 * d;
}

/// One ray of a cap's apex: the segment, its far end, and its direction (radians).
struct cap_ray {
  index_t segment, far;
  double angle;
};

/// The segments at v as rays, counter-clockwise from the first (exact order).
inline std::vector<cap_ray> rays_at(const pslg& g, index_t v) {
  std::vector<cap_ray> rays;
  const point pv = g.vertices[v];
  for (index_t s = 0; s < g.segments.size(); ++s)
    if (g.segments[s].a == v || g.segments[s].b == v) {
      const index_t far = g.segments[s].a == v ? g.segments[s].b : g.segments[s].a;
      const point q = g.vertices[far];
      rays.push_back({s, far, std::atan2(q.y - pv.y, q.x - pv.x)});
    }
  if (rays.empty()) return rays;
  const point ref = g.vertices[rays.front().far];
  std::sort(rays.begin(), rays.end(), [&](const cap_ray& x, const cap_ray& y) {
    return ray_turns_before(pv, ref, g.vertices[x.far], g.vertices[y.far]);
  });
  return rays;
}

/// The counter-clockwise angle (radians, in (0, 2 pi]) of the sector from ray i to the next.
inline double sector_angle(const std::vector<cap_ray>& rays, std::size_t i) {
  if (rays.size() == 1) return 2.0 * std::numbers::pi;
  double a = rays[(i + 1) % rays.size()].angle - rays[i].angle;
  while (a <= 0.0)
    a += 2.0 * std::numbers::pi;
  return a;
}

/// The point of v's circle of radius r at `angle`.
inline point on_circle(point v, double r, double angle) {
  return {v.x + r * std::cos(angle), v.y + r * std::sin(angle)};
}

/// Builds the caps of one vertex into `out`: `split[s]` receives the point where each capped
/// segment s at v is cut (its index in out.g), and the chords go to `chords`.
struct cap_builder {
  const pslg& input;
  const domain_faces& faces;
  capped_domain& out;
  std::vector<std::pair<index_t, index_t>>& chords;
  std::vector<std::vector<std::pair<index_t, index_t>>>& split; ///< per segment: (end, cut)

  /// The point where segment s is cut at distance r from v (added once).
  index_t cut(const cap_ray& ray, index_t v, double r) {
    for (const auto& [end, c] : split[ray.segment])
      if (end == v) return c;
    const point pv = input.vertices[v], q = input.vertices[ray.far];
    const double t = r / distance(pv, q);
    const index_t c = out.g.add_vertex({pv.x + t * (q.x - pv.x), pv.y + t * (q.y - pv.y)},
                                       input.segments[ray.segment].marker);
    split[ray.segment].emplace_back(v, c);
    return c;
  }

  /// The chords of sector i (from ray i counter-clockwise to the next) from `from` to `to`.
  void sector_chords(const std::vector<cap_ray>& rays, std::size_t i, point v, double r,
                     index_t from, index_t to) {
    const double a = sector_angle(rays, i);
    const auto n = static_cast<std::size_t>(std::ceil(a / (cap_arc_deg * std::numbers::pi / 180)));
    index_t prev = from;
    for (std::size_t j = 1; j < n; ++j) {
      const index_t p = out.g.add_vertex(
          on_circle(v, r, rays[i].angle + a * static_cast<double>(j) / static_cast<double>(n)));
      chords.emplace_back(prev, p);
      prev = p;
    }
    chords.emplace_back(prev, to);
  }

  /// The caps of vertex v: one per run of two or more consecutive sectors of the domain.
  void cap(index_t v) {
    const std::vector<cap_ray> rays = rays_at(input, v);
    const point pv = input.vertices[v];
    const double r = cap_radius(input, v);
    const std::size_t n = rays.size();
    std::vector<char> inside(n);
    for (std::size_t i = 0; i < n; ++i)
      inside[i] =
          faces.locate(on_circle(pv, 0.5 * r, rays[i].angle + 0.5 * sector_angle(rays, i))).where ==
          face_location::kind::inside;
    std::size_t start = 0; // a sector whose predecessor is outside (0 when all are inside)
    while (start < n && !(inside[start] && !inside[(start + n - 1) % n]))
      ++start;
    if (start == n) start = 0;
    for (std::size_t k = 0; k < n;) {
      const std::size_t first = (start + k) % n;
      std::size_t len = 0;
      while (k + len < n && inside[(first + len) % n])
        ++len;
      k += std::max<std::size_t>(len, 1);
      if (len >= 2) add_run(rays, first, len, pv, r, v);
    }
  }

  /// The cap over sectors first .. first + len - 1 (mod the rays) of v.
  void add_run(const std::vector<cap_ray>& rays, std::size_t first, std::size_t len, point pv,
               double r, index_t v) {
    const std::size_t n = rays.size();
    out.caps.emplace_back(pv, r);
    std::vector<point>& samples = out.cap_samples.emplace_back();
    for (std::size_t j = 0; j < len; ++j) {
      const std::size_t i = (first + j) % n;
      samples.push_back(on_circle(pv, 0.5 * r, rays[i].angle + 0.5 * sector_angle(rays, i)));
      sector_chords(rays, i, pv, r, cut(rays[i], v, r), cut(rays[(i + 1) % n], v, r));
    }
  }
};

/// g with caps at `apexes` (vertices of g, each once): see the file comment. `faces` are g's.
/// Complexity O(n (c + log n)) for c caps.
inline capped_domain cap_corners(const pslg& g, const domain_faces& faces,
                                 const std::vector<index_t>& apexes) {
  capped_domain out;
  out.g.vertices = g.vertices;
  out.g.vertex_markers = g.vertex_markers;
  out.g.vertex_markers.resize(g.vertices.size(), 0);
  out.g.holes = g.holes;
  out.g.rule = g.rule;
  std::vector<std::pair<index_t, index_t>> chords;
  std::vector<std::vector<std::pair<index_t, index_t>>> split(g.segments.size());
  cap_builder b{g, faces, out, chords, split};
  for (const index_t v : apexes)
    b.cap(v);
  for (index_t s = 0; s < g.segments.size(); ++s) {
    const segment& sg = g.segments[s];
    std::vector<index_t> chain{sg.a};
    for (const index_t end : {sg.a, sg.b})
      for (const auto& [at, c] : split[s])
        if (at == end) chain.push_back(c);
    chain.push_back(sg.b);
    for (std::size_t i = 0; i + 1 < chain.size(); ++i) {
      out.g.add_segment(chain[i], chain[i + 1], sg.marker);
      out.input_segment.push_back(s);
    }
  }
  for (const auto& [a, c] : chords) {
    out.g.add_segment(a, c, 0);
    out.input_segment.push_back(no_index);
  }
  return out;
}

} // namespace pdd::detail
