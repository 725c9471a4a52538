/// \file subdomain_region.hpp
/// pdd::subdomain_region: a subdomain of a decomposition as the region pdd::sizing_range bounds a
/// field over (its loops' inside, holes left out), for subdomains of any domain: loops that
/// touch themselves or each other at pinch vertices included.
#pragma once

#include <pdd/core/decomposition.hpp>
#include <pdd/core/index.hpp>
#include <pdd/core/kernel.hpp>
#include <pdd/core/triangulation_levels.hpp>
#include <pdd/sizing/domain_region.hpp>
#include <pdd/triangulation/constrained_delaunay_2.hpp>

#include <unordered_map>
#include <utility>
#include <vector>

namespace pdd {

namespace detail {
/// The constrained triangulation of a subdomain's loops (vertex info: the region's vertex id;
/// face info: the nesting level).
using region_cdt = constrained_delaunay_2<index_t, int>;
} // namespace detail

/// The region of subdomain s of d: the constrained Delaunay triangulation of its loops (each
/// pool vertex once, so a pinch vertex where loops touch is one vertex) and the faces at odd
/// nesting levels (pdd::flood_levels), which are the subdomain's inside whatever its loops'
/// orientation. The inner constraints of a general domain's subdomain (dangling segments,
/// isolated vertices) lie inside it and are left out: they do not change the region.
/// \pre s < d.subdomains.size(), the loops do not cross (a valid decomposition).
/// Complexity O(n log n) expected, n the loops' vertices.
inline triangulated_region subdomain_region(const decomposition& d, index_t s) {
  triangulated_region r;
  detail::region_cdt tr;
  std::unordered_map<index_t, detail::region_cdt::Vertex_handle> handle;
  const auto vertex = [&](index_t v) {
    auto [it, added] = handle.emplace(v, detail::region_cdt::Vertex_handle());
    if (added) {
      it->second = tr.insert(epick::Point_2(d.vertices[v].x, d.vertices[v].y));
      it->second->info() = static_cast<index_t>(r.vertices.size());
      r.vertices.push_back(d.vertices[v]);
    }
    return it->second;
  };
  for (const auto& loop : d.subdomains[s].loops)
    for (std::size_t i = 0; i < loop.size(); ++i) {
      const auto a = vertex(loop[i]), b = vertex(loop[(i + 1) % loop.size()]);
      if (a != b) tr.insert_constraint(a, b);
    }
  for (auto f = tr.all_faces_begin(); f != tr.all_faces_end(); ++f)
    f->info() = -1;
  flood_levels(tr, [](detail::region_cdt::Face_handle f) -> int& { return f->info(); });
  for (auto f = tr.finite_faces_begin(); f != tr.finite_faces_end(); ++f)
    if (f->info() % 2 == 1)
      r.triangles.push_back({f->vertex(0)->info(), f->vertex(1)->info(), f->vertex(2)->info()});
  return r;
}

} // namespace pdd
