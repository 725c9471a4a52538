/// \file write_mesh.hpp
/// pdd::write_mesh: writes a mesh in the format its file extension names.
#pragma once

#include <pdd/errors.hpp>
#include <pdd/io/msh.hpp>
#include <pdd/io/svg.hpp>
#include <pdd/io/triangle_files.hpp>
#include <pdd/io/vtu.hpp>
#include <pdd/core/triangle_mesh.hpp>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <string>

namespace pdd {

/// The extensions write_mesh understands, for messages and --help texts.
inline constexpr const char* supported_mesh_extensions = ".vtu, .msh, .node, .ele, .svg";

/// Writes the mesh in the format named by the extension of `path` (case-insensitive):
/// `.vtu` write_vtu, `.msh` write_msh (Gmsh 4.1), `.node` or `.ele` write_triangle_files
/// (`.node`, `.ele` and `.poly` siblings with the same stem), `.svg` write_svg. Each file is
/// written atomically.
/// \throws pdd::error listing the supported extensions when the extension is unknown, and as
///   the chosen writer otherwise.
/// Complexity: that of the chosen writer. Thread-safety: reentrant.
inline void write_mesh(const std::filesystem::path& path, const triangle_mesh& mesh) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char ch) { return static_cast<char>(std::tolower(ch)); });
  if (ext == ".vtu")
    write_vtu(path, mesh);
  else if (ext == ".msh")
    write_msh(path, mesh);
  else if (ext == ".node" || ext == ".ele")
    write_triangle_files(path, mesh);
  else if (ext == ".svg")
    write_svg(path, mesh);
  else
    throw error("cannot write '" + path.string() + "': unknown mesh file extension '" +
                path.extension().string() + "' (supported: " + supported_mesh_extensions + ")");
}

} // namespace pdd
