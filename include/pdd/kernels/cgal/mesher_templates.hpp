/// \file mesher_templates.hpp
/// The definition of pdd::cgal::mesher::mesh (kernels/cgal/mesher.hpp): CGAL's constrained
/// Delaunay triangulation refined by Mesh_2. Include it to mesh with a SizingField of your own;
/// libpdd holds the instantiations for pdd::any_sizing and pdd::uniform_sizing.
#pragma once

#include <pdd/errors.hpp>
#include <pdd/kernels/cgal/criteria.hpp>
#include <pdd/kernels/cgal/detail/mesher.hpp>
#include <pdd/kernels/cgal/mesher.hpp>
#include <pdd/kernels/detail/mesher_input.hpp>

#include <CGAL/exceptions.h>

#include <exception>
#include <string>
#include <vector>

namespace pdd::detail::cgal_mesh {

/// The kernel's work: the constrained triangulation of d, its domain marked, refined under the
/// criteria, extracted (see pdd::cgal::mesher).
template <SizingField S>
mesher_result refine_domain(const pslg& d, const mesh_criteria& c, const S& sizing) {
  cdt tr;
  const std::vector<vertex_handle> vh = build_cdt(tr, d);
  if (tr.dimension() == 2) {
    mark_domain(tr, d.holes, d.rule);
    if (d.rule == domain_rule::triangle) release_outside_segments(tr, d.holes);
    cgal::sizing_criteria<cdt, S> crit(c.shape_bound(), c.max_area, sizing);
    const lens_rule lens{c.lens_cosine()};
    refine(tr, crit, uses_diametral_lens(d, c) ? &lens : nullptr);
  }
  return extract(tr, d, vh);
}

} // namespace pdd::detail::cgal_mesh

namespace pdd::cgal {

template <SizingField S>
mesher_result mesher::mesh(const pslg& d, const mesh_criteria& criteria, const S& sizing) const {
  pdd::detail::check_mesher_input(d, criteria);
  try {
    return pdd::detail::cgal_mesh::refine_domain(d, criteria, sizing);
  } catch (const pdd::error&) {
    throw;
  } catch (const std::exception& e) {
    throw meshing_error(-1, std::string("CGAL failed: ") + e.what());
  }
}

} // namespace pdd::cgal
