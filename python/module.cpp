// The `pdd` Python module: pdd.triangulate (the `triangle` package's call, through pdd's
// Triangle switch parser), pdd.mesh (keywords, numpy arrays, statistics as a dict) and pdd.verify
// (pdd::verify with its defaults).
#include "arrays.hpp"
#include "sizing.hpp"
#include "triangle_functions.hpp"

#include <pdd/errors.hpp>
#include <pdd/generate.hpp>
#include <pdd/geometry/validate.hpp>
#include <pdd/kernels/default_mesher.hpp>
// the kernel with python::grid_sizing (libpdd holds it for pdd::any_sizing and uniform_sizing)
#ifdef PDD_PERMISSIVE
#include <pdd/kernels/native/mesher_templates.hpp>
#else
#include <pdd/kernels/cgal/mesher_templates.hpp>
#endif
#include <pdd/mesh/quality.hpp>
#include <pdd/mesh/verify.hpp>
#include <pdd/shielding/apply_shields.hpp>
#include <pdd/shielding/shield.hpp>
#include <pdd/triangle/switches.hpp>
#include <pdd/triangle/triangulate.hpp>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <limits>
#include <memory>
#include <optional>
#include <set>
#include <string>

namespace py = pybind11;
using namespace pybind11::literals;

namespace pdd::python {
namespace {

/// The kernel pdd.mesh meshes with: CGAL's Mesh_2, or the native kernel in a PDD_PERMISSIVE
/// build (no GPL code).
#ifdef PDD_PERMISSIVE
const std::string kernel_name = "native";
#else
const std::string kernel_name = "cgal";
#endif

/// The triangle package's input dict as a pslg; unknown and unsupported keys are refused.
pslg pslg_from_dict(const py::dict& tri) {
  static const std::set<std::string> known{"vertices", "vertex_markers",  "vertex_attributes",
                                           "segments", "segment_markers", "holes",
                                           "regions"};
  for (const auto& item : tri) {
    const auto key = py::str(item.first).cast<std::string>();
    if (key == "triangles" || key == "triangle_max_area" || key == "triangle_attributes")
      continue; // the previous mesh of switch r (previous_from_dict)
    if (!known.count(key)) throw bad_argument("unknown key '" + key + "' in the input dict");
  }
  if (!tri.contains("vertices")) throw bad_argument("the input dict needs 'vertices'");
  pslg g;
  g.vertices = points_of(tri["vertices"], "vertices");
  g.vertex_markers = tri.contains("vertex_markers")
                         ? markers_of(tri["vertex_markers"], g.vertices.size(), "vertex_markers")
                         : std::vector<int>(g.vertices.size(), 0);
  if (tri.contains("vertex_attributes") && py::len(tri["vertex_attributes"]) > 0)
    read_vertex_attributes(g, tri["vertex_attributes"]);
  if (tri.contains("segments"))
    add_segments(g, tri["segments"],
                 tri.contains("segment_markers") ? py::handle(tri["segment_markers"])
                                                 : py::handle(py::none()));
  else if (tri.contains("segment_markers"))
    throw bad_argument("'segment_markers' without 'segments'");
  if (tri.contains("holes")) g.holes = points_of(tri["holes"], "holes");
  if (tri.contains("regions")) {
    const auto r = as_table<double>(tri["regions"], 4, "regions (x, y, attribute, max_area)");
    for (py::ssize_t i = 0; i < r.shape(0); ++i)
      g.regions.push_back({{r.at(i, 0), r.at(i, 1)}, r.at(i, 2), r.at(i, 3)});
  }
  return g;
}

/// Without p Triangle reads only the vertices, without r no previous mesh: say so when the
/// dict holds more.
void warn_unread_keys(const py::dict& tri, const triangle::switches& sw) {
  if (!sw.refine)
    for (const char* key : {"triangles", "triangle_max_area", "triangle_attributes"})
      if (tri.contains(key) && py::len(tri[key]) > 0)
        warn(std::string("'") + key +
             "' are not read without switch r (refine a previous mesh), as in Triangle");
  if (sw.poly || sw.refine) return;
  for (const char* key : {"segments", "holes", "regions"})
    if (tri.contains(key) && py::len(tri[key]) > 0)
      warn(std::string("'") + key +
           "' are not read without switch p: the vertices are triangulated (as Triangle does)");
}

/// One value per triangle from an (n,) or (n, 1) array (`what` names it in errors).
std::vector<double> per_triangle(const py::handle& obj, std::size_t n, const std::string& what) {
  const auto a = as_table<double>(obj, 1, what);
  if (static_cast<std::size_t>(a.shape(0)) != n)
    throw bad_argument(what + " has " + std::to_string(a.shape(0)) + " rows for " +
                       std::to_string(n) + " triangles");
  return {a.data(), a.data() + n};
}

/// Switch r: the previous mesh of the dict (its triangles, and with them triangle_max_area,
/// used with a bare a, and triangle_attributes).
previous_mesh previous_from_dict(const py::dict& tri, pslg g) {
  if (!tri.contains("triangles") || py::len(tri["triangles"]) == 0)
    throw bad_argument("switch r refines a previous mesh: the dict needs 'triangles'");
  previous_mesh m;
  const auto t = as_table<long long>(tri["triangles"], 3, "triangles");
  for (py::ssize_t i = 0; i < t.shape(0); ++i) {
    std::array<index_t, 3> tr{};
    for (int k = 0; k < 3; ++k) {
      const long long v = t.at(i, k);
      if (v < 0 || static_cast<std::size_t>(v) >= g.vertices.size())
        throw bad_argument("triangles row " + std::to_string(i) + " refers to vertex " +
                           std::to_string(v) + " of " + std::to_string(g.vertices.size()));
      tr[k] = static_cast<index_t>(v);
    }
    m.triangles.push_back(tr);
  }
  for (const auto& [key, into] : {std::pair{"triangle_max_area", &m.triangle_areas},
                                  std::pair{"triangle_attributes", &m.triangle_attributes}})
    if (tri.contains(key) && py::len(tri[key]) > 0)
      *into = per_triangle(tri[key], m.triangles.size(), key);
  m.input = std::move(g);
  return m;
}

/// The dict pdd.triangulate returns (the `triangle` package's keys for the switches).
py::dict triangulate_result(const py::dict& tri, const triangle::switches& sw,
                            triangle::triangulation& t) {
  auto owner = std::make_unique<mesh_owner>();
  owner->mesh = std::move(t.mesh);
  owner->attributes = std::move(t.triangle_attributes);
  owner->neighbors = std::move(t.neighbors);
  owner->vertex_attributes = std::move(t.vertex_attributes);
  owner->vertex_attribute_count = t.vertex_attribute_count;
  for (std::size_t i = 0; i < t.second_order.size(); ++i) {
    const auto& c = owner->mesh.triangles[i];
    const auto& m = t.second_order[i];
    owner->six_node_triangles.push_back({c[0], c[1], c[2], m[0], m[1], m[2]});
  }
  mesh_views v(std::move(owner));
  py::dict out;
  const bool markers = !sw.no_boundary_markers;
  if (!sw.no_node) {
    out["vertices"] = v.vertices();
    if (markers) out["vertex_markers"] = v.ints(v.data().mesh.vertex_markers, true);
    if (v.data().vertex_attribute_count > 0) out["vertex_attributes"] = v.vertex_attributes();
  }
  if (!sw.no_ele) out["triangles"] = sw.second_order ? v.six_node_triangles() : v.triangles();
  if ((sw.poly || sw.convex) && !sw.no_poly) {
    out["segments"] = v.segments();
    if (markers) out["segment_markers"] = v.segment_markers(true);
  }
  if (sw.poly && tri.contains("holes")) out["holes"] = tri["holes"];
  if (sw.poly && tri.contains("regions")) out["regions"] = tri["regions"];
  if (sw.regional_attributes || !v.data().attributes.empty())
    out["triangle_attributes"] = v.attributes();
  if (sw.neighbors) out["neighbors"] = v.neighbors();
  if (sw.edges) add_edges(out, t.edges, markers);
  if (sw.voronoi) out["voronoi"] = voronoi_dict(t.voronoi);
  return out;
}

/// pdd.triangulate(tri, opts): see the docstring below.
py::dict triangulate(const py::dict& tri, const std::string& opts, unsigned threads,
                     std::size_t subdomains) {
  const triangle::switches sw = triangle::parse_switches(opts);
  pslg g = pslg_from_dict(tri);
  warn_unread_keys(tri, sw);
  triangle::triangulation t;
  if (sw.refine) {
    const previous_mesh previous = previous_from_dict(tri, std::move(g));
    py::gil_scoped_release release;
    t = triangle::refine(previous, sw, {threads, subdomains});
  } else {
    py::gil_scoped_release release;
    t = triangle::triangulate(std::move(g), sw, {threads, subdomains});
  }
  warn_duplicates(t);
  warn_empty_domain(t);
  raise_failed_check(t);
  if (sw.verbose > 0) { // Triangle's library prints its statistics for V; the summary here
    const mesh_statistics q = compute_statistics(t.mesh);
    py::print("pdd.triangulate:", q.vertices, "vertices,", q.triangles, "triangles, angles",
              q.min_angle_deg, "to", q.max_angle_deg, "degrees, largest area", q.max_area);
  }
  return triangulate_result(tri, sw, t);
}

/// generate_statistics (and the mesh's quality) as a dict.
py::dict statistics_dict(const generate_statistics& s, const mesh_statistics& q) {
  py::dict t("decompose"_a = s.timings.decompose, "decouple"_a = s.timings.decouple,
             "mesh"_a = s.timings.mesh, "merge"_a = s.timings.merge, "total"_a = s.timings.total);
  return py::dict(
      "subdomains"_a = s.subdomains, "threads"_a = s.threads, "triangles"_a = q.triangles,
      "vertices"_a = q.vertices, "estimated_triangles"_a = s.estimated_triangles, "k"_a = s.k,
      "split_points"_a = s.split_points, "interface_splits"_a = s.interface_splits,
      "chord_splits"_a = s.decomposition.chord_splits,
      "shielded_triangles"_a = s.shielded_triangles,
      "monolithic_fallback"_a = s.monolithic_fallback, "plan_reason"_a = s.plan_reason,
      "min_angle_deg"_a = q.min_angle_deg, "max_angle_deg"_a = q.max_angle_deg,
      "max_ratio"_a = q.max_ratio, "max_area"_a = q.max_area, "area"_a = q.area, "timings"_a = t);
}

/// pdd.verify(tri, mesh, ...): pdd::verify with its default options (see the docstring below).
py::dict verify(const py::dict& tri, const py::dict& mesh, double min_angle,
                const std::optional<double> max_area, std::size_t max_reported,
                const std::string& encroachment) {
  const pslg g = pslg_from_dict(tri);
  if (!mesh.contains("vertices") || !mesh.contains("triangles"))
    throw bad_argument("the mesh dict needs 'vertices' and 'triangles'");
  triangle_mesh m;
  m.vertices = points_of(mesh["vertices"], "mesh vertices");
  if (py::len(mesh["triangles"]) > 0) {
    const auto t = as_table<long long>(mesh["triangles"], 3, "mesh triangles");
    for (py::ssize_t i = 0; i < t.shape(0); ++i) {
      std::array<index_t, 3> tri_ids{};
      for (py::ssize_t k = 0; k < 3; ++k) // out of range: reported as a malformed triangle
        tri_ids[k] = t.at(i, k) < 0 || t.at(i, k) > static_cast<long long>(no_index - 1)
                         ? no_index
                         : static_cast<index_t>(t.at(i, k));
      m.triangles.push_back(tri_ids);
    }
  }
  verify_options o;
  o.criteria.min_angle_deg = min_angle;
  if (max_area) o.criteria.max_area = *max_area;
  if (encroachment == "diametral_lens")
    o.criteria.encroachment = segment_encroachment::diametral_lens;
  else if (encroachment != "diametral_circle")
    throw bad_argument("encroachment must be 'diametral_circle' or 'diametral_lens', got '" +
                       encroachment + "'");
  o.max_reported = max_reported;
  verification_report r;
  {
    py::gil_scoped_release release;
    r = pdd::verify(m, g, o);
  }
  return py::dict(
      "ok"_a = r.ok(), "delaunay_violations"_a = r.delaunay_violations,
      "orientation_violations"_a = r.orientation_violations,
      "missing_segments"_a = r.missing_segments, "duplicate_vertices"_a = r.duplicate_vertices,
      "missing_vertices"_a = r.missing_vertices, "quality_violations"_a = r.quality_violations,
      "area_violations"_a = r.area_violations, "nonmanifold_edges"_a = r.nonmanifold_edges,
      "area_domain"_a = r.area_domain, "area_mesh"_a = r.area_mesh, "area_ok"_a = r.area_ok,
      "messages"_a = r.messages);
}

/// The whole domain meshed by the kernel under a sizing field, small angles shielded first
/// (as pdd::pipeline::mesh_whole does for a uniform bound); a domain that is not one of closed
/// loops by Triangle's rule, or any domain above Ruppert's angle bound (where the shields do
/// not hold, pdd::within_ruppert_bound), unshielded (the kernel's own small-angle rule, as the
/// pipeline does).
template <SizingField S>
triangle_mesh mesh_with_sizing(const pslg& g, const mesh_criteria& c, const S& sizing,
                               generate_statistics& st) {
  st.subdomains = 1;
  st.threads = 1;
  if (!has_closed_loops(g)) {
    pslg whole = g;
    whole.rule = domain_rule::triangle;
    mesher_result r = default_mesher{}.mesh(whole, c, sizing);
    st.general_domain = true;
    st.triangles = r.mesh.triangles.size();
    return std::move(r.mesh);
  }
  if (!c.within_ruppert_bound()) {
    mesher_result r = default_mesher{}.mesh(g, c, sizing);
    st.triangles = r.mesh.triangles.size();
    return std::move(r.mesh);
  }
  const shielded_domain sd = shield(g, c.max_area);
  mesher_result r = default_mesher{}.mesh(sd.domain, c, sizing);
  if (add_shield_triangles(r, sd.domain, sd.triangles, 0) != 0)
    throw meshing_error(-1, "the kernel split a shield edge");
  st.shielded_triangles = sd.triangles.size();
  st.triangles = r.mesh.triangles.size();
  return std::move(r.mesh);
}

/// The PSLG of pdd.mesh's arrays.
pslg pslg_from_arrays(const py::handle& vertices, const py::handle& segments,
                      const py::handle& holes, const py::handle& vertex_markers,
                      const py::handle& segment_markers) {
  pslg g;
  g.vertices = points_of(vertices, "vertices");
  g.vertex_markers = vertex_markers.is_none()
                         ? std::vector<int>(g.vertices.size(), 0)
                         : markers_of(vertex_markers, g.vertices.size(), "vertex_markers");
  add_segments(g, segments, segment_markers);
  if (!holes.is_none()) g.holes = points_of(holes, "holes");
  return g;
}

/// pdd.mesh's keywords as generate options.
generate_options options_from(double min_angle, const py::handle& max_area, std::size_t subdomains,
                              unsigned threads) {
  generate_options o;
  o.criteria.min_angle_deg = min_angle;
  if (!max_area.is_none()) {
    o.criteria.max_area = max_area.cast<double>();
    if (!(o.criteria.max_area > 0.0)) throw bad_argument("max_area must be > 0");
  }
  o.subdomains = subdomains;
  o.threads = threads;
  return o;
}

/// pdd.mesh(...): see the docstring below.
py::dict mesh(const py::handle& vertices, const py::handle& segments, const py::handle& holes,
              double min_angle, const py::handle& max_area, const py::handle& sizing,
              const py::handle& sizing_bounds, std::size_t subdomains, unsigned threads,
              const std::string& kernel, const py::handle& vertex_markers,
              const py::handle& segment_markers) {
  if (kernel != kernel_name)
    throw bad_argument("kernel '" + kernel + "' is not available (this build of pdd has: '" +
                       kernel_name + "')");
  const pslg g = pslg_from_arrays(vertices, segments, holes, vertex_markers, segment_markers);
  const generate_options o = options_from(min_angle, max_area, subdomains, threads);
  const bool callable = !sizing.is_none() && PyCallable_Check(sizing.ptr());
  if (!sizing.is_none() && subdomains > 1)
    throw bad_argument("a sizing field meshes the whole domain at once: subdomains must be 0 or "
                       "1 (the decoupled pipeline takes a uniform max_area)");
  // The sizing objects are made and destroyed with the GIL held; copies made while
  // meshing only share the Python function through a shared_ptr.
  std::optional<callable_sizing> by_callable;
  std::optional<grid_sizing> by_grid;
  if (callable)
    by_callable = callable_sizing{
        std::make_shared<py::function>(py::reinterpret_borrow<py::function>(sizing))};
  else if (!sizing.is_none())
    by_grid = make_grid_sizing(sizing, sizing_bounds, g.vertices);
  auto owner = std::make_unique<mesh_owner>();
  generate_statistics st;
  {
    py::gil_scoped_release release;
    validate(g);
    if (by_callable) {
      owner->mesh = mesh_with_sizing(g, o.criteria, *by_callable, st);
    } else if (by_grid) {
      owner->mesh = mesh_with_sizing(g, o.criteria, *by_grid, st);
    } else {
      generate_result r = generate(g, o);
      owner->mesh = std::move(r.mesh);
      st = std::move(r.statistics);
    }
  }
  const mesh_statistics q = compute_statistics(owner->mesh);
  mesh_views v(std::move(owner));
  return py::dict("vertices"_a = v.vertices(), "triangles"_a = v.triangles(),
                  "segments"_a = v.segments(), "segment_markers"_a = v.segment_markers(false),
                  "vertex_markers"_a = v.ints(v.data().mesh.vertex_markers, false),
                  "triangle_markers"_a = v.ints(v.data().mesh.triangle_markers, false),
                  "statistics"_a = statistics_dict(st, q));
}

} // namespace
} // namespace pdd::python

PYBIND11_MODULE(pdd, m) {
  using namespace pdd::python;
  m.doc() = "pdd: parallel guaranteed-quality 2D Delaunay meshing by the decoupling method";
  m.attr("__version__") = PDD_PYTHON_VERSION; // project(VERSION), python/CMakeLists.txt
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const pdd::input_error& e) {
      PyErr_SetString(PyExc_ValueError, e.what());
    } catch (const pdd::geometry_error& e) {
      PyErr_SetString(PyExc_ValueError, e.what());
    } catch (const pdd::triangle::switch_error& e) {
      PyErr_SetString(PyExc_ValueError, e.what());
    } catch (const bad_argument& e) {
      PyErr_SetString(PyExc_ValueError, e.what());
    } catch (const pdd::limit_error& e) {
      PyErr_SetString(PyExc_MemoryError, e.what());
    } catch (const pdd::error& e) { // meshing, decomposition, internal: not the caller's input
      PyErr_SetString(PyExc_RuntimeError, e.what());
    }
  });
  m.def("triangulate", &triangulate, "tri"_a, "opts"_a = "", py::kw_only(), "threads"_a = 0,
        "subdomains"_a = 0,
        R"(Meshes a PSLG as the `triangle` package's triangulate(tri, opts) does, with pdd.

tri: dict with 'vertices' (n, 2) and optionally 'vertex_markers', 'segments' (m, 2),
'segment_markers', 'holes' (h, 2), 'regions' (r, 4: x, y, attribute, max_area).
opts: Triangle switches: p (mesh the PSLG; without p the vertices are a vertex set: their
Delaunay triangulation, or with q/a a quality mesh of their convex hull; segments, holes and
regions are then not read, with a warning), q[angle], a[area], a (regional areas), A, c (convex
hull: with p the hull is meshed, without p its edges are the segments), e (edges), v (Voronoi
diagram), o2 (six-node triangles: 'triangles' (t, 6), the corners, then the nodes in the middle
of the edges opposite them, added to 'vertices'), Q, V (prints a summary), N, E, P, B, O, z, j,
n; I is accepted and means nothing without files; i, F, l, s, L, X are accepted and ignored
(Triangle's internal algorithms). p alone is the constrained Delaunay triangulation (no
Steiner point). Numbering is zero-based (the triangle package's 'z'). 'vertex_attributes' (n,)
or (n, k) are carried to every output vertex: interpolated linearly over the input's constrained
Delaunay triangulation at new vertices, the edge's mean at o2's nodes. r refines the previous
mesh of 'triangles' (its vertices kept, first; with a bare a its 'triangle_max_area', <= 0: none;
its 'triangle_attributes' carried to the new triangles inside each old one); without r those keys
are not read, with a warning. C checks the mesh with pdd's verifier (exact Delaunay, or
constrained Delaunay without D; conformity; the domain's area; the angle and area bounds) and
raises RuntimeError with its messages when it fails. Any other switch or unknown key raises
ValueError. A vertex equal to an earlier one (without p) is ignored with a UserWarning, as
Triangle ignores it. A PSLG that encloses no domain (no face enclosed by segments, or hole
points eat every one) gives Triangle's empty mesh with a UserWarning: 'triangles' (0, 3).
Markers are Triangle's: a vertex keeps its nonzero marker, else takes a nonzero marker of a
segment it lies on, else 1 on the boundary, else 0; segments likewise (nonzero, else 1 on the
boundary, else 0).
Returns a dict: vertices, vertex_markers (n, 1), vertex_attributes (n, k) (when given),
triangles (t, 3) int32, segments and
segment_markers (with p or c), holes and regions (copied, with p), triangle_attributes (with A),
neighbors (with n, -1 on the boundary), edges (e, 2) and edge_markers (e, 1) int32 (with e),
voronoi (with v: a dict of vertices, edges, ray_origins, ray_directions as pdd.voronoi returns
them). Mesh arrays are views of pdd's mesh (no copy). pdd's keywords: threads (0: all cores),
subdomains (0: automatic).)");
  def_triangle_functions(m);
  m.def("mesh", &mesh, "vertices"_a, "segments"_a, "holes"_a = py::none(), "min_angle"_a = 20.7,
        "max_area"_a = py::none(), "sizing"_a = py::none(), "sizing_bounds"_a = py::none(),
        "subdomains"_a = 0, "threads"_a = 0, "kernel"_a = kernel_name,
        "vertex_markers"_a = py::none(), "segment_markers"_a = py::none(),
        R"(Meshes the domain enclosed by closed segment loops with guaranteed quality.

vertices (n, 2), segments (m, 2) vertex indices, holes (h, 2) one point in each hole.
min_angle degrees; max_area a uniform bound; sizing a callable f(x, y) -> area or a 2-D numpy
grid of areas over sizing_bounds (x0, y0, x1, y1; default: the vertices' bounding box) -- a
sizing field meshes the whole domain at once (subdomains 0 or 1). subdomains: N of the
decoupling method (0: automatic); threads (0: all cores): the arrays are bitwise the same for
every thread count. Returns a dict of numpy arrays (vertices, triangles, segments,
segment_markers, vertex_markers, triangle_markers = subdomain ids) and 'statistics'.
Bad input raises ValueError with pdd's message; the GIL is released while meshing.)");
  m.def("verify", &verify, "tri"_a, "mesh"_a, py::kw_only(), "min_angle"_a = 20.7,
        "max_area"_a = py::none(), "max_reported"_a = 20, "encroachment"_a = "diametral_circle",
        R"(Verifies a mesh of a PSLG with pdd::verify's defaults: the one verdict of `pdd-mesh
--verify`, pdd-verify and the C++ library.

tri: the input dict given to triangulate or mesh (the faces are read as pdd reads them).
mesh: a dict with 'vertices' (n, 2) and 'triangles' (t, 3), e.g. what triangulate returns.
Checks exact local Delaunay of every interior edge, orientation, every input segment a union
of mesh edges, the domain's area covered, every triangle's area <= max_area, and the angle
bound min_angle on every triangle but those pdd's rule exempts (shielded corners of input angles
< 60 deg; on a domain that is not closed loops, the cluster triangles at small angles between
segments). encroachment: 'diametral_circle' (default, as pdd.mesh meshes: every interior edge
Delaunay) or 'diametral_lens' for a mesh of triangulate without D, which refines under
Triangle's diametral lenses: constrained Delaunay, so edges on input segments are not checked
for the Delaunay property. Returns a dict: ok, the count of each kind of violation,
area_domain, area_mesh, area_ok and messages (the first max_reported, with ids and coordinates).)");
  m.attr("supported_switches") = std::string(pdd::triangle::supported_switches);
}
