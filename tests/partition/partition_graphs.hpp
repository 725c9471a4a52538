// Graphs for the partition tests: families with known optimal cuts, random planar-ish graphs,
// MADD-like weighted dual graphs of Delaunay triangulations, and an independent check that a
// bisection has two connected non-empty parts.
#pragma once

#include <pdd/concepts/graph_partitioner.hpp>
#include <pdd/core/kernel.hpp>
#include <pdd/triangulation/constrained_delaunay_2.hpp>

#include <boost/graph/connected_components.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <deque>
#include <map>
#include <random>
#include <vector>

namespace pdd::test {

inline void add(partition_graph& g, std::size_t u, std::size_t v, double w = 1.0) {
  boost::add_edge(u, v, partition_edge{w}, g);
}

inline partition_graph with_vertices(std::size_t n, double w = 1.0) {
  partition_graph g(n);
  for (std::size_t v = 0; v < n; ++v)
    g[v].weight = w;
  return g;
}

/// Two k-cliques (unit edges) joined by one edge of weight `bridge` between k-1 and k.
inline partition_graph two_cliques(std::size_t k, double bridge, double edge = 1.0) {
  partition_graph g = with_vertices(2 * k);
  for (std::size_t c = 0; c < 2; ++c)
    for (std::size_t i = 0; i < k; ++i)
      for (std::size_t j = i + 1; j < k; ++j)
        add(g, c * k + i, c * k + j, edge);
  add(g, k - 1, k, bridge);
  return g;
}

inline partition_graph path_graph(std::size_t n) {
  partition_graph g = with_vertices(n);
  for (std::size_t v = 0; v + 1 < n; ++v)
    add(g, v, v + 1);
  return g;
}

inline partition_graph ring_graph(std::size_t n) {
  partition_graph g = path_graph(n);
  add(g, n - 1, 0);
  return g;
}

/// w x h grid, vertex (x, y) = y * w + x, unit weights.
inline partition_graph grid_graph(std::size_t w, std::size_t h) {
  partition_graph g = with_vertices(w * h);
  for (std::size_t y = 0; y < h; ++y)
    for (std::size_t x = 0; x < w; ++x) {
      if (x + 1 < w) add(g, y * w + x, y * w + x + 1);
      if (y + 1 < h) add(g, y * w + x, (y + 1) * w + x);
    }
  return g;
}

/// Number of parts of `part` that are non-empty and connected (2 for a connected bisection),
/// by a plain BFS (independent of the library's Boost-based check).
inline int connected_nonempty_parts(const partition_graph& g,
                                    const std::vector<std::uint8_t>& part) {
  int good = 0;
  for (std::uint8_t side = 0; side < 2; ++side) {
    const auto first = std::find(part.begin(), part.end(), side);
    if (first == part.end()) continue;
    std::vector<char> seen(part.size(), 0);
    std::deque<std::size_t> queue{static_cast<std::size_t>(first - part.begin())};
    seen[queue.front()] = 1;
    std::size_t reached = 0;
    while (!queue.empty()) {
      const std::size_t v = queue.front();
      queue.pop_front();
      ++reached;
      for (const auto e : boost::make_iterator_range(boost::out_edges(v, g))) {
        const std::size_t t = boost::target(e, g);
        if (part[t] == side && !seen[t]) seen[t] = 1, queue.push_back(t);
      }
    }
    if (reached == static_cast<std::size_t>(std::count(part.begin(), part.end(), side))) ++good;
  }
  return good;
}

/// The subgraph of the largest connected component, vertices renumbered in order.
inline partition_graph largest_component(const partition_graph& g) {
  std::vector<std::size_t> comp(boost::num_vertices(g));
  const std::size_t count = boost::connected_components(g, comp.data());
  std::vector<std::size_t> size(count, 0);
  for (const std::size_t c : comp)
    ++size[c];
  const std::size_t keep =
      static_cast<std::size_t>(std::max_element(size.begin(), size.end()) - size.begin());
  std::vector<std::size_t> id(comp.size(), 0);
  partition_graph out;
  for (std::size_t v = 0; v < comp.size(); ++v)
    if (comp[v] == keep) {
      id[v] = boost::add_vertex(out);
      out[id[v]].weight = g[v].weight;
    }
  for (const auto e : boost::make_iterator_range(boost::edges(g))) {
    const std::size_t u = boost::source(e, g), v = boost::target(e, g);
    if (comp[u] == keep && comp[v] == keep) add(out, id[u], id[v], g[e].weight);
  }
  return out;
}

/// Random planar-ish graph: a w x h grid with random diagonals, random holes (disks of removed
/// vertices) and randomly deleted edges, random weights; its largest component.
inline partition_graph random_holey_grid(std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  const std::size_t w = 6 + rng() % 20, h = 6 + rng() % 20;
  const double deletion = 0.05 + 0.3 * u01(rng);
  std::vector<char> removed(w * h, 0);
  for (std::size_t hole = rng() % 4; hole-- > 0;) {
    const double cx = u01(rng) * w, cy = u01(rng) * h, r = 1.0 + u01(rng) * 0.2 * w;
    for (std::size_t v = 0; v < w * h; ++v)
      if (std::hypot(double(v % w) - cx, double(v / w) - cy) < r) removed[v] = 1;
  }
  partition_graph g(w * h);
  for (std::size_t v = 0; v < w * h; ++v)
    g[v].weight = 0.2 + 1.6 * u01(rng);
  auto maybe_add = [&](std::size_t a, std::size_t b) {
    if (!removed[a] && !removed[b] && u01(rng) >= deletion) add(g, a, b, 0.1 + u01(rng));
  };
  for (std::size_t y = 0; y < h; ++y)
    for (std::size_t x = 0; x < w; ++x) {
      const std::size_t v = y * w + x;
      if (x + 1 < w) maybe_add(v, v + 1);
      if (y + 1 < h) maybe_add(v, v + w);
      if (x + 1 < w && y + 1 < h && u01(rng) < 0.5)
        rng() % 2 ? maybe_add(v, v + w + 1) : maybe_add(v + 1, v + w);
    }
  return largest_component(g);
}

/// MADD-like graph: the dual of the Delaunay triangulation of n random points in the unit
/// square (vertex = triangle, weight = its area; edge = shared side, weight = its length), then
/// a fraction of random dual edges contracted (merged triangles; parallel edges remain, as in
/// the contracted MADD graph of dissertation 3.5).
inline partition_graph madd_like_graph(std::size_t n, double contract_fraction,
                                       std::uint64_t seed) {
  using K = pdd::epick;
  using DT = pdd::constrained_delaunay_2<>; // no constraint: the Delaunay triangulation
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  DT dt;
  for (std::size_t i = 0; i < n; ++i)
    dt.insert(K::Point_2(u01(rng), u01(rng)));
  // Triangles and dual edges in a canonical order (CGAL's storage order may vary), so that the
  // graph depends only on (n, contract_fraction, seed).
  using key = std::array<K::Point_2, 3>;
  auto face_key = [](DT::Face_handle f) {
    key k{f->vertex(0)->point(), f->vertex(1)->point(), f->vertex(2)->point()};
    std::sort(k.begin(), k.end());
    return k;
  };
  std::map<key, DT::Face_handle> faces;
  for (auto f = dt.finite_faces_begin(); f != dt.finite_faces_end(); ++f)
    faces[face_key(f)] = f;
  std::map<key, std::size_t> id;
  std::vector<double> area;
  for (const auto& [k, f] : faces) {
    id[k] = area.size();
    area.push_back(std::abs(CGAL::area(k[0], k[1], k[2])));
  }
  std::vector<std::size_t> rep(area.size()); // union-find of contracted triangles
  for (std::size_t i = 0; i < rep.size(); ++i)
    rep[i] = i;
  auto find = [&](std::size_t i) {
    while (rep[i] != i)
      i = rep[i] = rep[rep[i]];
    return i;
  };
  struct dual_edge {
    std::size_t a, b;
    double length;
    bool operator<(const dual_edge& o) const { return a != o.a ? a < o.a : b < o.b; }
  };
  std::vector<dual_edge> all;
  for (auto e = dt.finite_edges_begin(); e != dt.finite_edges_end(); ++e) {
    const auto f = e->first, h = f->neighbor(e->second);
    if (dt.is_infinite(f) || dt.is_infinite(h)) continue;
    const std::size_t a = id.at(face_key(f)), b = id.at(face_key(h));
    all.push_back({std::min(a, b), std::max(a, b),
                   std::sqrt(CGAL::squared_distance(f->vertex(DT::ccw(e->second))->point(),
                                                    f->vertex(DT::cw(e->second))->point()))});
  }
  std::sort(all.begin(), all.end());
  std::vector<dual_edge> edges;
  for (const dual_edge& e : all) {
    if (u01(rng) < contract_fraction)
      rep[find(e.a)] = find(e.b);
    else
      edges.push_back(e);
  }
  std::vector<std::size_t> vid(area.size(), static_cast<std::size_t>(-1));
  partition_graph out;
  for (std::size_t i = 0; i < area.size(); ++i)
    if (find(i) == i) vid[i] = boost::add_vertex(out);
  for (std::size_t i = 0; i < area.size(); ++i)
    out[vid[find(i)]].weight += area[i];
  for (const dual_edge& e : edges)
    if (find(e.a) != find(e.b)) add(out, vid[find(e.a)], vid[find(e.b)], e.length);
  return largest_component(out);
}

} // namespace pdd::test
