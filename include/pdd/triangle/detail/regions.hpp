/// \file regions.hpp
/// Implementation of pdd::triangle::triangulate for switches A and a alone: the area bound
/// and the attribute of every component, which component each triangle lies in, and one
/// pdd::generate run per component when the bounds differ.
#pragma once

#include <pdd/core/pslg.hpp>
#include <pdd/core/triangle_mesh.hpp>
#include <pdd/generate.hpp>
#include <pdd/geometry/loops.hpp>
#include <pdd/mesh/region_attributes.hpp>
#include <pdd/triangle/detail/components.hpp>
#include <pdd/triangle/switches.hpp>
#include <pdd/triangle/triangulation.hpp>

#include <algorithm>
#include <cstddef>
#include <functional>
#include <limits>
#include <vector>

namespace pdd::triangle::detail {

/// The area bound of every component: the uniform bound, lowered by the last region seed
/// in the component that has a positive area (Triangle floods regions in order).
inline std::vector<double> component_areas(const pslg& g, const loop_structure& ls,
                                           const std::vector<domain_component>& comps,
                                           double uniform) {
  std::vector<double> area(comps.size(), uniform);
  std::vector<double> regional(comps.size(), -1.0);
  for (const region& r : g.regions) {
    const std::size_t c = component_of(g, ls, comps, r.p);
    if (c != no_component) regional[c] = r.max_area;
  }
  for (std::size_t c = 0; c < comps.size(); ++c)
    if (regional[c] > 0.0) area[c] = std::min(area[c], regional[c]);
  return area;
}

/// The regional attribute of every component (the last seed in it wins; 0 without one).
inline std::vector<double> component_attributes(const pslg& g, const loop_structure& ls,
                                                const std::vector<domain_component>& comps) {
  std::vector<double> attr(comps.size(), 0.0);
  for (const region& r : g.regions) {
    const std::size_t c = component_of(g, ls, comps, r.p);
    if (c != no_component) attr[c] = r.attribute;
  }
  return attr;
}

/// The component of every triangle of a mesh of the whole domain: the components share no
/// vertex (pdd's loops are disjoint), so they are the connected pieces of the triangles'
/// adjacency; one centroid per piece is located. Complexity O(triangles + pieces * loops).
inline std::vector<std::size_t> triangle_components(const pslg& g, const loop_structure& ls,
                                                    const std::vector<domain_component>& comps,
                                                    const triangle_mesh& m) {
  const auto nb = triangle_neighbors(m);
  std::vector<std::size_t> out(m.triangles.size(), no_component - 1);
  std::vector<std::size_t> stack;
  for (std::size_t seed = 0; seed < m.triangles.size(); ++seed) {
    if (out[seed] != no_component - 1) continue;
    const auto& t = m.triangles[seed];
    const point a = m.vertices[t[0]], b = m.vertices[t[1]], c = m.vertices[t[2]];
    const std::size_t comp =
        component_of(g, ls, comps, {(a.x + b.x + c.x) / 3.0, (a.y + b.y + c.y) / 3.0});
    out[seed] = comp;
    stack.assign(1, seed);
    while (!stack.empty()) {
      const std::size_t u = stack.back();
      stack.pop_back();
      for (const long long n : nb[u])
        if (n >= 0 && out[static_cast<std::size_t>(n)] == no_component - 1) {
          out[static_cast<std::size_t>(n)] = comp;
          stack.push_back(static_cast<std::size_t>(n));
        }
    }
  }
  return out;
}

/// Meshes every component on its own (its own area bound) and concatenates the meshes;
/// `component` receives the component of every triangle.
inline triangle_mesh mesh_components(const pslg& g, const loop_structure& ls,
                                     const std::vector<domain_component>& comps,
                                     const std::vector<double>& areas, generate_options o,
                                     std::vector<std::size_t>& component,
                                     std::vector<generate_statistics>& runs) {
  triangle_mesh all;
  for (std::size_t c = 0; c < comps.size(); ++c) {
    std::vector<index_t> input_ids;
    const pslg part = component_pslg(g, ls, comps[c], input_ids);
    o.criteria.max_area = areas[c];
    generate_result r = generate(part, o);
    const auto offset = static_cast<index_t>(all.vertices.size());
    all.vertices.insert(all.vertices.end(), r.mesh.vertices.begin(), r.mesh.vertices.end());
    all.vertex_markers.insert(all.vertex_markers.end(), r.mesh.vertex_markers.begin(),
                              r.mesh.vertex_markers.end());
    for (auto t : r.mesh.triangles) {
      for (index_t& v : t)
        v += offset;
      all.triangles.push_back(t);
      component.push_back(c);
    }
    all.triangle_markers.insert(all.triangle_markers.end(), r.mesh.triangle_markers.begin(),
                                r.mesh.triangle_markers.end());
    for (mesh_edge e : r.mesh.segments)
      all.segments.push_back({e.a + offset, e.b + offset, e.marker});
    runs.push_back(std::move(r.statistics));
  }
  return all;
}

/// The generate options the switches ask for: q's angle (0 without q: Triangle's default),
/// a's uniform area bound (none without it), Triangle's diametral lenses unless D.
inline generate_options options_for(const switches& sw, const triangulate_options& o) {
  generate_options g;
  g.threads = o.threads;
  g.subdomains = o.subdomains;
  g.criteria.min_angle_deg = sw.quality ? sw.min_angle_deg : 0.0;
  g.criteria.max_area = sw.max_area > 0.0 ? sw.max_area : std::numeric_limits<double>::infinity();
  // Triangle refines under diametral lenses unless D asks for a conforming Delaunay mesh (D
  // takes conforming_pslg, which keeps the circles).
  g.criteria.encroachment =
      sw.conforming ? segment_encroachment::diametral_circle : segment_encroachment::diametral_lens;
  return g;
}

/// Meshes a domain with regions for switches A and a alone: one run when every component has
/// the same area bound, else one run per component; the regional attribute of every triangle
/// (switch A) from the component it lies in.
inline void mesh_regions(const pslg& domain, const switches& sw, const generate_options& gopt,
                         triangulation& out) {
  const loop_structure ls = find_loops(domain);
  const auto comps = domain_components(ls);
  std::vector<double> areas(comps.size(), gopt.criteria.max_area);
  if (sw.regional_areas) areas = component_areas(domain, ls, comps, gopt.criteria.max_area);
  std::vector<std::size_t> component;
  if (std::adjacent_find(areas.begin(), areas.end(), std::not_equal_to<>()) != areas.end()) {
    out.mesh = mesh_components(domain, ls, comps, areas, gopt, component, out.runs);
  } else {
    generate_options one = gopt;
    one.criteria.max_area = areas.empty() ? gopt.criteria.max_area : areas.front();
    generate_result r = generate(domain, one);
    out.mesh = std::move(r.mesh);
    out.runs.push_back(std::move(r.statistics));
    if (sw.regional_attributes) component = triangle_components(domain, ls, comps, out.mesh);
  }
  if (!sw.regional_attributes) return;
  const std::vector<double> attribute = component_attributes(domain, ls, comps);
  out.triangle_attributes.assign(out.mesh.triangles.size(), 0.0);
  for (std::size_t t = 0; t < component.size(); ++t)
    if (component[t] != no_component) out.triangle_attributes[t] = attribute[component[t]];
}

} // namespace pdd::triangle::detail
