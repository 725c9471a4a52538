/// \file assemble.hpp
/// Implementation detail of MADD: the regions of an input PSLG, the registry of edge splits
/// that keeps neighbouring regions conforming, and the final decomposition value with
/// deterministic vertex ids, subdomain order and interfaces.
#pragma once

#include <pdd/madd/detail/region.hpp>
#include <pdd/errors.hpp>
#include <pdd/geometry/loops.hpp>
#include <pdd/core/pslg.hpp>
#include <pdd/madd/decomposition.hpp>

#include <algorithm>
#include <cstdint>
#include <map>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

namespace pdd::detail {

/// The connected components of a PSLG's domain as regions (outer loop counter-clockwise, holes
/// clockwise), in the order of their outer loops in find_loops.
/// \throws geometry_error as find_loops.
inline std::vector<madd_region> regions_of(const pslg& g) {
  const loop_structure ls = find_loops(g);
  auto make_loop = [&](const polygon_loop& pl, bool want_ccw) {
    madd_loop l;
    const std::size_t n = pl.vertices.size();
    const bool reverse = pl.counterclockwise != want_ccw;
    for (std::size_t k = 0; k < n; ++k) {
      const index_t v = reverse ? pl.vertices[(n - k) % n] : pl.vertices[k];
      const index_t s = reverse ? pl.segments[n - k - 1] : pl.segments[k];
      l.points.push_back(g.vertices[v]);
      l.markers.push_back(v < g.vertex_markers.size() ? g.vertex_markers[v] : 0);
      l.tags.push_back(madd_edge_tag{true, s, g.segments[s].marker});
    }
    return l;
  };
  std::vector<madd_region> out;
  for (std::size_t i = 0; i < ls.loops.size(); ++i) {
    const polygon_loop& pl = ls.loops[i];
    if (!pl.bounds_domain_inside) continue;
    madd_region r;
    r.loops.push_back(make_loop(pl, true));
    for (const polygon_loop& h : ls.loops)
      if (h.parent == i && !h.bounds_domain_inside) r.loops.push_back(make_loop(h, false));
    r.area = region_area(r);
    out.push_back(std::move(r));
  }
  return out;
}

/// Inserts every registered split vertex into every region edge it lies on, so that both
/// sides of an interface have the same vertices. Complexity O(E log K) for E region edges and
/// K registered vertices.
inline void apply_edge_splits(std::vector<madd_region>& regions, std::vector<madd_edge_split> reg) {
  if (reg.empty()) return;
  std::sort(reg.begin(), reg.end(), [](const madd_edge_split& a, const madd_edge_split& b) {
    return std::tie(a.lo, a.hi, a.t) < std::tie(b.lo, b.hi, b.t);
  });
  reg.erase(std::unique(reg.begin(), reg.end(),
                        [](const madd_edge_split& a, const madd_edge_split& b) {
                          return a.lo == b.lo && a.hi == b.hi && a.t == b.t;
                        }),
            reg.end());
  // Groups: the points of each registered edge in order, ends included.
  struct gpoint {
    point p;
    int marker;
    bool end; // lo or hi: its marker is not ours to set
  };
  std::vector<std::vector<gpoint>> groups;
  for (std::size_t i = 0; i < reg.size();) {
    std::vector<gpoint> gp{{reg[i].lo, 0, true}};
    std::size_t k = i;
    for (; k < reg.size() && reg[k].lo == reg[i].lo && reg[k].hi == reg[i].hi; ++k)
      gp.push_back({reg[k].m, reg[k].marker, false});
    gp.push_back({reg[i].hi, 0, true});
    groups.push_back(std::move(gp));
    i = k;
  }
  struct entry {
    point a, b; // canonical
    std::uint32_t group, i, j;
  };
  std::vector<entry> entries;
  for (std::uint32_t gi = 0; gi < groups.size(); ++gi) {
    const auto& gp = groups[gi];
    for (std::uint32_t i = 0; i < gp.size(); ++i)
      for (std::uint32_t j = i + 2; j < gp.size(); ++j)
        entries.push_back({std::min(gp[i].p, gp[j].p), std::max(gp[i].p, gp[j].p), gi, i, j});
  }
  std::sort(entries.begin(), entries.end(),
            [](const entry& x, const entry& y) { return std::tie(x.a, x.b) < std::tie(y.a, y.b); });
  auto find = [&](point x, point y) -> const entry* {
    const point a = std::min(x, y), b = std::max(x, y);
    auto it = std::lower_bound(entries.begin(), entries.end(), std::make_pair(a, b),
                               [](const entry& e, const std::pair<point, point>& k) {
                                 return std::tie(e.a, e.b) < std::tie(k.first, k.second);
                               });
    if (it == entries.end() || it->a != a || it->b != b) return nullptr;
    return &*it;
  };
  for (madd_region& r : regions) {
    bool changed = false;
    for (madd_loop& l : r.loops) {
      const std::size_t n = l.size();
      bool any = false;
      for (std::size_t i = 0; i < n && !any; ++i)
        any = find(l.points[i], l.points[(i + 1) % n]) != nullptr;
      if (!any) continue;
      madd_loop out;
      for (std::size_t i = 0; i < n; ++i) {
        out.points.push_back(l.points[i]);
        out.markers.push_back(l.markers[i]);
        out.tags.push_back(l.tags[i]);
        const entry* e = find(l.points[i], l.points[(i + 1) % n]);
        if (e == nullptr) continue;
        const auto& gp = groups[e->group];
        const bool forward = gp[e->i].p == l.points[i];
        for (std::uint32_t k = 1; k + 1 < e->j - e->i + 1; ++k) {
          const gpoint& q = gp[forward ? e->i + k : e->j - k];
          out.points.push_back(q.p);
          out.markers.push_back(q.marker);
          out.tags.push_back(l.tags[i]);
        }
      }
      l = std::move(out);
      changed = true;
    }
    if (changed) r.area = region_area(r);
  }
}

/// The decomposition value of the final regions: vertex ids in lexicographic order of the
/// coordinates, every loop starting at its smallest id, holes ordered by their first id,
/// subdomains ordered by their outer loops, interfaces found from the shared edges.
/// \throws internal_error if an interface edge is not shared by exactly two regions.
inline decomposition assemble_decomposition(const std::vector<madd_region>& regions) {
  decomposition d;
  std::vector<std::pair<point, int>> pts;
  for (const madd_region& r : regions)
    for (const madd_loop& l : r.loops)
      for (std::size_t i = 0; i < l.size(); ++i)
        pts.emplace_back(l.points[i], l.markers[i]);
  std::sort(pts.begin(), pts.end());
  pts.erase(std::unique(pts.begin(), pts.end(),
                        [](const auto& a, const auto& b) { return a.first == b.first; }),
            pts.end());
  for (const auto& [p, m] : pts) {
    d.vertices.push_back(p);
    d.vertex_markers.push_back(m);
  }
  auto id_of = [&](point p) {
    const auto it = std::lower_bound(d.vertices.begin(), d.vertices.end(), p);
    PDD_ASSERT(it != d.vertices.end() && *it == p);
    return static_cast<index_t>(it - d.vertices.begin());
  };
  struct tagged_loop {
    std::vector<index_t> v;
    std::vector<madd_edge_tag> t;
  };
  std::vector<std::vector<tagged_loop>> subs;
  for (const madd_region& r : regions) {
    std::vector<tagged_loop> loops;
    for (const madd_loop& l : r.loops) {
      tagged_loop tl;
      for (std::size_t i = 0; i < l.size(); ++i) {
        tl.v.push_back(id_of(l.points[i]));
        tl.t.push_back(l.tags[i]);
      }
      const auto s =
          static_cast<std::size_t>(std::min_element(tl.v.begin(), tl.v.end()) - tl.v.begin());
      std::rotate(tl.v.begin(), tl.v.begin() + s, tl.v.end());
      std::rotate(tl.t.begin(), tl.t.begin() + s, tl.t.end());
      loops.push_back(std::move(tl));
    }
    std::sort(loops.begin() + 1, loops.end(),
              [](const tagged_loop& a, const tagged_loop& b) { return a.v[0] < b.v[0]; });
    subs.push_back(std::move(loops));
  }
  std::sort(subs.begin(), subs.end(), [](const auto& a, const auto& b) { return a[0].v < b[0].v; });
  // Interface edges: (min id, max id, subdomain, loop, edge).
  struct iedge {
    index_t u, w, s, l, i;
  };
  std::vector<iedge> ie;
  for (index_t s = 0; s < subs.size(); ++s)
    for (index_t l = 0; l < subs[s].size(); ++l) {
      const auto& tl = subs[s][l];
      for (index_t i = 0; i < tl.v.size(); ++i) {
        if (tl.t[i].external) continue;
        const index_t a = tl.v[i], b = tl.v[(i + 1) % tl.v.size()];
        ie.push_back({std::min(a, b), std::max(a, b), s, l, i});
      }
    }
  std::sort(ie.begin(), ie.end(), [](const iedge& x, const iedge& y) {
    return std::tie(x.u, x.w, x.s) < std::tie(y.u, y.w, y.s);
  });
  if (ie.size() % 2 != 0) throw internal_error("MADD: an interface edge has no neighbour");
  // Per subdomain pair: the shared edges (as vertex pairs).
  std::map<std::pair<index_t, index_t>, std::vector<std::pair<index_t, index_t>>> pair_edges;
  for (std::size_t k = 0; k < ie.size(); k += 2) {
    const iedge& x = ie[k];
    const iedge& y = ie[k + 1];
    if (x.u != y.u || x.w != y.w || x.s == y.s ||
        (k + 2 < ie.size() && ie[k + 2].u == x.u && ie[k + 2].w == x.w))
      throw internal_error("MADD: interface edge (" + std::to_string(x.u) + ", " +
                           std::to_string(x.w) + ") is not shared by exactly two subdomains");
    pair_edges[{x.s, y.s}].emplace_back(x.u, x.w);
  }
  // Chain each pair's edges into polylines from their smaller end.
  std::map<std::pair<index_t, index_t>, index_t> edge_interface;
  for (const auto& [sides, edges] : pair_edges) {
    const std::pair<index_t, index_t> st = sides; // Clang < 16: no capture of a binding
    std::map<index_t, std::vector<index_t>> adj;
    for (const auto& [a, b] : edges) {
      adj[a].push_back(b);
      adj[b].push_back(a);
    }
    std::map<std::pair<index_t, index_t>, char> used;
    auto walk = [&](index_t start) {
      interface_curve c;
      c.a = st.first;
      c.b = st.second;
      c.vertices.push_back(start);
      index_t v = start;
      for (;;) {
        index_t nxt = no_index;
        for (const index_t w : adj[v]) {
          const auto key = std::make_pair(std::min(v, w), std::max(v, w));
          if (!used[key]) {
            if (nxt == no_index || w < nxt) nxt = w;
          }
        }
        if (nxt == no_index) break;
        used[{std::min(v, nxt), std::max(v, nxt)}] = 1;
        c.vertices.push_back(nxt);
        v = nxt;
      }
      const auto id = static_cast<index_t>(d.interfaces.size());
      for (std::size_t k = 0; k + 1 < c.vertices.size(); ++k)
        edge_interface[{std::min(c.vertices[k], c.vertices[k + 1]),
                        std::max(c.vertices[k], c.vertices[k + 1])}] = id;
      d.interfaces.push_back(std::move(c));
    };
    for (const auto& [v, nb] : adj)
      if (nb.size() == 1 && !used[{std::min(v, nb[0]), std::max(v, nb[0])}]) walk(v);
    for (const auto& [v, nb] : adj)
      for (const index_t w : nb)
        if (!used[{std::min(v, w), std::max(v, w)}]) walk(v); // closed chains
  }
  for (index_t s = 0; s < subs.size(); ++s) {
    subdomain sd;
    for (const auto& tl : subs[s]) {
      std::vector<edge_tag> tags;
      for (index_t i = 0; i < tl.v.size(); ++i) {
        const madd_edge_tag& t = tl.t[i];
        edge_tag et;
        if (t.external) {
          et.type = edge_tag::kind::external;
          et.id = t.segment;
          et.marker = t.marker;
        } else {
          const index_t a = tl.v[i], b = tl.v[(i + 1) % tl.v.size()];
          et.type = edge_tag::kind::interface;
          et.id = edge_interface.at({std::min(a, b), std::max(a, b)});
          const interface_curve& c = d.interfaces[et.id];
          et.neighbour = c.a == s ? c.b : c.a;
        }
        tags.push_back(et);
      }
      sd.loops.push_back(tl.v);
      sd.tags.push_back(std::move(tags));
    }
    double area = 0.0;
    for (const auto& l : sd.loops) {
      std::vector<point> p;
      for (const index_t v : l)
        p.push_back(d.vertices[v]);
      area += signed_area(p);
    }
    sd.area = area;
    d.subdomains.push_back(std::move(sd));
  }
  return d;
}

} // namespace pdd::detail
