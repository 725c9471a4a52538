/// \file vertex_attributes.hpp
/// Implementation of pdd::triangle::triangulate for inputs with vertex attributes (Triangle's
/// `.node` attribute columns, the `triangle` package's `vertex_attributes`): every new vertex
/// gets them interpolated linearly, as Triangle does.
///
/// Triangle interpolates at each insertion from the triangle (or the segment) of its current
/// mesh that holds the new vertex, so its values depend on the order of insertion. pdd
/// interpolates on the constrained Delaunay triangulation of the input (its vertices and, with
/// p, its segments): the piecewise linear function the input defines, the same for every
/// order, thread count and N; it reproduces a function that is linear over the input exactly,
/// and along a segment it is the linear interpolation between the segment's ends.
#pragma once

#include <pdd/core/kernel.hpp>
#include <pdd/core/pslg.hpp>
#include <pdd/triangle/detail/point_set.hpp>
#include <pdd/triangulation/constrained_delaunay_2.hpp>

#include <algorithm>
#include <array>
#include <cstddef>
#include <utility>
#include <vector>

namespace pdd::triangle::detail {

/// Linear interpolation of a PSLG's vertex attributes over its constrained Delaunay
/// triangulation. Thread-safety: const members may be called concurrently.
class vertex_attribute_interpolator {
public:
  /// The triangulation of g's distinct vertices, with g's segments as constraints when
  /// `segments` (switch p; the PSLG was validated: no two segments cross).
  /// Complexity O(n log n) expected.
  vertex_attribute_interpolator(const pslg& g, bool segments)
      : count_(g.vertex_attribute_count), inputs_(g.vertices.size()), values_(g.vertex_attributes) {
    values_.resize(inputs_ * count_, 0.0);
    std::vector<cdt::Vertex_handle> handle(g.vertices.size());
    const distinct_vertices d = find_distinct(g.vertices);
    for (const index_t v : d.kept) {
      handle[v] = cdt_.insert(epick::Point_2(g.vertices[v].x, g.vertices[v].y));
      handle[v]->info() = v;
    }
    if (segments)
      for (const segment& s : g.segments)
        cdt_.insert_constraint(handle[d.first[s.a]], handle[d.first[s.b]]);
  }

  /// The attributes of the vertices of a mesh whose first `inputs` vertices are the input's in
  /// input order (they keep their own values): count() values per vertex, vertex by vertex.
  std::vector<double> at(const std::vector<point>& vertices) const {
    std::vector<double> out(values_.begin(), values_.end());
    out.resize(vertices.size() * count_, 0.0);
    for (std::size_t v = inputs_; v < vertices.size(); ++v)
      interpolate(vertices[v], &out[v * count_]);
    return out;
  }

  std::size_t count() const noexcept { return count_; }

private:
  using cdt = constrained_delaunay_2<index_t>;

  /// Writes the interpolated attributes at p to out (count_ values): barycentric in the
  /// triangle holding p, linear on an edge, the vertex's own at a vertex.
  void interpolate(const point& p, double* out) const {
    cdt::Locate_type type{};
    int li = 0;
    const cdt::Face_handle f = cdt_.locate(epick::Point_2(p.x, p.y), type, li);
    std::array<std::pair<index_t, double>, 3> w{};
    if (type == cdt::VERTEX) {
      w[0] = {f->vertex(li)->info(), 1.0};
    } else if (type == cdt::EDGE) {
      w = along_edge(f, li, p);
    } else if (type == cdt::FACE) {
      w = barycentric(f, p);
    } else if (type == cdt::OUTSIDE_CONVEX_HULL) {
      // a split point of a hull segment, rounded to just outside it: along the hull edge of
      // the infinite face CGAL returns (the one p sees)
      w = along_edge(f, f->index(cdt_.infinite_vertex()), p);
    } else {
      return; // outside the affine hull of collinear inputs: no mesh is made of them
    }
    for (std::size_t k = 0; k < count_; ++k) {
      double sum = 0.0;
      for (const auto& [v, weight] : w)
        if (weight != 0.0) sum += weight * values_[v * count_ + k];
      out[k] = sum;
    }
  }

  static point at_vertex(cdt::Vertex_handle v) { return {v->point().x(), v->point().y()}; }

  /// Linear along the edge of f opposite its vertex li, p projected onto it (clamped to it).
  static std::array<std::pair<index_t, double>, 3> along_edge(cdt::Face_handle f, int li,
                                                              const point& p) {
    const cdt::Vertex_handle u = f->vertex(cdt::ccw(li)), v = f->vertex(cdt::cw(li));
    const point a = at_vertex(u), b = at_vertex(v);
    const double dx = b.x - a.x, dy = b.y - a.y;
    const double t =
        std::clamp(((p.x - a.x) * dx + (p.y - a.y) * dy) / (dx * dx + dy * dy), 0.0, 1.0);
    return {{{u->info(), 1.0 - t}, {v->info(), t}, {no_index, 0.0}}};
  }

  /// p's barycentric coordinates in the finite face f.
  static std::array<std::pair<index_t, double>, 3> barycentric(cdt::Face_handle f, const point& p) {
    const point a = at_vertex(f->vertex(0)), b = at_vertex(f->vertex(1)),
                c = at_vertex(f->vertex(2));
    const auto twice_area = [](const point& u, const point& v, const point& w) {
      return (v.x - u.x) * (w.y - u.y) - (v.y - u.y) * (w.x - u.x);
    };
    const double whole = twice_area(a, b, c);
    return {{{f->vertex(0)->info(), twice_area(p, b, c) / whole},
             {f->vertex(1)->info(), twice_area(a, p, c) / whole},
             {f->vertex(2)->info(), twice_area(a, b, p) / whole}}};
  }

  std::size_t count_;
  std::size_t inputs_;
  std::vector<double> values_;
  cdt cdt_{constraint_crossing::split_at_vertices};
};

} // namespace pdd::triangle::detail
