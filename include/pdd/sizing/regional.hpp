/// \file regional.hpp
/// pdd::regional_sizing: the regional maximum areas of a PSLG (Triangle's .poly regions
/// section, `-a` without a number): the face of the domain holding a region point gets that
/// region's area bound.
#pragma once

#include <pdd/concepts/sizing_field.hpp>
#include <pdd/core/pslg.hpp>
#include <pdd/errors.hpp>
#include <pdd/geometry/domain_faces.hpp>
#include <pdd/sizing/background_mesh.hpp>

#include <array>
#include <cstddef>
#include <limits>
#include <map>
#include <string>
#include <vector>

namespace pdd {

namespace detail {
/// The loop whose face (its inside minus its child loops) holds region r of g.
/// \throws pdd::geometry_error naming the region when its point lies on a segment, on a
/// vertex, in a hole or outside every loop.
inline index_t region_face(const pslg& g, const domain_faces& faces, std::size_t r) {
  const point& p = g.regions[r].p;
  const face_location at = faces.locate(p);
  if (at.where == face_location::kind::inside) return at.face;
  const std::string where = "region " + std::to_string(r) + " at (" + std::to_string(p.x) + ", " +
                            std::to_string(p.y) + ")";
  if (at.where == face_location::kind::on_boundary)
    throw geometry_error(where + " lies on the domain's boundary; a region point must lie "
                                 "inside the face it constrains",
                         {r});
  throw geometry_error(where + " lies outside the domain (in a hole or outside every loop)", {r});
}
} // namespace detail

/// Models BoundedSizingField from the regions of a PSLG: every region with max_area > 0
/// bounds the face of the domain that holds its point (a face: the inside of one loop minus
/// the loops nested directly in it; pdd accepts closed, non-touching loops, so every face is
/// bounded by loops). Several regions in one face: the smallest bound wins (Triangle takes
/// the last one read). Faces without a region, and regions with max_area <= 0 (Triangle's "no
/// constraint"), give no bound (infinity); region attributes are not a sizing matter.
/// The faces are found on the PSLG's constrained Delaunay triangulation (the one pdd's loop
/// nesting uses); queries locate a triangle of it through an R-tree, as
/// pdd::background_mesh_sizing with one area per triangle, and range(box) is exact from the
/// faces' bounds (lo: the smallest bound of a face near the box).
/// Thread-safety: const and shared.
class regional_sizing {
public:
  /// \throws pdd::geometry_error as pdd::find_loops, or naming a region with max_area > 0
  /// whose point lies on a segment, in a hole or outside the domain. Complexity O(n log n)
  /// expected.
  explicit regional_sizing(const pslg& g) : field_(build(g, regions_)) {}

  /// The bound of the face that holds p (the smallest of its regions'); infinity (no bound)
  /// in a face without a bounded region and outside the domain.
  double area_at(const point& p) const { return field_.area_at(p); }
  /// Bounds over the closed box b from the faces near it (see the class comment); {infinity,
  /// infinity} when no bounded face is near.
  sizing_bounds range(const bbox& b) const { return field_.range(b); }
  /// "regional": the field's name in reports (any_sizing::kind, min_sizing::kind).
  static constexpr const char* kind() noexcept { return "regional"; }
  /// Number of regions with a bound (max_area > 0).
  std::size_t bounded_regions() const noexcept { return regions_; }

private:
  static background_mesh_sizing build(const pslg& g, std::size_t& bounded) {
    const domain_faces faces(g);
    std::map<index_t, double> bound; // face (owning loop) -> area bound
    bounded = 0;
    for (std::size_t r = 0; r < g.regions.size(); ++r) {
      if (!(g.regions[r].max_area > 0.0)) continue; // attribute only: not a sizing matter
      const index_t face = detail::region_face(g, faces, r);
      ++bounded;
      const auto [it, inserted] = bound.emplace(face, g.regions[r].max_area);
      if (!inserted) it->second = std::min(it->second, g.regions[r].max_area);
    }
    std::vector<std::array<index_t, 3>> triangles;
    std::vector<double> values;
    for (const domain_triangle& t : faces.triangles()) {
      const auto it = bound.find(t.face);
      if (it == bound.end()) continue;
      triangles.push_back(t.vertices);
      values.push_back(it->second);
    }
    return background_mesh_sizing(g.vertices, std::move(triangles), std::move(values),
                                  background_mesh_sizing::interpolation::per_triangle);
  }

  std::size_t regions_ = 0;
  background_mesh_sizing field_;
};
static_assert(BoundedSizingField<regional_sizing>);

} // namespace pdd
