/// \file triangulation.hpp
/// pdd::triangle::triangulate_options and pdd::triangle::triangulation: the options and the
/// result of pdd::triangle::triangulate (triangle/triangulate.hpp).
#pragma once

#include <pdd/core/triangle_mesh.hpp>
#include <pdd/mesh/verification_report.hpp>
#include <pdd/pipeline/statistics.hpp>

#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace pdd::triangle {

/// pdd's own knobs beside the switches.
struct triangulate_options {
  unsigned threads = 0;       ///< threads of pdd::generate (0: all cores)
  std::size_t subdomains = 0; ///< N of every component (0: automatic, 1: monolithic)
};

/// Switch v: the Voronoi diagram dual to the mesh, as Triangle writes it (.v.node, .v.edge).
struct voronoi_diagram {
  /// Vertex t: the circumcentre of triangle t of the mesh (CGAL's construction, rounded).
  std::vector<point> vertices;
  /// Edge i, the dual of edge i of triangulation::edges: two Voronoi vertices, or one and -1
  /// for a ray (the dual of a boundary edge).
  std::vector<std::array<long long, 2>> edges;
  /// Edge i's ray direction (a boundary edge a->b, the mesh on its left, rotated clockwise:
  /// (b.y - a.y, a.x - b.x), outward, as long as the edge); (0, 0) for a finite edge.
  std::vector<point> directions;
};

/// The mesh and the tables Triangle's outputs hold.
struct triangulation {
  /// The mesh: input vertices first, in input order (as Triangle numbers them), then the
  /// Steiner vertices; triangles counter-clockwise; segments the edges on input segments.
  triangle_mesh mesh;
  /// The input's vertex attributes (pslg::vertex_attribute_count per vertex), vertex by vertex
  /// for every vertex of `mesh`: the input's own, interpolated linearly at the others (see
  /// triangle/detail/vertex_attributes.hpp); empty when the input has none.
  std::vector<double> vertex_attributes;
  /// Attributes per vertex in vertex_attributes (the input's pslg::vertex_attribute_count; 0:
  /// none).
  std::size_t vertex_attribute_count = 0;
  /// Switch A: the regional attribute of every triangle (0 where no region seed lies).
  std::vector<double> triangle_attributes;
  /// Switch n: the triangle across from vertex i of triangle t, -1 on the boundary.
  std::vector<std::array<long long, 3>> neighbors;
  /// One pdd::generate run per meshed part (the whole domain, or one per component when
  /// regional area bounds differ).
  std::vector<generate_statistics> runs;
  std::size_t jettisoned_vertices = 0; ///< switch j
  /// Switch e (or v): every edge of the mesh once, triangle by triangle (the edge across from
  /// vertex i of triangle t, i = 0, 1, 2, listed by the smaller of its two triangles), oriented
  /// as in that triangle; markers by Triangle's rule: a segment's nonzero marker, else 1 on the
  /// boundary, else 0.
  std::vector<mesh_edge> edges;
  voronoi_diagram voronoi; ///< switch v
  /// Switch o2: per triangle t the nodes 4, 5 and 6 of its six-node triangle, in the middle of
  /// the edges opposite its corners 0, 1 and 2; they are vertices of `mesh` after all those the
  /// triangles use as corners (no triangle has them as a corner).
  std::vector<std::array<index_t, 3>> second_order;
  /// Without p: {vertex, the earlier equal vertex} for every input vertex equal to an earlier
  /// one; Triangle ignores it (it is in the output, used by no triangle) with a warning.
  std::vector<std::array<index_t, 2>> duplicate_vertices;
  /// With p, when the PSLG encloses no domain (pdd::empty_domain_error: no face enclosed by
  /// segments, every enclosed face eaten by hole points, or all vertices collinear): why. The
  /// mesh then has the input's vertices and no triangle and no segment, as Triangle's. Empty
  /// otherwise.
  std::string empty_domain;
  /// Without p, with q or a: the strips the vertex set's hull was decoupled into, their
  /// separators through the vertices (triangle/detail/point_set_strips.hpp); 0 when it was not
  /// (meshed whole, or split by MADD: runs says how many subdomains).
  std::size_t strips = 0;
  /// Switch C: pdd::verify's report on the mesh (before j, o2 and the tables), against the
  /// domain that was meshed and the switches' bounds (see pdd::triangle::triangulate); absent
  /// without C or when the mesh is empty.
  std::optional<verification_report> check;
};

} // namespace pdd::triangle
