// Benchmark of the Medial Axis Domain Decomposition against a plain METIS partition of a
// background Delaunay mesh (dissertation 5.2, Figures 5.2 and 5.4-5.9); not a test. One run per
// call, one JSON line on stdout:
//
//   bench_madd key|pipe|FILE.poly madd|metis N [THREADS [REPEATS]]
//
// Each run is timed REPEATS times (default 1) and the fastest is reported (wall clock).
// madd:  pdd::decompose into N subdomains (madd_options::threads = THREADS), checked with
//        pdd::validate_decomposition (valid); digest hashes the result bit for bit.
// metis: the domain meshed by pdd::cgal::mesher at area bound A / (120 N * 0.656) (about 120
//        triangles per part), its triangle dual graph (vertex weight = triangle area, edge
//        weight = shared edge length) split by METIS_PartGraphKway into N parts. time_s
//        includes the meshing (as the dissertation's Figure 5.6 does). THREADS must be 1.
//        METIS does not promise connected parts: valid means every part is edge-connected.
//
// Angles (both methods, the same definition): the subdomains' boundaries form a planar graph
// (input segments and interface edges). A *corner* is a maximal angular sector of one subdomain
// at one vertex between two consecutive edges of that graph, measured inside the subdomain. A
// corner counts when one of its two edges is an interface edge. *Junction* corners are those at
// vertices of degree >= 3 (a separator meets the boundary or other separators): min_angle,
// median_angle, q90_angle and below_60 are over them. *Bends* are corners at degree-2 vertices
// inside one interface chain (the turn at a circumcentre in MADD, the zigzag of a mesh-edge
// partition boundary): min_angle_all is the minimum over junctions and bends together (what a
// mesher meeting the subdomain sees; pdd::validate_decomposition checks the same set).
//
// benchmarks/run_madd.sh runs the table in benchmarks/results/madd.md.
#include <pdd/core/triangle_measures.hpp>
#include <pdd/geometry/loops.hpp>
#include <pdd/geometry/model_domains.hpp>
#include <pdd/io/poly.hpp>
#include <pdd/kernels/cgal/mesher.hpp>
#include <pdd/madd/decompose.hpp>
#include <pdd/madd/detail/region.hpp>
#include <pdd/madd/validate_decomposition.hpp>
#include <pdd/partition/default_partitioner.hpp>
#include <pdd/pipeline/system.hpp>
#include <pdd/sizing/uniform.hpp>

#ifdef PDD_HAVE_METIS
#include <metis.h>
#endif
#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <limits>
#include <map>
#include <numbers>
#include <numeric>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

namespace {

using pdd::index_t;
using pdd::point;
using clock_type = std::chrono::steady_clock;

/// One corner of a subdomain at a vertex (see the file comment).
struct corner {
  double angle_deg;
  bool junction; ///< at a vertex of degree >= 3 in the boundary+interface graph
};

/// The quantities of one partition, whatever produced it.
struct partition_measures {
  std::vector<corner> corners;
  std::vector<double> part_area;     ///< per subdomain
  std::vector<double> interface_len; ///< per subdomain: its interface edges
};

std::uint64_t edge_key(index_t a, index_t b) {
  return (static_cast<std::uint64_t>(std::min(a, b)) << 32) | std::max(a, b);
}

double quantile(std::vector<double> v, double q) {
  if (v.empty()) return std::numeric_limits<double>::quiet_NaN();
  std::sort(v.begin(), v.end());
  const double pos = q * static_cast<double>(v.size() - 1);
  const auto lo = static_cast<std::size_t>(std::floor(pos));
  const std::size_t hi = std::min(lo + 1, v.size() - 1);
  return v[lo] + (pos - static_cast<double>(lo)) * (v[hi] - v[lo]);
}

/// Fills the JSON fields shared by both methods from m.
void report_measures(const partition_measures& m, nlohmann::json& j) {
  std::vector<double> junction;
  double min_all = 180.0;
  std::size_t bends = 0;
  for (const corner& c : m.corners) {
    min_all = std::min(min_all, c.angle_deg);
    if (c.junction)
      junction.push_back(c.angle_deg);
    else
      ++bends;
  }
  const double n = static_cast<double>(m.part_area.size());
  const double total = std::accumulate(m.part_area.begin(), m.part_area.end(), 0.0);
  const double amax = *std::max_element(m.part_area.begin(), m.part_area.end());
  const double sep = std::accumulate(m.interface_len.begin(), m.interface_len.end(), 0.0) / n;
  j["min_angle"] = junction.empty() ? 180.0 : quantile(junction, 0.0);
  j["median_angle"] = quantile(junction, 0.5);
  j["q90_angle"] = quantile(junction, 0.9);
  j["junction_corners"] = junction.size();
  j["below_60"] =
      std::count_if(junction.begin(), junction.end(), [](double a) { return a < 60.0; });
  j["bend_corners"] = bends;
  j["min_angle_all"] = min_all;
  j["max_over_mean"] = amax / (total / n);
  j["sep_len_per_subdomain"] = sep;
  j["sep_len_rel"] = sep / std::sqrt(total / n); // per sqrt(mean area): scale-free
}

// ---------------------------------------------------------------------------------------------
// MADD

/// Corners, areas and interface lengths of a MADD decomposition.
partition_measures measure_madd(const pdd::decomposition& d) {
  std::map<std::uint64_t, char> edges; // every boundary/interface edge once
  for (const auto& sd : d.subdomains)
    for (const auto& loop : sd.loops)
      for (std::size_t i = 0; i < loop.size(); ++i)
        edges.emplace(edge_key(loop[i], loop[(i + 1) % loop.size()]), 0);
  std::vector<int> degree(d.vertices.size(), 0);
  for (const auto& [key, unused] : edges) {
    ++degree[key >> 32];
    ++degree[key & 0xffffffffU];
  }
  partition_measures m;
  for (const auto& sd : d.subdomains) {
    m.part_area.push_back(sd.area);
    double len = 0.0;
    for (std::size_t l = 0; l < sd.loops.size(); ++l) {
      const auto& loop = sd.loops[l];
      const std::size_t k = loop.size();
      for (std::size_t i = 0; i < k; ++i) {
        const bool out_if = sd.tags[l][i].type == pdd::edge_tag::kind::interface;
        const bool in_if = sd.tags[l][(i + k - 1) % k].type == pdd::edge_tag::kind::interface;
        const point prev = d.vertices[loop[(i + k - 1) % k]], v = d.vertices[loop[i]],
                    next = d.vertices[loop[(i + 1) % k]];
        if (out_if) len += pdd::detail::distance(v, next);
        if (out_if || in_if)
          m.corners.push_back(
              {pdd::detail::interior_angle_deg(prev, v, next), degree[loop[i]] >= 3});
      }
    }
    m.interface_len.push_back(len);
  }
  return m;
}

/// FNV-1a over the vertex coordinates (bits) and the subdomain loops: equal digests for the
/// thread counts show the bitwise-identical result.
std::uint64_t digest(const pdd::decomposition& d) {
  std::uint64_t h = 1469598103934665603ULL;
  auto mix = [&h](std::uint64_t x) {
    for (int b = 0; b < 8; ++b) {
      h ^= (x >> (8 * b)) & 0xffU;
      h *= 1099511628211ULL;
    }
  };
  for (const point& p : d.vertices) {
    std::uint64_t x = 0, y = 0;
    std::memcpy(&x, &p.x, sizeof x);
    std::memcpy(&y, &p.y, sizeof y);
    mix(x);
    mix(y);
  }
  for (const auto& sd : d.subdomains)
    for (const auto& loop : sd.loops) {
      mix(loop.size());
      for (const index_t v : loop)
        mix(v);
    }
  return h;
}

nlohmann::json run_madd(const pdd::pslg& g, std::size_t n, unsigned threads, int repeats) {
  pdd::madd_options o;
  o.subdomains = n;
  o.threads = threads;
  pdd::decomposition d;
  pdd::decomposition_statistics st;
  double best = std::numeric_limits<double>::infinity();
  for (int r = 0; r < repeats; ++r) {
    const auto t0 = clock_type::now();
    d = pdd::decompose(g, o, pdd::default_partitioner{}, &st);
    best = std::min(best, pdd::seconds_since(t0));
  }
  const pdd::decomposition_report rep = pdd::validate_decomposition(d, g);
  nlohmann::json j;
  j["time_s"] = best;
  j["valid"] = rep.ok() && d.subdomains.size() == n;
  report_measures(measure_madd(d), j);
  j["splits"] = st.splits;
  j["repairs"] = st.repairs;
  j["boundary_points"] = st.boundary_points;
  j["digest"] = std::to_string(digest(d));
  if (!rep.ok()) j["problems"] = rep.summary();
  return j;
}

// ---------------------------------------------------------------------------------------------
// METIS on a background Delaunay mesh
#ifdef PDD_HAVE_METIS

using tri_list = std::vector<std::array<index_t, 3>>;

/// Triangle pairs sharing an edge ({t, u}, edge a-b) and the edges of one triangle only.
struct mesh_edges {
  std::vector<std::array<index_t, 4>> inner;    ///< t, u, a, b
  std::vector<std::array<index_t, 3>> boundary; ///< t, a, b
};

mesh_edges edges_of(const tri_list& tris) {
  std::vector<std::pair<std::uint64_t, index_t>> e;
  e.reserve(3 * tris.size());
  for (std::size_t t = 0; t < tris.size(); ++t)
    for (int k = 0; k < 3; ++k)
      e.emplace_back(edge_key(tris[t][k], tris[t][(k + 1) % 3]), static_cast<index_t>(t));
  std::sort(e.begin(), e.end());
  mesh_edges out;
  for (std::size_t i = 0; i < e.size();) {
    const auto a = static_cast<index_t>(e[i].first >> 32);
    const auto b = static_cast<index_t>(e[i].first & 0xffffffffU);
    if (i + 1 < e.size() && e[i + 1].first == e[i].first) {
      out.inner.push_back({e[i].second, e[i + 1].second, a, b});
      i += 2;
    } else {
      out.boundary.push_back({e[i].second, a, b});
      i += 1;
    }
  }
  return out;
}

double tri_area(const pdd::triangle_mesh& m, const std::array<index_t, 3>& t) {
  return pdd::detail::triangle_area(m.vertices[t[0]], m.vertices[t[1]], m.vertices[t[2]]);
}

/// METIS_PartGraphKway on the dual graph: vertex weight = area, edge weight = edge length.
std::vector<idx_t> metis_parts(const pdd::triangle_mesh& m, const mesh_edges& me, idx_t nparts) {
  const std::size_t nt = m.triangles.size();
  double mean_area = 0.0, mean_len = 0.0;
  for (const auto& t : m.triangles)
    mean_area += tri_area(m, t) / static_cast<double>(nt);
  for (const auto& e : me.inner)
    mean_len += pdd::detail::distance(m.vertices[e[2]], m.vertices[e[3]]) /
                static_cast<double>(me.inner.size());
  std::vector<std::vector<std::pair<idx_t, idx_t>>> adj(nt);
  for (const auto& e : me.inner) {
    const double len = pdd::detail::distance(m.vertices[e[2]], m.vertices[e[3]]);
    const auto w = std::max<idx_t>(1, static_cast<idx_t>(std::llround(100.0 * len / mean_len)));
    adj[e[0]].emplace_back(static_cast<idx_t>(e[1]), w);
    adj[e[1]].emplace_back(static_cast<idx_t>(e[0]), w);
  }
  std::vector<idx_t> xadj{0}, adjncy, adjwgt, vwgt;
  for (std::size_t t = 0; t < nt; ++t) {
    for (const auto& [u, w] : adj[t]) {
      adjncy.push_back(u);
      adjwgt.push_back(w);
    }
    xadj.push_back(static_cast<idx_t>(adjncy.size()));
    vwgt.push_back(std::max<idx_t>(
        1, static_cast<idx_t>(std::llround(1000.0 * tri_area(m, m.triangles[t]) / mean_area))));
  }
  idx_t nv = static_cast<idx_t>(nt), ncon = 1, cut = 0;
  idx_t options[METIS_NOPTIONS];
  METIS_SetDefaultOptions(options);
  options[METIS_OPTION_SEED] = 1;
  std::vector<idx_t> part(nt, 0);
  if (METIS_PartGraphKway(&nv, &ncon, xadj.data(), adjncy.data(), vwgt.data(), nullptr,
                          adjwgt.data(), &nparts, nullptr, nullptr, options, &cut,
                          part.data()) != METIS_OK)
    throw pdd::internal_error("METIS_PartGraphKway failed");
  return part;
}

/// Union-find over triangle corners (3 t + k).
struct corner_sets {
  std::vector<std::size_t> parent;
  explicit corner_sets(std::size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0); }
  std::size_t find(std::size_t x) {
    while (parent[x] != x)
      x = parent[x] = parent[parent[x]];
    return x;
  }
  void unite(std::size_t a, std::size_t b) { parent[find(a)] = find(b); }
};

std::size_t corner_of(const tri_list& tris, index_t t, index_t v) {
  const auto& tr = tris[t];
  return 3 * static_cast<std::size_t>(t) + (tr[0] == v ? 0 : tr[1] == v ? 1 : 2);
}

/// The triangle corners of a partition joined across edges inside a part, the number of
/// interface and boundary edges at every vertex, the interface edges at every corner.
struct partition_corners {
  corner_sets cs;
  std::vector<int> degree;      ///< per vertex: interface and boundary edges
  std::vector<int> iface_sides; ///< per corner: interface edges of its triangle at it
};

/// Joins corners across the inner edges within a part and counts interface and boundary edges;
/// adds each interface edge's length to r.interface_len of both its parts.
partition_corners join_partition_corners(const pdd::triangle_mesh& m, const mesh_edges& me,
                                         const std::vector<idx_t>& part, partition_measures& r) {
  const tri_list& tris = m.triangles;
  partition_corners pc{corner_sets(3 * tris.size()), std::vector<int>(m.vertices.size(), 0),
                       std::vector<int>(3 * tris.size(), 0)};
  for (const auto& [t, u, a, b] : me.inner) {
    if (part[t] == part[u]) {
      pc.cs.unite(corner_of(tris, t, a), corner_of(tris, u, a));
      pc.cs.unite(corner_of(tris, t, b), corner_of(tris, u, b));
      continue;
    }
    ++pc.degree[a];
    ++pc.degree[b];
    for (const index_t v : {a, b}) {
      ++pc.iface_sides[corner_of(tris, t, v)];
      ++pc.iface_sides[corner_of(tris, u, v)];
    }
    const double len = pdd::detail::distance(m.vertices[a], m.vertices[b]);
    r.interface_len[part[t]] += len;
    r.interface_len[part[u]] += len;
  }
  for (const auto& [t, a, b] : me.boundary) {
    ++pc.degree[a];
    ++pc.degree[b];
  }
  return pc;
}

/// Corners, areas and interface lengths of a triangle partition: the corners of one part at a
/// vertex are the triangle corners joined across edges inside the part.
partition_measures measure_metis(const pdd::triangle_mesh& m, const mesh_edges& me,
                                 const std::vector<idx_t>& part, std::size_t n) {
  const tri_list& tris = m.triangles;
  partition_measures r;
  r.interface_len.assign(n, 0.0);
  r.part_area.assign(n, 0.0);
  partition_corners pc = join_partition_corners(m, me, part, r);
  std::vector<double> angle(3 * tris.size(), 0.0);
  std::vector<int> set_iface(3 * tris.size(), 0);
  for (std::size_t t = 0; t < tris.size(); ++t) {
    r.part_area[part[t]] += tri_area(m, tris[t]);
    for (int k = 0; k < 3; ++k) {
      const std::size_t c = 3 * t + k, s = pc.cs.find(c);
      angle[s] += pdd::detail::angle_deg(m.vertices[tris[t][k]], m.vertices[tris[t][(k + 1) % 3]],
                                         m.vertices[tris[t][(k + 2) % 3]]);
      set_iface[s] += pc.iface_sides[c];
    }
  }
  for (std::size_t t = 0; t < tris.size(); ++t)
    for (int k = 0; k < 3; ++k) {
      const std::size_t c = 3 * t + k;
      if (pc.cs.find(c) == c && set_iface[c] > 0)
        r.corners.push_back({angle[c], pc.degree[tris[t][k]] >= 3});
    }
  return r;
}

/// Parts that are not edge-connected (or empty).
std::size_t disconnected_parts(const mesh_edges& me, const std::vector<idx_t>& part,
                               std::size_t n) {
  corner_sets cs(part.size());
  for (const auto& e : me.inner)
    if (part[e[0]] == part[e[1]]) cs.unite(e[0], e[1]);
  std::vector<std::vector<std::size_t>> roots(n);
  for (std::size_t t = 0; t < part.size(); ++t)
    roots[part[t]].push_back(cs.find(t));
  std::size_t bad = 0;
  for (auto& r : roots) {
    std::sort(r.begin(), r.end());
    bad += std::unique(r.begin(), r.end()) - r.begin() != 1 ? 1 : 0;
  }
  return bad;
}

nlohmann::json run_metis(const pdd::pslg& g, std::size_t n, int repeats) {
  pdd::mesh_criteria criteria;
  criteria.max_area = pdd::domain_area(g) / (120.0 * static_cast<double>(n) * 0.656);
  pdd::mesher_result mesh;
  mesh_edges me;
  std::vector<idx_t> part;
  double mesh_s = std::numeric_limits<double>::infinity(), part_s = mesh_s, best = mesh_s;
  for (int r = 0; r < repeats; ++r) {
    const auto t0 = clock_type::now();
    mesh = pdd::cgal::mesher{}.mesh(g, criteria, pdd::uniform_sizing{criteria.max_area});
    const double ms = pdd::seconds_since(t0);
    const auto t1 = clock_type::now();
    me = edges_of(mesh.mesh.triangles);
    part = metis_parts(mesh.mesh, me, static_cast<idx_t>(n));
    const double ps = pdd::seconds_since(t1);
    if (ms + ps < best) std::tie(best, mesh_s, part_s) = std::tuple(ms + ps, ms, ps);
  }
  const std::size_t bad = disconnected_parts(me, part, n);
  nlohmann::json j;
  j["time_s"] = best;
  j["valid"] = bad == 0;
  report_measures(measure_metis(mesh.mesh, me, part, n), j);
  j["mesh_s"] = mesh_s;
  j["partition_s"] = part_s;
  j["triangles"] = mesh.mesh.triangles.size();
  j["disconnected_parts"] = bad;
  return j;
}
#else
nlohmann::json run_metis(const pdd::pslg&, std::size_t, int) {
  throw pdd::error("bench_madd was built without METIS (PDD_HAVE_METIS undefined)");
}
#endif

pdd::pslg load(const std::string& name) {
  if (name == "key") return pdd::key_domain();
  if (name == "pipe") return pdd::pipe_domain();
  return pdd::read_poly(name);
}

} // namespace

int main(int argc, char** argv) {
  if (argc < 4) {
    std::fprintf(stderr, "usage: %s key|pipe|FILE.poly madd|metis N [THREADS [REPEATS]]\n",
                 argv[0]);
    return 2;
  }
  try {
    const std::string name = argv[1], method = argv[2];
    const auto n = static_cast<std::size_t>(std::atol(argv[3]));
    const unsigned threads = argc > 4 ? static_cast<unsigned>(std::atoi(argv[4])) : 1;
    const int repeats = argc > 5 ? std::max(1, std::atoi(argv[5])) : 1;
    if (n < 1 || (method != "madd" && method != "metis") || (method == "metis" && threads != 1))
      throw pdd::error("bad arguments (metis runs with THREADS = 1 only)");
    const pdd::pslg g = load(name);
    nlohmann::json j;
    j["domain"] = std::filesystem::path(name).stem().string();
    j["method"] = method;
    j["N"] = n;
    j["threads"] = threads;
    nlohmann::json r =
        method == "madd" ? run_madd(g, n, threads, repeats) : run_metis(g, n, repeats);
    j.update(r);
    j["peak_rss_mib"] = pdd::peak_rss_mib();
    std::cout << j.dump() << std::endl;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "bench_madd: %s\n", e.what());
    return 1;
  }
  return 0;
}
