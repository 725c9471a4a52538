// The `triangle` package's functions beside triangulate: delaunay, convex_hull and voronoi (its
// return shapes and dtypes), the outputs of switches e and v as numpy arrays, and Triangle's
// warnings as Python warnings. All of them run pdd::triangle::triangulate.
#pragma once

#include "arrays.hpp"

#include <pdd/core/pslg.hpp>
#include <pdd/triangle/switches.hpp>
#include <pdd/triangle/triangulate.hpp>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace pdd::python {

/// Issues a Python UserWarning (an error when the warnings filter makes it one).
inline void warn(const std::string& message) {
  if (PyErr_WarnEx(PyExc_UserWarning, message.c_str(), 1) != 0) throw py::error_already_set();
}

/// Triangle's warning about input vertices equal to earlier ones (a vertex set): one warning
/// naming the first, with the count.
inline void warn_duplicates(const triangle::triangulation& t) {
  const auto& d = t.duplicate_vertices;
  if (d.empty()) return;
  warn("vertex " + std::to_string(d[0][0]) + " duplicates vertex " + std::to_string(d[0][1]) +
       (d.size() > 1 ? " (and " + std::to_string(d.size() - 1) + " more vertices duplicate others)"
                     : std::string()) +
       ": ignored as Triangle ignores them, no triangle uses them");
}

/// Triangle's empty mesh of a PSLG that encloses no domain: a warning saying why.
inline void warn_empty_domain(const triangle::triangulation& t) {
  if (!t.empty_domain.empty()) warn(t.empty_domain + "; the mesh has no triangles (as Triangle's)");
}

/// Switch C: raises RuntimeError with pdd::verify's messages when the check failed.
inline void raise_failed_check(const triangle::triangulation& t) {
  if (!t.check || t.check->ok()) return;
  std::string message = "the mesh check (switch C, pdd's verifier) failed:";
  for (const std::string& m : t.check->messages)
    message += "\n  " + m;
  throw std::runtime_error(message);
}

/// A new C-contiguous (rows, cols) array, element (r, c) = value(r, c).
template <class T, class F>
py::array_t<T> new_table(std::size_t rows, std::size_t cols, F value) {
  py::array_t<T> a({static_cast<py::ssize_t>(rows), static_cast<py::ssize_t>(cols)});
  auto m = a.template mutable_unchecked<2>();
  for (std::size_t r = 0; r < rows; ++r)
    for (std::size_t c = 0; c < cols; ++c)
      m(static_cast<py::ssize_t>(r), static_cast<py::ssize_t>(c)) = static_cast<T>(value(r, c));
  return a;
}

/// (n, 2) int32 endpoints of edges (segments or the edges of switch e).
inline py::array_t<std::int32_t> edge_table(const std::vector<mesh_edge>& e) {
  return new_table<std::int32_t>(
      e.size(), 2, [&e](std::size_t r, std::size_t c) { return c ? e[r].b : e[r].a; });
}

/// Switch e's keys: 'edges' (n, 2) and, with markers, 'edge_markers' (n, 1), int32.
inline void add_edges(py::dict& out, const std::vector<mesh_edge>& e, bool markers) {
  out["edges"] = edge_table(e);
  if (markers)
    out["edge_markers"] = new_table<std::int32_t>(
        e.size(), 1, [&e](std::size_t r, std::size_t) { return e[r].marker; });
}

/// The `triangle` package's voronoi tuple: vertices (t, 2) float64, finite edges (k, 2) int32,
/// ray origins (r,) int32, ray directions (r, 2) float64.
inline py::tuple voronoi_tuple(const triangle::voronoi_diagram& v) {
  std::vector<std::size_t> finite, rays;
  for (std::size_t e = 0; e < v.edges.size(); ++e)
    (v.edges[e][1] >= 0 ? finite : rays).push_back(e);
  const auto vertices = new_table<double>(v.vertices.size(), 2, [&v](std::size_t r, std::size_t c) {
    return c ? v.vertices[r].y : v.vertices[r].x;
  });
  const auto edges = new_table<std::int32_t>(
      finite.size(), 2, [&](std::size_t r, std::size_t c) { return v.edges[finite[r]][c]; });
  py::array_t<std::int32_t> origins(static_cast<py::ssize_t>(rays.size()));
  auto o = origins.mutable_unchecked<1>();
  for (std::size_t r = 0; r < rays.size(); ++r)
    o(static_cast<py::ssize_t>(r)) = static_cast<std::int32_t>(v.edges[rays[r]][0]);
  const auto directions = new_table<double>(rays.size(), 2, [&](std::size_t r, std::size_t c) {
    return c ? v.directions[rays[r]].y : v.directions[rays[r]].x;
  });
  return py::make_tuple(vertices, edges, origins, directions);
}

/// Switch v's key in pdd.triangulate's result (the `triangle` package drops Triangle's Voronoi
/// output there): 'voronoi', a dict of the four arrays of voronoi_tuple.
inline py::dict voronoi_dict(const triangle::voronoi_diagram& v) {
  const py::tuple t = voronoi_tuple(v);
  return py::dict(py::arg("vertices") = t[0], py::arg("edges") = t[1],
                  py::arg("ray_origins") = t[2], py::arg("ray_directions") = t[3]);
}

/// Triangulates the vertex set `points` ((n, 2) floats) with the switches `opts` (no p).
inline triangle::triangulation triangulate_points(const py::handle& points, const char* opts) {
  pslg g;
  g.vertices = points_of(points, "points");
  g.vertex_markers.assign(g.vertices.size(), 0);
  const triangle::switches sw = triangle::parse_switches(opts);
  triangle::triangulation t;
  {
    py::gil_scoped_release release;
    t = triangle::triangulate(std::move(g), sw);
  }
  warn_duplicates(t);
  return t;
}

/// pdd.delaunay(points): the triangles (m, 3) int32 of the Delaunay triangulation.
inline py::array_t<std::int32_t> delaunay(const py::handle& points) {
  const triangle::triangulation t = triangulate_points(points, "Qz");
  const auto& tri = t.mesh.triangles;
  return new_table<std::int32_t>(tri.size(), 3,
                                 [&tri](std::size_t r, std::size_t c) { return tri[r][c]; });
}

/// pdd.convex_hull(points): the hull's edges (k, 2) int32, counter-clockwise.
inline py::array_t<std::int32_t> convex_hull(const py::handle& points) {
  return edge_table(triangulate_points(points, "Qzc").mesh.segments);
}

/// pdd.voronoi(points): see voronoi_tuple.
inline py::tuple voronoi(const py::handle& points) {
  return voronoi_tuple(triangulate_points(points, "Qzv").voronoi);
}

/// Registers delaunay, convex_hull and voronoi in the module.
inline void def_triangle_functions(py::module_& m) {
  m.def("delaunay", &pdd::python::delaunay, py::arg("points"),
        R"(The Delaunay triangulation of points (n, 2): triangles (m, 3) int32, counter-clockwise,
as the `triangle` package's delaunay returns them (CGAL's exact predicates; no point added).
Fewer than three distinct points, or all collinear, raise ValueError; a point equal to an
earlier one is ignored with a UserWarning.)");
  m.def("convex_hull", &pdd::python::convex_hull, py::arg("points"),
        R"(The convex hull of points (n, 2): its edges (k, 2) int32, counter-clockwise, every point
on the hull's boundary a vertex (as the `triangle` package's convex_hull). Errors as delaunay.)");
  m.def("voronoi", &pdd::python::voronoi, py::arg("points"),
        R"(The Voronoi diagram of points (n, 2), as the `triangle` package's voronoi returns it:
(vertices (t, 2) float64: the circumcentre of each Delaunay triangle, edges (k, 2) int32 between
two vertices, ray_origins (r,) int32: the vertex each infinite ray starts at, ray_directions
(r, 2) float64: outward, perpendicular to a hull edge and as long as it). Errors as delaunay.)");
}

} // namespace pdd::python
