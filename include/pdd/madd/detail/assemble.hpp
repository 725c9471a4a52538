/// \file assemble.hpp
/// Implementation detail of MADD: the regions of an input PSLG, the registry of edge splits
/// that keeps neighbouring regions conforming, and the final decomposition value with
/// deterministic vertex ids, subdomain order and interfaces.
#pragma once

#include <pdd/core/decomposition.hpp>
#include <pdd/core/pslg.hpp>
#include <pdd/errors.hpp>
#include <pdd/geometry/loops.hpp>
#include <pdd/madd/detail/region.hpp>

#include <algorithm>
#include <cstdint>
#include <map>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

namespace pdd::detail {

/// The connected components of a PSLG's domain as regions (outer loop counter-clockwise, holes
/// clockwise), in the order of their outer loops in ls (g's loops, pdd::find_loops).
inline std::vector<madd_region> regions_of(const pslg& g, const loop_structure& ls) {
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

/// regions_of on g's loops. \throws geometry_error as find_loops.
inline std::vector<madd_region> regions_of(const pslg& g) {
  return regions_of(g, find_loops(g));
}

/// One point of a registered edge's split group: the edge's ends (whose markers are not ours
/// to set) or a split vertex with its marker.
struct split_group_point {
  point p;
  int marker;
  bool end; ///< lo or hi of the registered edge
};

/// The registered edge splits grouped by edge: the points of each edge in order of their
/// parameter, ends included. Duplicate registrations are dropped.
inline std::vector<std::vector<split_group_point>> split_groups(std::vector<madd_edge_split> reg) {
  std::sort(reg.begin(), reg.end(), [](const madd_edge_split& a, const madd_edge_split& b) {
    return std::tie(a.lo, a.hi, a.t) < std::tie(b.lo, b.hi, b.t);
  });
  reg.erase(std::unique(reg.begin(), reg.end(),
                        [](const madd_edge_split& a, const madd_edge_split& b) {
                          return a.lo == b.lo && a.hi == b.hi && a.t == b.t;
                        }),
            reg.end());
  std::vector<std::vector<split_group_point>> groups;
  for (std::size_t i = 0; i < reg.size();) {
    std::vector<split_group_point> gp{{reg[i].lo, 0, true}};
    std::size_t k = i;
    for (; k < reg.size() && reg[k].lo == reg[i].lo && reg[k].hi == reg[i].hi; ++k)
      gp.push_back({reg[k].m, reg[k].marker, false});
    gp.push_back({reg[i].hi, 0, true});
    groups.push_back(std::move(gp));
    i = k;
  }
  return groups;
}

/// Lookup of a region edge among the split groups: every pair (i, j), j >= i + 2, of points
/// of a group is an edge that the points strictly between them subdivide.
class split_edge_index {
public:
  /// A group's sub-edge from its point i to its point j (canonical ends a < b).
  struct entry {
    point a, b;
    std::uint32_t group, i, j;
  };

  explicit split_edge_index(const std::vector<std::vector<split_group_point>>& groups) {
    for (std::uint32_t gi = 0; gi < groups.size(); ++gi) {
      const auto& gp = groups[gi];
      for (std::uint32_t i = 0; i < gp.size(); ++i)
        for (std::uint32_t j = i + 2; j < gp.size(); ++j)
          entries_.push_back({std::min(gp[i].p, gp[j].p), std::max(gp[i].p, gp[j].p), gi, i, j});
    }
    std::sort(entries_.begin(), entries_.end(), [](const entry& x, const entry& y) {
      return std::tie(x.a, x.b) < std::tie(y.a, y.b);
    });
  }

  /// The entry of the edge xy (either orientation), nullptr if no split lies on it.
  const entry* find(point x, point y) const {
    const point a = std::min(x, y), b = std::max(x, y);
    auto it = std::lower_bound(entries_.begin(), entries_.end(), std::make_pair(a, b),
                               [](const entry& e, const std::pair<point, point>& k) {
                                 return std::tie(e.a, e.b) < std::tie(k.first, k.second);
                               });
    if (it == entries_.end() || it->a != a || it->b != b) return nullptr;
    return &*it;
  }

private:
  std::vector<entry> entries_;
};

/// Inserts the split vertices lying on the edges of l; false (l unchanged) if there are none.
inline bool insert_splits_into_loop(madd_loop& l,
                                    const std::vector<std::vector<split_group_point>>& groups,
                                    const split_edge_index& index) {
  const std::size_t n = l.size();
  bool any = false;
  for (std::size_t i = 0; i < n && !any; ++i)
    any = index.find(l.points[i], l.points[(i + 1) % n]) != nullptr;
  if (!any) return false;
  madd_loop out;
  for (std::size_t i = 0; i < n; ++i) {
    out.points.push_back(l.points[i]);
    out.markers.push_back(l.markers[i]);
    out.tags.push_back(l.tags[i]);
    const split_edge_index::entry* e = index.find(l.points[i], l.points[(i + 1) % n]);
    if (e == nullptr) continue;
    const auto& gp = groups[e->group];
    const bool forward = gp[e->i].p == l.points[i];
    for (std::uint32_t k = 1; k + 1 < e->j - e->i + 1; ++k) {
      const split_group_point& q = gp[forward ? e->i + k : e->j - k];
      out.points.push_back(q.p);
      out.markers.push_back(q.marker);
      out.tags.push_back(l.tags[i]);
    }
  }
  l = std::move(out);
  return true;
}

/// Inserts every registered split vertex into every region edge it lies on, so that both
/// sides of an interface have the same vertices. Complexity O(E log K) for E region edges and
/// K registered vertices.
inline void apply_edge_splits(std::vector<madd_region>& regions, std::vector<madd_edge_split> reg) {
  if (reg.empty()) return;
  const std::vector<std::vector<split_group_point>> groups = split_groups(std::move(reg));
  const split_edge_index index(groups);
  for (madd_region& r : regions) {
    bool changed = false;
    for (madd_loop& l : r.loops)
      changed = insert_splits_into_loop(l, groups, index) || changed;
    if (changed) r.area = region_area(r);
  }
}

/// A region loop by vertex ids, with its edge tags (tag i: edge v[i] -> v[i + 1]).
struct id_loop {
  std::vector<index_t> v;
  std::vector<madd_edge_tag> t;
};

/// The distinct points of all region loops and features in lexicographic order, with their
/// markers, as the vertices of d.
inline void number_vertices(const std::vector<madd_region>& regions, decomposition& d) {
  std::vector<std::pair<point, int>> pts;
  for (const madd_region& r : regions) {
    for (const madd_loop& l : r.loops)
      for (std::size_t i = 0; i < l.size(); ++i)
        pts.emplace_back(l.points[i], l.markers[i]);
    for (const madd_feature& f : r.features) {
      pts.emplace_back(f.a, f.marker_a);
      pts.emplace_back(f.b, f.marker_b);
    }
  }
  std::sort(pts.begin(), pts.end());
  pts.erase(std::unique(pts.begin(), pts.end(),
                        [](const auto& a, const auto& b) { return a.first == b.first; }),
            pts.end());
  for (const auto& [p, m] : pts) {
    d.vertices.push_back(p);
    d.vertex_markers.push_back(m);
  }
}

/// The id of point p among the sorted vertices of d.
inline index_t pool_id(const decomposition& d, point p) {
  const auto it = std::lower_bound(d.vertices.begin(), d.vertices.end(), p);
  PDD_ASSERT(it != d.vertices.end() && *it == p);
  return static_cast<index_t>(it - d.vertices.begin());
}

/// The regions' loops by the vertex ids of d (sorted vertices): each loop starts at its
/// smallest id, holes are ordered by their first id, regions by their outer loops;
/// region_of[s] is the region that became subdomain s.
inline std::vector<std::vector<id_loop>> numbered_loops(const std::vector<madd_region>& regions,
                                                        const decomposition& d,
                                                        std::vector<std::size_t>& region_of) {
  auto id_of = [&](point p) { return pool_id(d, p); };
  std::vector<std::vector<id_loop>> subs;
  for (const madd_region& r : regions) {
    std::vector<id_loop> loops;
    for (const madd_loop& l : r.loops) {
      id_loop tl;
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
              [](const id_loop& a, const id_loop& b) { return a.v[0] < b.v[0]; });
    subs.push_back(std::move(loops));
  }
  region_of.resize(subs.size());
  for (std::size_t i = 0; i < subs.size(); ++i)
    region_of[i] = i;
  std::sort(region_of.begin(), region_of.end(),
            [&](std::size_t a, std::size_t b) { return subs[a][0].v < subs[b][0].v; });
  std::vector<std::vector<id_loop>> sorted;
  for (const std::size_t i : region_of)
    sorted.push_back(std::move(subs[i]));
  return sorted;
}

/// The features of a region as inner constraints over the pool of d, in input order
/// (segments by id, then vertices by id).
inline std::vector<inner_constraint> inner_constraints(const madd_region& r,
                                                       const decomposition& d) {
  std::vector<inner_constraint> out;
  for (const madd_feature& f : r.features)
    out.push_back({pool_id(d, f.a), pool_id(d, f.b), f.segment, f.marker});
  std::sort(out.begin(), out.end(), [](const inner_constraint& x, const inner_constraint& y) {
    return std::tie(x.segment, x.a) < std::tie(y.segment, y.a);
  });
  return out;
}

/// An undirected edge by its vertex ids (smaller first), or a pair of subdomains.
using index_pair = std::pair<index_t, index_t>;

/// Per pair of subdomains (smaller index first): the interface edges they share: the
/// separator edges, and the external edges two subdomains share (on an internal constraint
/// of a general PSLG, between two of its faces).
/// \throws internal_error if a separator edge is not shared by exactly two subdomains.
inline std::map<index_pair, std::vector<index_pair>>
shared_interface_edges(const std::vector<std::vector<id_loop>>& subs) {
  struct interface_edge {
    index_t u, w, s; // min id, max id, subdomain
    bool external;
  };
  std::vector<interface_edge> all;
  for (index_t s = 0; s < subs.size(); ++s)
    for (const id_loop& tl : subs[s])
      for (index_t i = 0; i < tl.v.size(); ++i) {
        const index_t a = tl.v[i], b = tl.v[(i + 1) % tl.v.size()];
        all.push_back({std::min(a, b), std::max(a, b), s, tl.t[i].external});
      }
  std::sort(all.begin(), all.end(), [](const interface_edge& x, const interface_edge& y) {
    return std::tie(x.u, x.w, x.s) < std::tie(y.u, y.w, y.s);
  });
  std::vector<interface_edge> ie; // separator edges, and external edges of two subdomains
  for (std::size_t k = 0; k < all.size(); ++k) {
    const bool shared =
        (k > 0 && all[k - 1].u == all[k].u && all[k - 1].w == all[k].w) ||
        (k + 1 < all.size() && all[k + 1].u == all[k].u && all[k + 1].w == all[k].w);
    if (!all[k].external || shared) ie.push_back(all[k]);
  }
  if (ie.size() % 2 != 0) throw internal_error("MADD: an interface edge has no neighbour");
  std::map<index_pair, std::vector<index_pair>> pair_edges;
  for (std::size_t k = 0; k < ie.size(); k += 2) {
    const interface_edge& x = ie[k];
    const interface_edge& y = ie[k + 1];
    if (x.u != y.u || x.w != y.w || x.s == y.s ||
        (k + 2 < ie.size() && ie[k + 2].u == x.u && ie[k + 2].w == x.w))
      throw internal_error("MADD: interface edge (" + std::to_string(x.u) + ", " +
                           std::to_string(x.w) + ") is not shared by exactly two subdomains");
    pair_edges[{x.s, y.s}].emplace_back(x.u, x.w);
  }
  return pair_edges;
}

/// Chains the edges shared by the subdomains sides.first and sides.second into interface
/// curves of d: open chains from their smaller end first, then closed chains, each walked
/// to its smallest unused neighbour. Records each edge's interface id in edge_interface.
inline void chain_interface_edges(index_pair sides, const std::vector<index_pair>& edges,
                                  decomposition& d, std::map<index_pair, index_t>& edge_interface) {
  std::map<index_t, std::vector<index_t>> adj;
  for (const auto& [a, b] : edges) {
    adj[a].push_back(b);
    adj[b].push_back(a);
  }
  std::map<index_pair, char> used;
  auto walk = [&](index_t start) {
    interface_curve c;
    c.a = sides.first;
    c.b = sides.second;
    c.vertices.push_back(start);
    index_t v = start;
    for (;;) {
      index_t nxt = no_index;
      for (const index_t w : adj[v])
        if (!used[{std::min(v, w), std::max(v, w)}] && (nxt == no_index || w < nxt)) nxt = w;
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

/// The edge tags of subdomain s's loop tl: external edges keep their segment and marker,
/// interface edges get their interface id and the neighbour across.
inline std::vector<edge_tag>
subdomain_edge_tags(const id_loop& tl, index_t s, const decomposition& d,
                    const std::map<index_pair, index_t>& edge_interface) {
  std::vector<edge_tag> tags;
  for (index_t i = 0; i < tl.v.size(); ++i) {
    const madd_edge_tag& t = tl.t[i];
    const index_t a = tl.v[i], b = tl.v[(i + 1) % tl.v.size()];
    const auto it = edge_interface.find({std::min(a, b), std::max(a, b)});
    edge_tag et;
    if (it == edge_interface.end()) {
      PDD_ASSERT(t.external);
      et.type = edge_tag::kind::external;
      et.id = t.segment;
      et.marker = t.marker;
    } else {
      et.type = edge_tag::kind::interface;
      et.id = it->second;
      const interface_curve& c = d.interfaces[et.id];
      et.neighbour = c.a == s ? c.b : c.a;
      et.on_segment = t.external;
      et.marker = t.external ? t.marker : 0;
    }
    tags.push_back(et);
  }
  return tags;
}

/// Subdomain s of d from its numbered loops: loops, tags, and its area (the sum of the
/// signed loop areas, outer counter-clockwise, holes clockwise).
inline subdomain make_subdomain(const std::vector<id_loop>& loops, index_t s,
                                const decomposition& d,
                                const std::map<index_pair, index_t>& edge_interface) {
  subdomain sd;
  for (const id_loop& tl : loops) {
    sd.tags.push_back(subdomain_edge_tags(tl, s, d, edge_interface));
    sd.loops.push_back(tl.v);
  }
  double area = 0.0;
  for (const auto& l : sd.loops)
    area += polygon_signed_area(l.size(), [&](std::size_t i) { return d.vertices[l[i]]; });
  sd.area = area;
  return sd;
}

/// The decomposition value of the final regions: vertex ids in lexicographic order of the
/// coordinates, every loop starting at its smallest id, holes ordered by their first id,
/// subdomains ordered by their outer loops, interfaces found from the shared edges, each
/// region's features as its subdomain's inner constraints.
/// \throws internal_error if an interface edge is not shared by exactly two regions.
inline decomposition assemble_decomposition(const std::vector<madd_region>& regions) {
  decomposition d;
  number_vertices(regions, d);
  std::vector<std::size_t> region_of;
  const std::vector<std::vector<id_loop>> subs = numbered_loops(regions, d, region_of);
  std::map<index_pair, index_t> edge_interface;
  for (const auto& [sides, edges] : shared_interface_edges(subs))
    chain_interface_edges(sides, edges, d, edge_interface);
  for (index_t s = 0; s < subs.size(); ++s) {
    d.subdomains.push_back(make_subdomain(subs[s], s, d, edge_interface));
    d.subdomains.back().inner = inner_constraints(regions[region_of[s]], d);
  }
  return d;
}

} // namespace pdd::detail
