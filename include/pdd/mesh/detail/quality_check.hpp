/// \file quality_check.hpp
/// Implementation of pdd::check_quality: the message that describes a triangle that fails it.
#pragma once

#include <pdd/core/mesh_criteria.hpp>
#include <pdd/core/point.hpp>
#include <pdd/core/triangle_measures.hpp>
#include <pdd/core/triangle_mesh.hpp>
#include <pdd/mesh/detail/verify_checks.hpp>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <string>

namespace pdd::detail {

/// What is wrong with triangle t (flags of detail::check_triangles), with its vertices.
inline std::string describe_bad_triangle(const triangle_mesh& m, std::size_t t, std::uint8_t f,
                                         const mesh_criteria& criteria, double area_bound) {
  const auto& tri = m.triangles[t];
  std::string s = "quality check failed: triangle " + std::to_string(t);
  if (f & tri_malformed) return s + " has bad vertex indices";
  const point& a = m.vertices[tri[0]];
  const point& b = m.vertices[tri[1]];
  const point& c = m.vertices[tri[2]];
  const auto ang = triangle_angles_deg(a, b, c);
  char buf[160];
  std::snprintf(buf, sizeof buf, ": smallest angle %.6g deg (bound %.6g), area %.6g (bound %.6g)",
                std::min({ang[0], ang[1], ang[2]}), criteria.min_angle_deg, triangle_area(a, b, c),
                area_bound);
  s += " " + pdd::to_string(a) + " " + pdd::to_string(b) + " " + pdd::to_string(c) + buf;
  if (f & tri_orientation) s += "; not counter-clockwise";
  if (f & tri_quality) s += "; below the angle bound and not a shielded triangle";
  if (f & tri_area) s += "; above the area bound";
  return s;
}

} // namespace pdd::detail
