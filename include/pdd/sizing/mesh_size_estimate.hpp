/// \file mesh_size_estimate.hpp
/// pdd::estimate_mesh_size: the expected triangle count of a quality mesh of a domain under a
/// sizing field, bounded by the local feature size (dissertation Algorithm 7.2's integral of
/// 1 / (0.656 F), with F also bounded by the features), and the feature that costs the most.
#pragma once

#include <pdd/concepts/sizing_field.hpp>
#include <pdd/core/mesh_criteria.hpp>
#include <pdd/core/point.hpp>
#include <pdd/core/pslg.hpp>
#include <pdd/geometry/feature_gap.hpp>
#include <pdd/sizing/detail/mesh_size_integrator.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <string>

namespace pdd {

/// c in F_eff(x) = min(F(x), c gap(x)^2) where a vertex is one of the two features: the
/// largest triangle area a quality mesh puts where the feature gap (pdd::feature_gap_field)
/// is g. An equilateral triangle of side s has area (sqrt 3 / 4) s^2; Ruppert-type refinement
/// grades around a vertex with edges of about half the gap: (sqrt 3 / 4) / 4 = 0.11 is the
/// first guess. Calibrated on the CGAL kernel's quality-only meshes of the shared
/// geometries (lake, Texas, airfoil, guitar, letter A: benchmarks/results/estimate.md).
inline constexpr double gap_area_factor = 0.45;

/// c where the two features are segments (a corridor or a wedge between them): the kernel
/// spans such a gap with one row of triangles whose vertices lie on the two segments (angles
/// >= 20.7 deg allow it), edges about the gap: sqrt 3 / 4 = 0.43 first. Calibrated on
/// corridors and spikes (benchmarks/results/estimate.md).
inline constexpr double across_area_factor = 1.2;

/// An estimate of a mesh's size and of the feature that costs the most.
struct mesh_size_estimate {
  /// Expected triangles: the integral of 1 / (0.656 F_eff), at least the triangles of the
  /// input's constrained Delaunay triangulation (infinity: an empty domain).
  double triangles = std::numeric_limits<double>::infinity();
  /// The same with F alone (the area bound and sizing field, no features): area / (0.656 A)
  /// for a uniform bound A.
  double area_triangles = std::numeric_limits<double>::infinity();
  /// The feature pair whose bound adds the most triangles (first.id == no_index: none does).
  feature_pair cause;
  double cause_triangles = 0.0; ///< the triangles it adds
  point cause_location;         ///< where its gap is smallest relative to F
  double cause_gap = 0.0;       ///< the gap there
  double cause_bound = 0.0;     ///< F there (infinity: no area bound)
  double cause_angle_deg = 0.0; ///< the domain-side angle at the apex (small-angle cause)
  std::size_t pieces = 0;       ///< triangles integrated over (the cost)
};

/// The expected size of a quality mesh of the domain of g under min(max_area, sizing): the
/// integral of 1 / (0.656 F_eff) with F_eff = min(max_area, F, c gap^2) (c =
/// pdd::gap_area_factor, or pdd::across_area_factor across two segments; gap from
/// pdd::feature_gap_field). Each triangle of the domain's
/// constrained Delaunay triangulation is cut into n^2 similar pieces (n from `samples` as in
/// pdd::inverse_area_integral; samples = 1 for a uniform bound), then halved across its longest
/// edge where the feature bound applies and the gap varies by more than a factor 2 over a piece (at
/// most 120 halvings deep, 1M pieces in all), never below the scale of the gap's change: the
/// cost grows with the number of features and the logarithm of their scale ratios, not with
/// the mesh. Pieces in
/// the shielded corner of an angle below 60 deg count by F alone (pdd::shield's one
/// triangle); `shield_area` is the area bound the shields are built for.
/// \tparam S a SizingField. \pre g is valid. \throws pdd::geometry_error as pdd::find_loops.
/// Deterministic; an estimate, not a bound. Thread-safe.
template <SizingField S>
mesh_size_estimate estimate_mesh_size(const pslg& g, double max_area, const S& sizing,
                                      std::size_t samples = 1, double shield_area = 0.0) {
  const feature_gap_field field(g);
  mesh_size_estimate out;
  if (field.size() == 0) return out;
  detail::mesh_size_integrator<S> in(field, max_area, sizing, gap_area_factor, across_area_factor,
                                     shield_area > 0.0 ? shield_area : max_area);
  const auto n = static_cast<std::size_t>(
      std::max(1.0, std::floor(std::sqrt(static_cast<double>(samples) / field.size()))));
  double sum = 0.0;
  for (std::size_t t = 0; t < field.size(); ++t) {
    const auto& v = field.triangle(t);
    const point a = g.vertices[v[0]], b = g.vertices[v[1]], c = g.vertices[v[2]];
    const double ux = (b.x - a.x) / n, uy = (b.y - a.y) / n, vx = (c.x - a.x) / n,
                 vy = (c.y - a.y) / n;
    const auto at = [&](double i, double j) {
      return point{a.x + i * ux + j * vx, a.y + i * uy + j * vy};
    };
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t j = 0; i + j < n; ++j) {
        sum += in.top(t, at(i, j), at(i + 1, j), at(i, j + 1));
        if (i + j + 1 < n) sum += in.top(t, at(i + 1, j), at(i + 1, j + 1), at(i, j + 1));
      }
  }
  // at least the input's own triangles (a domain that is one shielded corner is one triangle)
  out.triangles = std::max(sum / mean_triangle_area_fraction, static_cast<double>(field.size()));
  if (in.area_integral > 0.0) out.area_triangles = in.area_integral / mean_triangle_area_fraction;
  out.pieces = in.pieces();
  const detail::feature_excess* worst = nullptr;
  for (const auto& entry : in.excess)
    if (!worst || entry.second.integral > worst->integral) worst = &entry.second;
  if (worst) {
    out.cause = worst->pair;
    out.cause_triangles = worst->integral / mean_triangle_area_fraction;
    out.cause_location = worst->where;
    out.cause_gap = worst->gap;
    out.cause_bound = worst->bound;
    if (worst->pair.apex != no_index) out.cause_angle_deg = field.angle_deg(worst->pair.apex);
  }
  return out;
}

} // namespace pdd
