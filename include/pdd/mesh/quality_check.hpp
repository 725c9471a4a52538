/// \file quality_check.hpp
/// pdd::check_quality and pdd::quality_check_sink: the always-on O(n) check of a finished mesh
/// against the promise of the method (every triangle outside a shielded corner meets the angle
/// bound and the area bound, dissertation Theorem 24 (1)), so that a bad mesh is an error and
/// never written silently. pdd::verify remains the full (optional) check.
#pragma once

#include <pdd/concepts/mesh_sink.hpp>
#include <pdd/concepts/sizing_field.hpp>
#include <pdd/core/mesh_criteria.hpp>
#include <pdd/core/pslg.hpp>
#include <pdd/core/triangle_mesh.hpp>
#include <pdd/errors.hpp>
#include <pdd/geometry/validate.hpp>
#include <pdd/mesh/detail/quality_check.hpp>
#include <pdd/mesh/quality_exemptions.hpp>
#include <pdd/mesh/verify.hpp>
#include <pdd/shielding/shield_statistics.hpp>
#include <pdd/sizing/uniform.hpp>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

namespace pdd {

namespace detail {
/// check_quality with the exempt triangles given (verify_options::quality_exempt).
template <SizingField S>
void check_quality_exempt(const triangle_mesh& m, std::vector<char> exempt,
                          const mesh_criteria& criteria, const S& sizing, long long subdomain) {
  verify_options vo{.criteria = criteria};
  vo.quality_exempt = std::move(exempt);
  const auto bound_at = [&](const point& p) { return static_cast<double>(sizing.area_at(p)); };
  const std::vector<std::uint8_t> flags = detail::check_triangles(m, vo, bound_at);
  const auto bad = std::find_if(flags.begin(), flags.end(), [](std::uint8_t f) { return f != 0; });
  if (bad == flags.end()) return;
  const auto t = static_cast<std::size_t>(bad - flags.begin());
  const long long id = subdomain >= 0                  ? subdomain
                       : t < m.triangle_markers.size() ? m.triangle_markers[t]
                                                       : 0;
  double bound = criteria.max_area;
  if (!(*bad & detail::tri_malformed)) {
    const auto& tri = m.triangles[t];
    bound = std::min(bound, bound_at(detail::triangle_centroid(
                                m.vertices[tri[0]], m.vertices[tri[1]], m.vertices[tri[2]])));
  }
  throw meshing_error(id, detail::describe_bad_triangle(m, t, *bad, criteria, bound));
}
} // namespace detail

/// Checks every triangle of m: vertex indices, counter-clockwise orientation, the area bound
/// min(criteria.max_area, sizing at the centroid) and, unless it is a shielded triangle of
/// the domain (pdd::find_shielded_triangles of its small input angles `angles`), the angle bound
/// criteria.min_angle_deg; with the
/// tolerances of pdd::verify (1e-9 deg, relative 1e-12 of the area).
/// \param subdomain the id to report; -1: the triangle's marker (the subdomain id in a merged
///   mesh of pdd::generate), 0 without markers.
/// \throws pdd::meshing_error(subdomain, ...) naming the first bad triangle: its index in m,
///   its vertices' coordinates, its smallest angle and area. A bad triangle is an internal
///   error (the kernel broke its guarantee), never a property of the input.
/// Complexity O(T log s) for T triangles and s small input angles, parallel. Thread-safe.
template <SizingField S = uniform_sizing>
void check_quality(const triangle_mesh& m, const small_input_angles& angles,
                   const mesh_criteria& criteria, const S& sizing = {}, long long subdomain = -1) {
  detail::check_quality_exempt(m, find_shielded_triangles(m, angles), criteria, sizing, subdomain);
}

/// check_quality with pdd's one rule for the triangles exempt from the angle bound
/// (pdd::quality_exemptions of `domain`, as meshed: the shielded triangles of its small input
/// angles on closed loops; on a domain of domain_rule::triangle that is not one of closed loops,
/// meshed unshielded, the cluster triangles at small angles between segments).
/// \throws geometry_error as validate(), pdd::meshing_error as above.
template <SizingField S = uniform_sizing>
void check_quality(const triangle_mesh& m, const pslg& domain, const mesh_criteria& criteria,
                   const S& sizing = {}, long long subdomain = -1) {
  detail::check_quality_exempt(m, quality_exemptions(domain)(m, criteria.min_angle_deg), criteria,
                               sizing, subdomain);
}

/// A MeshSink decorator that runs check_quality on every subdomain mesh before handing it to
/// the inner sink: a bad subdomain mesh throws (pdd::meshing_error with its id) and never
/// reaches the inner sink, and the inner sink's finish() (e.g. the .pvtu index of a
/// vtu_directory_sink, written last) is never reached either.
/// \tparam Inner a MeshSink. \tparam S a SizingField.
/// Thread-safety: consume() may run concurrently (as the inner sink's); `inner` must outlive
/// the sink (the domain's small input angles are found once, in the constructor).
template <MeshSink Inner, SizingField S = uniform_sizing>
class quality_check_sink {
public:
  /// The inner sink's: this decorator keeps no mesh itself.
  static constexpr bool retains_meshes = sink_retains_meshes<Inner>;

  /// Checks every mesh against `criteria` (angle bound, area bound) and `sizing`, with the
  /// quality exemptions of `domain` (found here, once); meshes that pass go to `inner`.
  /// \throws geometry_error as validate() for an invalid `domain`.
  quality_check_sink(Inner& inner, const pslg& domain, mesh_criteria criteria, S sizing = {})
      : inner_(inner), exemptions_(domain), criteria_(criteria), sizing_(std::move(sizing)) {}

  /// Passes start(n) on to the inner sink when it has one.
  void start(index_t n) {
    if constexpr (requires { inner_.start(n); }) inner_.start(n);
  }
  /// Checks the mesh (\throws as check_quality, with id), then hands it on.
  void consume(index_t id, triangle_mesh&& mesh) {
    detail::check_quality_exempt(mesh, exemptions_(mesh, criteria_.min_angle_deg), criteria_,
                                 sizing_, static_cast<long long>(id));
    inner_.consume(id, std::move(mesh));
  }
  /// Calls the inner sink's finish() (not reached once a consume has thrown).
  void finish() { inner_.finish(); }

private:
  Inner& inner_;
  quality_exemptions exemptions_; ///< the domain's, found once (not per subdomain)
  mesh_criteria criteria_;
  S sizing_;
};

} // namespace pdd
