/// \file previous_mesh.hpp
/// pdd::previous_mesh and pdd::read_previous_mesh: a mesh to refine, as Triangle's -r reads it
/// (`.node`, `.ele`, with p the `.poly`'s segments, with a bare a the `.area` bounds).
#pragma once

#include <pdd/core/pslg.hpp>
#include <pdd/io/detail/poly.hpp>
#include <pdd/io/detail/sizing_files.hpp>
#include <pdd/io/poly.hpp>

#include <array>
#include <filesystem>
#include <vector>

namespace pdd {

/// A mesh to refine (Triangle's -r): its vertices with their markers and attributes (and the
/// segments of a .poly read with it), its triangles, and per triangle an optional attribute and
/// an optional area bound (Triangle's .area: <= 0 means none).
struct previous_mesh {
  /// The mesh's vertices (with their markers and attributes) and, when a .poly was read, the
  /// rest of it (segments, holes, regions); no segments otherwise.
  pslg input;
  /// The triangles, as indices in input.vertices (0-based, whatever the files' first id).
  std::vector<std::array<index_t, 3>> triangles;
  std::vector<double> triangle_attributes; ///< empty, or one per triangle
  std::vector<double> triangle_areas;      ///< empty, or one per triangle
};

/// Reads `<stem>.node` and `<stem>.ele` (Triangle's formats; the .ele's ids numbered as the
/// .node's; at most one triangle attribute), with `poly` the segments of `<stem>.poly` (its
/// vertex section may be empty: the .node's vertices), with `area` the bounds of
/// `<stem>.area`. `stem` is the name without extension (`key.1`).
/// \throws pdd::input_error (file:line) for malformed files or counts that disagree, pdd::error
/// when a file cannot be read. Complexity: linear in the files' size.
inline previous_mesh read_previous_mesh(const std::string& stem, bool poly, bool area) {
  const std::string node = stem + ".node", ele = stem + ".ele";
  previous_mesh m;
  m.input = poly ? read_poly(stem + ".poly") : read_node(node);
  const detail::vertex_section vs = detail::parse_node_text(detail::slurp_file(node), node);
  m.triangles = detail::parse_ele(detail::slurp_file(ele), ele, m.input.vertices.size(),
                                  vs.first_id, &m.triangle_attributes);
  if (area)
    m.triangle_areas =
        detail::parse_area(detail::slurp_file(stem + ".area"), stem + ".area", m.triangles.size());
  return m;
}

} // namespace pdd
