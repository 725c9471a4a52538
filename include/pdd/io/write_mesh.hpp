/// \file write_mesh.hpp
/// pdd::write_mesh: writes a mesh in the format its file extension names.
#pragma once

#include <pdd/core/triangle_mesh.hpp>
#include <pdd/errors.hpp>
#include <pdd/io/msh.hpp>
#include <pdd/io/svg.hpp>
#include <pdd/io/triangle_files.hpp>
#include <pdd/io/vtu.hpp>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <span>
#include <string>

namespace pdd {

/// The extensions write_mesh understands, for messages and --help texts.
inline constexpr const char* supported_mesh_extensions = ".vtu, .msh, .node, .ele, .svg";

/// Writes the mesh in the format named by the extension of `path` (case-insensitive):
/// `.vtu` write_vtu, `.msh` write_msh (Gmsh 4.1), `.node` or `.ele` write_triangle_files
/// (`.node`, `.ele` and `.poly` siblings with the same stem), `.svg` write_svg. Each file is
/// written atomically. `region_attributes` (empty: none; else one per triangle, from
/// pdd::region_attributes) go with the mesh: the .vtu's cell data "region_attribute", the
/// .msh's physical tags (integers), the .ele's attribute column; an .svg cannot show them.
/// \throws pdd::error listing the supported extensions when the extension is unknown, naming
///   the path for region attributes with an .svg, and as the chosen writer otherwise.
/// Complexity: that of the chosen writer. Thread-safety: reentrant.
inline void write_mesh(const std::filesystem::path& path, const triangle_mesh& mesh,
                       std::span<const double> region_attributes = {}) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char ch) { return static_cast<char>(std::tolower(ch)); });
  if (ext == ".vtu")
    write_vtu(path, mesh, region_attributes);
  else if (ext == ".msh")
    write_msh(path, mesh, region_attributes);
  else if (ext == ".node" || ext == ".ele")
    write_triangle_files(path, mesh, region_attributes);
  else if (ext == ".svg" && region_attributes.empty())
    write_svg(path, mesh);
  else if (ext == ".svg")
    throw error("cannot write '" + path.string() +
                "': an .svg picture does not carry region attributes (write .vtu, .msh or .ele)");
  else
    throw error("cannot write '" + path.string() + "': unknown mesh file extension '" +
                path.extension().string() + "' (supported: " + supported_mesh_extensions + ")");
}

} // namespace pdd
