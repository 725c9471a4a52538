/// \file background_mesh.hpp
/// pdd::read_background_mesh: a background-mesh sizing field from Triangle's files.
#pragma once

#include <pdd/io/detail/sizing_files.hpp>
#include <pdd/sizing/background_mesh.hpp>

#include <filesystem>
#include <string>

namespace pdd {

/// Reads a background mesh from `<stem>.node` (the path given) and `<stem>.ele`, with the
/// area bounds either
///  - in the .node file as its one vertex attribute (the area at the vertex, > 0): linear
///    interpolation in each triangle; or
///  - in a sibling `<stem>.area` file, Triangle's format (`<#triangles>`, then
///    `<id> <maximum area>`, <= 0: no constraint): one area per triangle, piecewise constant.
/// Exactly one of the two must be present. .node and .ele follow Triangle's formats (ids from
/// 0 or 1, the .node's first id decides, markers allowed, .ele attributes read and dropped).
/// \throws pdd::input_error (file:line) for malformed files, both or neither kind of areas,
/// or a count mismatch; pdd::error when a file cannot be read; pdd::sizing_error for a
/// degenerate triangle (naming it, 0-based). Complexity O(n log n).
inline background_mesh_sizing read_background_mesh(const std::filesystem::path& node_path) {
  namespace fs = std::filesystem;
  const std::string node_file = node_path.string();
  const detail::node_with_areas nodes =
      detail::parse_area_node(detail::slurp_file(node_path), node_file);
  fs::path ele = node_path, area = node_path;
  ele.replace_extension(".ele");
  area.replace_extension(".area");
  auto tris = detail::parse_ele(detail::slurp_file(ele), ele.string(), nodes.vertices.size(),
                                nodes.first_id);
  std::error_code ec;
  const bool has_area_file = fs::is_regular_file(area, ec);
  if (has_area_file && !nodes.areas.empty())
    throw input_error(node_file, 1,
                      "the vertices have an area attribute and '" + area.string() +
                          "' exists too: give the areas one way (per vertex or per triangle)");
  if (!has_area_file && nodes.areas.empty())
    throw input_error(node_file, 1,
                      "expected the area at each vertex as the one vertex attribute, or a "
                      "sibling '" +
                          area.string() + "' with one area per triangle");
  if (has_area_file) {
    std::vector<double> a =
        detail::parse_area(detail::slurp_file(area), area.string(), tris.size());
    return {nodes.vertices, std::move(tris), std::move(a),
            background_mesh_sizing::interpolation::per_triangle};
  }
  return {nodes.vertices, std::move(tris), nodes.areas,
          background_mesh_sizing::interpolation::per_vertex};
}

} // namespace pdd
