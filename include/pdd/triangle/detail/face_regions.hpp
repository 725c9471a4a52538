/// \file face_regions.hpp
/// Implementation of pdd::triangle::triangulate for switches A and a alone on a domain that is
/// not one of closed loops (Triangle's rule: internal segments separate faces): one run with
/// the regional area bounds as a sizing field, and the attribute of every triangle from the
/// face it lies in.
#pragma once

#include <pdd/core/pslg.hpp>
#include <pdd/core/triangle_mesh.hpp>
#include <pdd/generate.hpp>
#include <pdd/mesh/region_attributes.hpp>
#include <pdd/sizing/regional.hpp>
#include <pdd/triangle/switches.hpp>
#include <pdd/triangle/triangulation.hpp>

#include <utility>

namespace pdd::triangle::detail {

/// Switches A and a alone on a domain that is not one of closed loops: one pdd::generate run
/// (the pipeline meshes it whole), with a alone the regions' area bounds as a sizing field
/// (pdd::regional_sizing: in each face the smallest bound of its region points, the uniform
/// bound elsewhere), with A every triangle's attribute from its face (pdd::region_attributes).
inline void mesh_face_regions(pslg domain, const switches& sw, generate_options gopt,
                              triangulation& out) {
  domain.rule = domain_rule::triangle;
  if (sw.regional_areas) {
    regional_sizing field(domain);
    if (field.bounded_regions() > 0) gopt.sizing = std::move(field);
  }
  generate_result r = generate(domain, gopt);
  out.mesh = std::move(r.mesh);
  out.runs.push_back(std::move(r.statistics));
  if (sw.regional_attributes) out.triangle_attributes = region_attributes(domain, out.mesh);
}

} // namespace pdd::triangle::detail
