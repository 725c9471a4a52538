/// \file area_grid.hpp
/// pdd::read_area_grid: a structured-grid sizing field from a text file.
#pragma once

#include <pdd/io/detail/sizing_files.hpp>
#include <pdd/sizing/grid.hpp>

#include <filesystem>

namespace pdd {

/// Reads an area grid file (pdd's format; `#` starts a comment, blank lines are skipped):
/// ```
/// <nx> <ny> <x0> <y0> <dx> <dy>     # nodes per row and per column, origin, spacings
/// <a(0,0)> <a(1,0)> ... <a(nx-1,0)>  # row j = 0: y = y0, x = x0 + i dx
/// ...                                # ny rows in all, row j at y = y0 + j dy
/// ```
/// Every area is a finite number > 0; nx, ny >= 2; dx, dy > 0. The field interpolates
/// bilinearly (pdd::grid_sizing).
/// \throws pdd::input_error (file:line) for every malformed line; pdd::error when the file
/// cannot be read. Complexity linear.
inline grid_sizing read_area_grid(const std::filesystem::path& path) {
  detail::area_grid_data g = detail::parse_area_grid(detail::slurp_file(path), path.string());
  return {g.origin, g.dx, g.dy, g.nx, g.ny, std::move(g.values)};
}

} // namespace pdd
