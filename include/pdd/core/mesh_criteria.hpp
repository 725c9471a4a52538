/// \file mesh_criteria.hpp
/// pdd::mesh_criteria: the quality and size bounds every kernel and pipeline takes.
#pragma once

#include <cmath>
#include <limits>
#include <numbers>

namespace pdd {

/// The minimum angle, in degrees, that corresponds to a circumradius-to-shortest-edge ratio
/// bound B: sin(theta_min) = 1 / (2 B). For B = sqrt 2 this is 20.7048... degrees.
inline double min_angle_for_ratio(double ratio) {
  return std::asin(1.0 / (2.0 * ratio)) * 180.0 / std::numbers::pi;
}
/// The circumradius-to-shortest-edge ratio that corresponds to a minimum angle in degrees.
inline double ratio_for_min_angle(double min_angle_deg) {
  return 1.0 / (2.0 * std::sin(min_angle_deg * std::numbers::pi / 180.0));
}

/// Whether an angle bound is at most Ruppert's (circumradius-to-shortest-edge ratio at least
/// sqrt 2, 20.7048 deg): the bound under which the decoupling theorems hold, the shields of
/// small input angles (Theorem 24 (5): no shield edge is split) and the invariance of the
/// decoupling path among them. Above it the kernels did split both (Triangle's Texas and the
/// Bahamas at 31-33 deg, CGAL's kernel then refining without end beside a shield), so pdd
/// meshes small input angles there with the kernel's own rule and decouples only domains that
/// have none (pipeline's plan).
inline bool within_ruppert_bound(double min_angle_deg) {
  return !(ratio_for_min_angle(min_angle_deg) < std::numbers::sqrt2 * (1.0 - 1e-12));
}

/// When a vertex encroaches an input segment (splits it instead of being inserted).
enum class segment_encroachment {
  /// In the segment's closed diametral disk (Ruppert's rule): every edge of the result is
  /// locally Delaunay, input segments included (a conforming Delaunay mesh; Triangle's -D).
  diametral_circle,
  /// In its diametral lens, the part of the disk seen from the segment at an angle above
  /// 180 - 2 min_angle_deg (Chew's rule, Triangle's default for -q without -D): fewer segment
  /// splits, so meshes of Triangle's size when no area bound is asked for; the result is
  /// constrained Delaunay (an edge on an input segment may not be locally Delaunay, every other
  /// edge is). A kernel input with interface pieces or shield edges (the subdomains of a
  /// decoupled run, a shielded domain) is refined under the circle throughout, so that the
  /// union of the subdomain meshes stays Delaunay across them.
  diametral_lens,
};

/// Quality criteria for Delaunay refinement.
struct mesh_criteria {
  /// Smallest angle allowed in a triangle, degrees (default: ratio sqrt 2, 20.7048 deg).
  /// Ruppert-type refinement is guaranteed to terminate for <= 20.7 deg with input angles
  /// >= 60 deg; CGAL's mesher usually terminates up to about 33 deg.
  double min_angle_deg = min_angle_for_ratio(std::numbers::sqrt2);
  /// Uniform upper bound on triangle area; infinity means none. A SizingField given next to
  /// the criteria is combined with it (the smaller bound wins).
  double max_area = std::numeric_limits<double>::infinity();
  /// Which vertices encroach an input segment (segment_encroachment); pdd::verify checks the
  /// Delaunay property of the edges on input segments only under diametral_circle.
  segment_encroachment encroachment = segment_encroachment::diametral_circle;

  /// The circumradius-to-shortest-edge bound B that min_angle_deg stands for.
  double ratio_bound() const { return ratio_for_min_angle(min_angle_deg); }
  /// pdd::within_ruppert_bound(min_angle_deg).
  bool within_ruppert_bound() const { return pdd::within_ruppert_bound(min_angle_deg); }
  /// CGAL's shape bound: sin^2 of the minimum angle (0.125 for 20.7 deg).
  double shape_bound() const {
    const double s = std::sin(min_angle_deg * std::numbers::pi / 180.0);
    return s * s;
  }
  /// cos(2 min_angle_deg): a point p strictly inside the diametral disk of [a, b] is inside its
  /// lens when (a - p).(b - p) < -lens_cosine() |a - p| |b - p| (the angle a p b exceeds
  /// 180 - 2 min_angle_deg).
  double lens_cosine() const { return std::cos(2.0 * min_angle_deg * std::numbers::pi / 180.0); }
};

/// Mean triangle area of a quality mesh under a uniform area bound A, as a fraction of A
/// (CGAL's kernel, 20.7 deg, measured on squares from 19K to 4M triangles: 0.655-0.659).
inline constexpr double mean_triangle_area_fraction = 0.656;

} // namespace pdd
