/// \file sizing_files.hpp
/// Implementation of pdd::read_background_mesh and pdd::read_area_grid: strict parsers of a
/// .node with an area attribute, a .ele, a Triangle .area file and pdd's area grid format.
#pragma once

#include <pdd/core/point.hpp>
#include <pdd/errors.hpp>
#include <pdd/io/detail/poly.hpp>

#include <array>
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace pdd::detail {

/// A .node file's vertices and the first attribute of each (empty when it has none).
struct node_with_areas {
  std::vector<point> vertices;
  std::vector<double> areas;
  long long first_id = 1;
};

/// What the one vertex attribute of a .node file means.
enum class node_value { area, weight };

/// Reads a .node file keeping the first vertex attribute as the area at the vertex (> 0;
/// optional) or as a density weight (>= 0, finite; required).
/// \throws pdd::input_error (file:line) as the .poly reader, and for more than one attribute.
inline node_with_areas parse_area_node(std::string_view text, const std::string& file,
                                       node_value kind = node_value::area) {
  triangle_file_parser p(text, file);
  const vertex_header h = p.vertex_section_header();
  const bool area = kind == node_value::area;
  if (h.count == 0) p.fail("expected at least one vertex in the .node file, found 0");
  if (h.attributes > 1 || (!area && h.attributes != 1))
    p.fail(std::string("expected ") + (area ? "at most" : "exactly") + " 1 vertex attribute (the " +
           (area ? "area at" : "density weight of") + " the vertex), found " +
           std::to_string(h.attributes));
  node_with_areas r;
  const std::size_t nf = 3 + h.attributes + h.markers;
  for (std::size_t i = 0; i < h.count; ++i) {
    const auto rec = [&] {
      return "vertex " + std::to_string(i + 1) + " of " + std::to_string(h.count) +
             " '<id> <x> <y>" + (h.attributes ? (area ? " <area>" : " <weight>") : "") +
             (h.markers ? " <marker>" : "") + "'";
    };
    p.next(rec);
    p.expect_fields(nf, nf, rec);
    const long long id = p.integer(0, "the vertex id");
    if (i == 0 && id != 0 && id != 1)
      p.fail("expected the first vertex id to be 0 or 1, found " + std::to_string(id));
    if (i == 0) r.first_id = id;
    if (id != r.first_id + static_cast<long long>(i))
      p.fail("expected vertex id " + std::to_string(r.first_id + static_cast<long long>(i)) +
             " (ids must be consecutive), found " + std::to_string(id));
    r.vertices.push_back(
        {p.real(1, "the vertex x coordinate"), p.real(2, "the vertex y coordinate")});
    if (h.attributes == 1) {
      const double a = p.real(3, area ? "the area at the vertex" : "the vertex weight");
      if (area && !(a > 0.0))
        p.fail("expected the area at the vertex to be > 0, found " + std::to_string(a));
      if (!area && !(a >= 0.0))
        p.fail("expected the vertex weight to be >= 0, found " + std::to_string(a));
      r.areas.push_back(a);
    }
    if (h.markers) (void)p.marker(3 + h.attributes, "the vertex boundary marker");
  }
  return r;
}

/// Reads a .ele file of 3-node triangles over `nv` vertices numbered from `first_id`.
/// With `attributes`, the one attribute column of every triangle goes there (none: empty; more
/// than one is refused); without, attributes are read and dropped.
inline std::vector<std::array<index_t, 3>> parse_ele(std::string_view text, const std::string& file,
                                                     std::size_t nv, long long first_id,
                                                     std::vector<double>* attributes = nullptr) {
  triangle_file_parser p(text, file);
  const auto header = [] { return "the triangle header '<#triangles> 3 <#attributes>'"; };
  p.next(header);
  p.expect_fields(3, 3, header);
  const std::size_t nt = p.count(0, "the number of triangles");
  if (p.integer(1, "the number of nodes per triangle") != 3)
    p.fail("expected 3 nodes per triangle (linear triangles)");
  const std::size_t na = p.count(2, "the number of triangle attributes");
  p.check_fits(nt, "the number of triangles");
  p.check_fits(na, "the number of triangle attributes");
  if (attributes && na > 1)
    p.fail("expected at most one triangle attribute (pdd carries one attribute per triangle), "
           "found " +
           std::to_string(na));
  std::vector<std::array<index_t, 3>> ts;
  ts.reserve(nt);
  const long long hi = first_id + static_cast<long long>(nv) - 1;
  for (std::size_t i = 0; i < nt; ++i) {
    const auto rec = [&] {
      return "triangle " + std::to_string(i + 1) + " of " + std::to_string(nt) +
             " '<id> <v1> <v2> <v3>" + (na ? " <attributes>'" : "'");
    };
    p.next(rec);
    p.expect_fields(4 + na, 4 + na, rec);
    (void)p.integer(0, "the triangle id");
    std::array<index_t, 3> t{};
    for (std::size_t k = 0; k < 3; ++k) {
      const long long v = p.integer(1 + k, "a triangle vertex id");
      if (v < first_id || v > hi)
        p.fail("expected a triangle vertex id in [" + std::to_string(first_id) + ", " +
               std::to_string(hi) + "], found " + std::to_string(v));
      t[k] = static_cast<index_t>(v - first_id);
    }
    for (std::size_t a = 0; a < na; ++a) {
      const double value = p.real(4 + a, "a triangle attribute");
      if (attributes) attributes->push_back(value);
    }
    ts.push_back(t);
  }
  return ts;
}

/// Reads a Triangle .area file: `<#triangles>`, then `<id> <maximum area>` per triangle
/// (<= 0: no constraint); the count must equal `nt`.
inline std::vector<double> parse_area(std::string_view text, const std::string& file,
                                      std::size_t nt) {
  triangle_file_parser p(text, file);
  const auto header = [] { return "the area header '<#triangles>'"; };
  p.next(header);
  p.expect_fields(1, 1, header);
  const std::size_t n = p.count(0, "the number of triangles");
  if (n != nt)
    p.fail("expected " + std::to_string(nt) + " triangles (as in the .ele file), found " +
           std::to_string(n));
  std::vector<double> a;
  a.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    const auto rec = [&] {
      return "triangle " + std::to_string(i + 1) + " of " + std::to_string(n) +
             " '<id> <maximum area>'";
    };
    p.next(rec);
    p.expect_fields(2, 2, rec);
    (void)p.integer(0, "the triangle id");
    a.push_back(p.real(1, "the maximum area"));
  }
  if (p.try_next()) p.fail("expected the end of the file after " + std::to_string(n) + " areas");
  return a;
}

/// An area grid as read from a file.
struct area_grid_data {
  point origin;
  double dx = 0.0, dy = 0.0;
  std::size_t nx = 0, ny = 0;
  std::vector<double> values;
};

/// Parses pdd's area grid format (see pdd::read_area_grid); with node_value::weight the
/// values are density weights (>= 0) instead of areas (> 0).
inline area_grid_data parse_area_grid(std::string_view text, const std::string& file,
                                      node_value kind = node_value::area) {
  const bool area = kind == node_value::area;
  triangle_file_parser p(text, file);
  const auto header = [] { return "the grid header '<nx> <ny> <x0> <y0> <dx> <dy>'"; };
  p.next(header);
  p.expect_fields(6, 6, header);
  area_grid_data g;
  g.nx = p.count(0, "nx, the number of nodes along x");
  g.ny = p.count(1, "ny, the number of nodes along y");
  if (g.nx < 2 || g.ny < 2) p.fail("expected at least 2 x 2 nodes");
  g.origin = {p.real(2, "x0"), p.real(3, "y0")};
  g.dx = p.real(4, "dx");
  g.dy = p.real(5, "dy");
  if (!(g.dx > 0.0 && g.dy > 0.0)) p.fail("expected the spacings dx and dy to be > 0");
  p.check_fits(g.ny, "ny rows");
  p.check_fits(g.nx, "nx values per row");
  g.values.reserve(g.nx * g.ny);
  for (std::size_t j = 0; j < g.ny; ++j) {
    const auto rec = [&] {
      return "row " + std::to_string(j + 1) + " of " + std::to_string(g.ny) + " (y = y0 + " +
             std::to_string(j) + " dy, " + std::to_string(g.nx) + (area ? " areas)" : " weights)");
    };
    p.next(rec);
    p.expect_fields(g.nx, g.nx, rec);
    for (std::size_t i = 0; i < g.nx; ++i) {
      const double a = p.real(i, area ? "an area" : "a weight");
      if (area ? !(a > 0.0) : !(a >= 0.0))
        p.fail(std::string("expected the ") + (area ? "area" : "weight") + " at node (" +
               std::to_string(i) + ", " + std::to_string(j) + ") to be " + (area ? "> 0" : ">= 0") +
               ", found " + std::to_string(a));
      g.values.push_back(a);
    }
  }
  if (p.try_next()) p.fail("expected the end of the file after " + std::to_string(g.ny) + " rows");
  return g;
}

} // namespace pdd::detail
