/// \file mesher_templates.hpp
/// The definition of pdd::native::mesher::mesh (kernels/native/mesher.hpp). Include it to mesh
/// with a SizingField of your own; libpdd holds the instantiations for pdd::any_sizing and
/// pdd::uniform_sizing.
#pragma once

#include <pdd/kernels/detail/mesher_input.hpp>
#include <pdd/kernels/native/detail/build.hpp>
#include <pdd/kernels/native/detail/extract.hpp>
#include <pdd/kernels/native/detail/refine.hpp>
#include <pdd/kernels/native/mesher.hpp>

namespace pdd::native {

template <SizingField S>
mesher_result mesher::mesh(const pslg& d, const mesh_criteria& criteria, const S& sizing) const {
  pdd::detail::check_mesher_input(d, criteria);
  namespace nm = pdd::detail::native_mesh;
  nm::triangulation tr;
  nm::cavity cav;
  nm::build(tr, cav, d);
  nm::segment_ids ids(d, tr.pts.size());
  nm::reserve_for_area_bound(tr, ids.of_vertex, criteria.max_area);
  nm::refiner<S>(tr, cav, ids, d, criteria, sizing).run();
  return nm::extract(tr, ids, d);
}

} // namespace pdd::native
