/// \file weight_files.hpp
/// pdd::read_node_weights and pdd::read_weight_grid: the density weights of a graded MADD
/// (dissertation 4.4, cases 2 and 3) from files.
#pragma once

#include <pdd/io/detail/sizing_files.hpp>
#include <pdd/madd/graded_weights.hpp>

#include <filesystem>
#include <utility>

namespace pdd {

/// Reads weighted points from a Triangle .node file whose one vertex attribute is the density
/// weight of the point (finite, >= 0): e.g. the vertices of a previous mesh (4.4, case 2).
/// Ids from 0 or 1 (the first decides), markers allowed.
/// \throws pdd::input_error (file:line) for a malformed file, a missing or extra attribute or
/// a negative weight; pdd::error when the file cannot be read. Complexity O(n).
inline point_weights read_node_weights(const std::filesystem::path& path) {
  detail::node_with_areas n =
      detail::parse_area_node(detail::slurp_file(path), path.string(), detail::node_value::weight);
  return {std::move(n.vertices), std::move(n.areas)};
}

/// Reads a density-weight grid (4.4, case 3) in the format of pdd::read_area_grid, with
/// weights (finite, >= 0) instead of areas: the header `<nx> <ny> <x0> <y0> <dx> <dy>`, then
/// ny rows of nx weights, row j at y = y0 + j dy. Each grid node is a weighted point.
/// \throws pdd::input_error (file:line) for every malformed line or negative weight;
/// pdd::error when the file cannot be read. Complexity O(nx ny).
inline point_weights read_weight_grid(const std::filesystem::path& path) {
  const detail::area_grid_data g =
      detail::parse_area_grid(detail::slurp_file(path), path.string(), detail::node_value::weight);
  std::size_t k = 0;
  return point_weights::on_grid(g.origin, g.dx, g.dy, g.nx, g.ny,
                                [&](const point&) { return g.values[k++]; });
}

} // namespace pdd
