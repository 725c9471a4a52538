/// \file mesher_input.hpp
/// What both Delaunay refinement kernels (kernels/cgal, kernels/native) do with their input
/// alike: the input checks, the spatially sorted insertion order of the input vertices, and
/// the lookup of an input segment by its endpoints.
#pragma once

#include <pdd/core/index.hpp>
#include <pdd/core/kernel.hpp>
#include <pdd/core/mesh_criteria.hpp>
#include <pdd/core/pslg.hpp>
#include <pdd/errors.hpp>

#include <CGAL/Spatial_sort_traits_adapter_2.h>
#include <CGAL/property_map.h>
#include <CGAL/spatial_sort.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <numeric>
#include <string>
#include <utility>
#include <vector>

namespace pdd::detail {

/// \throws meshing_error (subdomain -1) for vertex markers of the wrong size or criteria a
/// Ruppert-type kernel cannot meet (min angle outside [0, 60), max_area not positive).
inline void check_mesher_input(const pslg& d, const mesh_criteria& c) {
  if (!d.vertex_markers.empty() && d.vertex_markers.size() != d.vertices.size())
    throw meshing_error(-1, "vertex_markers has " + std::to_string(d.vertex_markers.size()) +
                                " entries for " + std::to_string(d.vertices.size()) + " vertices");
  if (!(c.min_angle_deg >= 0.0 && c.min_angle_deg < 60.0))
    throw meshing_error(-1, "min_angle_deg must lie in [0, 60), got " +
                                std::to_string(c.min_angle_deg));
  if (!(c.max_area > 0.0))
    throw meshing_error(-1, "max_area must be > 0, got " + std::to_string(c.max_area));
}

/// The input vertices as CGAL points and their insertion order along CGAL's Hilbert
/// spatial_sort (deterministic: a function of the coordinates alone).
struct spatial_insertion {
  std::vector<epick::Point_2> points;
  std::vector<std::size_t> order;
};

/// \throws meshing_error for a non-finite coordinate or more vertices than max_vertices.
inline spatial_insertion spatial_insertion_order(const pslg& d, std::size_t max_vertices) {
  const std::size_t n = d.vertices.size();
  if (n >= max_vertices) throw meshing_error(-1, "too many vertices");
  spatial_insertion s;
  s.points.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    const point& p = d.vertices[i];
    if (!std::isfinite(p.x) || !std::isfinite(p.y))
      throw meshing_error(-1, "vertex " + std::to_string(i) + " has a non-finite coordinate");
    s.points.emplace_back(p.x, p.y);
  }
  s.order.resize(n);
  std::iota(s.order.begin(), s.order.end(), std::size_t{0});
  using map = CGAL::Pointer_property_map<epick::Point_2>::type;
  CGAL::spatial_sort(
      s.order.begin(), s.order.end(),
      CGAL::Spatial_sort_traits_adapter_2<epick, map>(CGAL::make_property_map(s.points)));
  return s;
}

/// Finds the index of the input segment with endpoints {a, b} (sorted table lookup).
class segment_table {
public:
  explicit segment_table(const pslg& d) {
    keys_.reserve(d.segments.size());
    for (std::size_t s = 0; s < d.segments.size(); ++s)
      keys_.push_back({key(d.segments[s].a, d.segments[s].b), static_cast<index_t>(s)});
    std::stable_sort(keys_.begin(), keys_.end(),
                     [](const auto& x, const auto& y) { return x.first < y.first; });
  }
  /// The first segment with endpoints {a, b}; no_index if there is none.
  index_t find(index_t a, index_t b) const {
    const std::uint64_t k = key(a, b);
    const auto it = std::lower_bound(keys_.begin(), keys_.end(), k,
                                     [](const auto& x, std::uint64_t v) { return x.first < v; });
    return it != keys_.end() && it->first == k ? it->second : no_index;
  }

private:
  static std::uint64_t key(index_t a, index_t b) {
    return static_cast<std::uint64_t>(std::min(a, b)) << 32 | std::max(a, b);
  }
  std::vector<std::pair<std::uint64_t, index_t>> keys_;
};

} // namespace pdd::detail
