// numpy <-> pdd conversions for the Python module: checked input arrays, and output arrays that
// are zero-copy views of a mesh kept alive by a capsule.
#pragma once

#include <pdd/core/pslg.hpp>
#include <pdd/core/triangle_mesh.hpp>
#include <pdd/errors.hpp>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <cmath>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace pdd::python {

namespace py = pybind11;

/// A value error with pdd's wording (becomes Python's ValueError).
struct bad_argument : error {
  using error::error;
};

/// `obj` as a C-contiguous array of T with `cols` columns (a 1-D array counts as one column
/// when cols == 1); `what` names it in errors. \throws bad_argument on a wrong shape/type.
template <class T>
py::array_t<T, py::array::c_style | py::array::forcecast>
as_table(const py::handle& obj, py::ssize_t cols, const std::string& what) {
  py::array_t<T, py::array::c_style | py::array::forcecast> a;
  try {
    a = py::array_t<T, py::array::c_style | py::array::forcecast>::ensure(obj);
  } catch (const py::error_already_set&) {
    a = {};
  }
  if (!a) throw bad_argument(what + " must be a numeric array");
  const bool one_column = a.ndim() == 1 && cols == 1;
  if (!one_column && (a.ndim() != 2 || a.shape(1) != cols))
    throw bad_argument(what + " must have shape (n, " + std::to_string(cols) + "), got " +
                       std::to_string(a.ndim()) + " dimension(s)" +
                       (a.ndim() == 2 ? " with " + std::to_string(a.shape(1)) + " columns" : ""));
  return a;
}

/// Rows of an (n, 2) float array as points; every coordinate finite.
inline std::vector<point> points_of(const py::handle& obj, const std::string& what) {
  if (py::len(obj) == 0) return {}; // holes=[] as the triangle package accepts it
  const auto a = as_table<double>(obj, 2, what);
  std::vector<point> out(static_cast<std::size_t>(a.shape(0)));
  const double* d = a.data();
  for (std::size_t i = 0; i < out.size(); ++i) {
    out[i] = {d[2 * i], d[2 * i + 1]};
    if (!std::isfinite(out[i].x) || !std::isfinite(out[i].y))
      throw bad_argument(what + " row " + std::to_string(i) + " is not finite");
  }
  return out;
}

/// An (n, 1) or (n,) integer array as ints, with n rows required.
inline std::vector<int> markers_of(const py::handle& obj, std::size_t n, const std::string& what) {
  const auto a = as_table<long long>(obj, 1, what);
  if (static_cast<std::size_t>(a.shape(0)) != n)
    throw bad_argument(what + " has " + std::to_string(a.shape(0)) + " rows for " +
                       std::to_string(n) + " items");
  std::vector<int> out(n);
  for (std::size_t i = 0; i < n; ++i) {
    const long long v = a.data()[i];
    if (v < INT32_MIN || v > INT32_MAX) throw bad_argument(what + " exceeds the range of int32");
    out[i] = static_cast<int>(v);
  }
  return out;
}

/// The triangle package's vertex_attributes, (n,) or (n, k) floats with n = g's vertex count
/// and every value finite, into g.vertex_attributes.
inline void read_vertex_attributes(pslg& g, const py::handle& obj) {
  using table = py::array_t<double, py::array::c_style | py::array::forcecast>;
  table a;
  try {
    a = table::ensure(obj);
  } catch (const py::error_already_set&) {
    a = {};
  }
  if (!a || a.ndim() < 1 || a.ndim() > 2)
    throw bad_argument("vertex_attributes must be a numeric array of shape (n,) or (n, k)");
  if (static_cast<std::size_t>(a.shape(0)) != g.vertices.size())
    throw bad_argument("vertex_attributes has " + std::to_string(a.shape(0)) + " rows for " +
                       std::to_string(g.vertices.size()) + " vertices");
  g.vertex_attribute_count = a.ndim() == 1 ? 1 : static_cast<std::size_t>(a.shape(1));
  g.vertex_attributes.assign(a.data(), a.data() + a.size());
  for (std::size_t i = 0; i < g.vertex_attributes.size(); ++i)
    if (!std::isfinite(g.vertex_attributes[i]))
      throw bad_argument("vertex_attributes row " + std::to_string(i / g.vertex_attribute_count) +
                         " is not finite");
}

/// Adds (m, 2) segments (vertex indices in [0, n)) with optional markers to g.
inline void add_segments(pslg& g, const py::handle& segs, const py::handle& markers) {
  if (py::len(segs) == 0) return;
  const auto a = as_table<long long>(segs, 2, "segments");
  const auto m = static_cast<std::size_t>(a.shape(0));
  const std::vector<int> mk =
      markers.is_none() ? std::vector<int>(m, 0) : markers_of(markers, m, "segment_markers");
  for (std::size_t s = 0; s < m; ++s) {
    const long long u = a.data()[2 * s], v = a.data()[2 * s + 1];
    const auto n = static_cast<long long>(g.vertices.size());
    if (u < 0 || v < 0 || u >= n || v >= n)
      throw bad_argument("segment " + std::to_string(s) + " refers to vertex " +
                         std::to_string(u < 0 || u >= n ? u : v) + ", outside [0, " +
                         std::to_string(n) + ")");
    g.add_segment(static_cast<index_t>(u), static_cast<index_t>(v), mk[s]);
  }
}

/// Keeps a mesh (and anything moved into it) alive for the arrays that view it.
struct mesh_owner {
  triangle_mesh mesh;
  std::vector<double> attributes;
  std::vector<std::array<long long, 3>> neighbors;
  /// Triangle's -o2: the corners, then the nodes in the middle of the edges opposite them.
  std::vector<std::array<index_t, 6>> six_node_triangles;
  std::vector<double> vertex_attributes; ///< vertex_attribute_count per vertex
  std::size_t vertex_attribute_count = 0;
};

/// Zero-copy numpy views of a mesh_owner's vectors; each holds the capsule.
class mesh_views {
public:
  explicit mesh_views(std::unique_ptr<mesh_owner> owner)
      : owner_(owner.get()),
        capsule_(owner.release(), [](void* p) { delete static_cast<mesh_owner*>(p); }) {}
  mesh_owner& data() { return *owner_; }

  py::array vertices() {
    return view<double>(owner_->mesh.vertices.data(), {rows(owner_->mesh.vertices), 2},
                        {sizeof(point), sizeof(double)});
  }
  /// Triangles as int32 (as the triangle package returns them; indices < 2^31 here).
  py::array triangles() {
    return view<std::int32_t>(owner_->mesh.triangles.data(), {rows(owner_->mesh.triangles), 3},
                              {3 * sizeof(index_t), sizeof(index_t)});
  }
  /// The vertex attributes, (n, k) float64.
  py::array vertex_attributes() {
    const auto k = static_cast<py::ssize_t>(owner_->vertex_attribute_count);
    return view<double>(owner_->vertex_attributes.data(),
                        {k == 0 ? 0 : rows(owner_->vertex_attributes) / k, k},
                        {k * static_cast<py::ssize_t>(sizeof(double)), sizeof(double)});
  }
  /// The six-node triangles (-o2) as int32, (t, 6).
  py::array six_node_triangles() {
    return view<std::int32_t>(owner_->six_node_triangles.data(),
                              {rows(owner_->six_node_triangles), 6},
                              {6 * sizeof(index_t), sizeof(index_t)});
  }
  py::array segments() {
    return view<std::int32_t>(owner_->mesh.segments.data(), {rows(owner_->mesh.segments), 2},
                              {sizeof(mesh_edge), sizeof(index_t)});
  }
  py::array segment_markers(bool column) {
    auto* first = owner_->mesh.segments.empty() ? nullptr : &owner_->mesh.segments[0].marker;
    return column ? view<int>(first, {rows(owner_->mesh.segments), 1}, {sizeof(mesh_edge), 0})
                  : view<int>(first, {rows(owner_->mesh.segments)}, {sizeof(mesh_edge)});
  }
  py::array ints(std::vector<int>& v, bool column) {
    return column ? view<int>(v.data(), {rows(v), 1}, {sizeof(int), 0})
                  : view<int>(v.data(), {rows(v)}, {sizeof(int)});
  }
  py::array attributes() {
    return view<double>(owner_->attributes.data(), {rows(owner_->attributes), 1},
                        {sizeof(double), 0});
  }
  py::array neighbors() {
    return view<long long>(owner_->neighbors.data(), {rows(owner_->neighbors), 3},
                           {3 * sizeof(long long), sizeof(long long)});
  }

private:
  template <class V>
  static py::ssize_t rows(const V& v) {
    return static_cast<py::ssize_t>(v.size());
  }
  template <class T>
  py::array view(const void* data, std::vector<py::ssize_t> shape,
                 std::vector<py::ssize_t> strides) {
    return py::array_t<T>(std::move(shape), std::move(strides), static_cast<const T*>(data),
                          capsule_);
  }
  mesh_owner* owner_;
  py::capsule capsule_;
};

} // namespace pdd::python
