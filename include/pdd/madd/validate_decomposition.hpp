/// \file validate_decomposition.hpp
/// pdd::validate_decomposition: checks that a decomposition is a conforming partition of its
/// domain into polygons with holes with separator angles >= Phi0 (the guarantees of MADD,
/// dissertation ch. 3; used by the tests and by the pdd-decompose driver).
#pragma once

#include <pdd/core/decomposition.hpp>
#include <pdd/core/pslg.hpp>
#include <pdd/geometry/loops.hpp>
#include <pdd/madd/decomposition_report.hpp>
#include <pdd/madd/detail/validate.hpp>

#include <cmath>
#include <cstddef>
#include <vector>

namespace pdd {

/// Checks a decomposition of the domain of g: every subdomain is a polygon with holes (outer
/// loop counter-clockwise, holes clockwise and inside it, no vertex twice except where the
/// domain's loops touch (a pinch vertex: a subdomain visits it once per sector), no two edges
/// crossing or overlapping); its area field matches its loops; the areas add up to the
/// domain's area (relative tolerance); every external edge lies on the input segment it names
/// (same marker) exactly once and the external edges cover every input segment; every
/// interface edge is in exactly two subdomains, in opposite directions, with the same
/// interface id and each other as neighbour, and lies on its interface curve; every interior
/// angle of a subdomain at a vertex with an incident interface edge is >= Phi0 - tolerance;
/// every inner constraint (general PSLGs) is its input segment and touches no interface.
/// Returns every problem found (up to max_problems), never throws for a bad decomposition.
/// \throws geometry_error if g itself has no valid loops (find_loops).
/// Complexity O(n log n) for n loop edges. Thread-safe.
inline decomposition_report validate_decomposition(const decomposition& d, const pslg& g,
                                                   const decomposition_check_options& o = {}) {
  decomposition_report rep;
  auto& pr = rep.problems;
  if (d.vertex_markers.size() != d.vertices.size())
    pr.push_back("vertex_markers has the wrong size");
  detail::decomposition_edges edges;
  const std::vector<point> pinches = detail::pinch_candidates(g);
  for (std::size_t s = 0; s < d.subdomains.size() && pr.size() < o.max_problems; ++s) {
    if (!detail::check_subdomain_structure(d, s, pinches, pr)) continue;
    detail::check_subdomain_loops(d, s, pr);
    detail::check_subdomain_simple(d, s, pr);
    rep.area_sum += detail::check_subdomain_edges(d, s, o, rep, edges);
  }
  // Edges: external once on their segment, interfaces twice with matching tags.
  std::vector<double> covered(g.segments.size(), 0.0);
  double on_segment_length = 0.0;
  for (const auto& [key, list] : edges) {
    if (pr.size() >= o.max_problems) break;
    if (list[0].tag.type == edge_tag::kind::external) {
      detail::check_external_edge(key, list, d, g, covered, pr);
      continue;
    }
    detail::check_interface_edge(key, list, d, pr);
    if (list[0].tag.on_segment && key.first < d.vertices.size() && key.second < d.vertices.size())
      on_segment_length += detail::distance(d.vertices[key.first], d.vertices[key.second]);
  }
  detail::check_inner_constraints(d, g, covered, o.max_problems, pr);
  detail::check_segment_coverage(g, covered, on_segment_length, o.max_problems, pr);
  detail::check_interface_curves(d, edges, o.max_problems, pr);
  rep.domain_area = domain_area(g);
  if (std::abs(rep.area_sum - rep.domain_area) > o.area_tolerance * std::abs(rep.domain_area))
    pr.push_back("the subdomain areas add up to " + std::to_string(rep.area_sum) +
                 ", the domain's area is " + std::to_string(rep.domain_area));
  return rep;
}

} // namespace pdd
