/// \file split.hpp
/// Implementation detail of MADD: one 2-way split of a region (dissertation 3.3-3.5 with the
/// dynamic refinement of 4.1, the smoothing of 4.2 and the repairs of 5.1).
///
/// For refinement levels r, 2r, 4r, ... the region's boundary is discretised, triangulated and
/// turned into the contracted MADD graph; the graph is bisected into two connected parts
/// (pdd::connected_bisection) and the cut faces become the separator (Algorithms 3.3 / 3.6).
/// A bisection is repaired and repeated (5.1) when two separator pieces would end at the same
/// boundary vertex: that would pinch a subdomain there (a polygon touching itself) and may
/// form an angle < Phi0 between them; all but the cheapest of those pieces are contracted.
/// The children are read off the cells of each part; refinement vertices that no separator
/// uses are dropped again, those it uses are reported so that the neighbour across the edge
/// gets them too.
#pragma once

#include <pdd/concepts/graph_partitioner.hpp>
#include <pdd/errors.hpp>
#include <pdd/madd/detail/children.hpp>
#include <pdd/madd/detail/chord_split.hpp>
#include <pdd/madd/detail/features.hpp>
#include <pdd/madd/detail/graph.hpp>
#include <pdd/madd/detail/region.hpp>
#include <pdd/madd/detail/split_result.hpp>
#include <pdd/madd/detail/triangulation.hpp>
#include <pdd/partition/connectivity.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace pdd::detail {

/// Part of every cell for a part of every node.
inline std::vector<std::uint8_t> cell_parts(const madd_graph& g,
                                            const std::vector<std::uint8_t>& node_part) {
  std::vector<std::uint8_t> part(g.cells.size());
  for (std::size_t c = 0; c < part.size(); ++c)
    part[c] = node_part[g.node[c]];
  return part;
}

inline bool is_cut(const madd_cell_face& f, const std::vector<std::uint8_t>& part) {
  return f.cuttable && part[f.a] != part[f.b];
}

/// Boundary vertices at which two or more cut faces end (they would pinch a child there).
inline std::vector<std::uint32_t> pinch_vertices(const madd_triangulation& tr, const madd_graph& g,
                                                 const std::vector<std::uint8_t>& part) {
  std::vector<std::uint8_t> count(tr.z.size(), 0);
  std::vector<std::uint32_t> bad;
  auto bump = [&](std::uint32_t z) {
    if (++count[z] == 2) bad.push_back(z);
  };
  for (const madd_cell_face& f : g.faces) {
    if (!is_cut(f, part)) continue;
    bump(f.z0);
    if (f.z1 != no_index) bump(f.z1);
  }
  return bad;
}

/// True if the nodes of part p other than `without` are connected in pg (and non-empty).
inline bool part_connected_without(const partition_graph& pg, const std::vector<std::uint8_t>& np,
                                   std::uint8_t p, std::size_t without) {
  const std::size_t n = boost::num_vertices(pg);
  std::size_t start = n, members = 0;
  for (std::size_t v = 0; v < n; ++v)
    if (np[v] == p && v != without) {
      if (start == n) start = v;
      ++members;
    }
  if (members == 0) return false;
  std::vector<char> seen(n, 0);
  std::vector<std::size_t> stack{start};
  seen[start] = 1;
  std::size_t reached = 1;
  while (!stack.empty()) {
    const std::size_t v = stack.back();
    stack.pop_back();
    for (const auto e : boost::make_iterator_range(boost::out_edges(v, pg))) {
      const std::size_t w = boost::target(e, pg);
      if (seen[w] || np[w] != p || w == without) continue;
      seen[w] = 1;
      ++reached;
      stack.push_back(w);
    }
  }
  return reached == members;
}

/// The part limits of the smoothing: o's, or with keep_balance those of the balance of the
/// part weights pw the partitioner reached (when tighter).
inline part_limits smoothing_limits(const bisection_options& o, const std::array<double, 2>& pw,
                                    double total, bool keep_balance) {
  const part_limits limits = part_weight_limits(o, total);
  if (!keep_balance) return limits;
  const double share[2] = {o.target_fraction, 1.0 - o.target_fraction};
  const double reached = std::max(pw[0] / share[0], pw[1] / share[1]);
  return {std::min(limits[0], reached * share[0]), std::min(limits[1], reached * share[1])};
}

/// Second smoothing step (4.2): moves single nodes across the cut while that lowers the
/// weighted separator cost (f0 f1 times the length), keeps both parts connected, keeps the
/// parts within `o`'s limits (or no further over them than before; MADD passes the
/// partitioner's own options) and pinches no child. With `keep_balance` (MADD into N, where the
/// quotas rest on the children's areas) the limits are those of the balance the partitioner
/// reached, so that the search trades no balance for length.
inline std::size_t smooth_bisection(const madd_triangulation& tr, const madd_graph& g,
                                    const partition_graph& pg, std::vector<std::uint8_t>& np,
                                    const bisection_options& o, bool keep_balance) {
  const std::size_t n = boost::num_vertices(pg);
  double total = 0.0;
  std::array<double, 2> pw{0.0, 0.0};
  for (std::size_t v = 0; v < n; ++v) {
    total += pg[v].weight;
    pw[np[v]] += pg[v].weight;
  }
  const part_limits limits = smoothing_limits(o, pw, total, keep_balance);
  std::size_t moves = 0;
  for (int pass = 0; pass < 4; ++pass) {
    bool improved = false;
    for (std::size_t x = 0; x < n; ++x) {
      const std::uint8_t p = np[x];
      double gain = 0.0, wsum = 0.0;
      for (const auto e : boost::make_iterator_range(boost::out_edges(x, pg))) {
        const double w = pg[e].weight;
        wsum += w;
        gain += np[boost::target(e, pg)] != p ? w : -w;
      }
      if (!(gain > 1e-12 * wsum)) continue;
      std::array<double, 2> after = pw;
      after[p] -= pg[x].weight;
      after[1 - p] += pg[x].weight;
      if (balance_excess(after, limits) > balance_excess(pw, limits)) continue;
      if (!part_connected_without(pg, np, p, x)) continue;
      np[x] = static_cast<std::uint8_t>(1 - p);
      if (!pinch_vertices(tr, g, cell_parts(g, np)).empty()) {
        np[x] = p;
        continue;
      }
      pw[p] -= pg[x].weight;
      pw[1 - p] += pg[x].weight;
      ++moves;
      improved = true;
    }
    if (!improved) break;
  }
  return moves;
}

/// Reads the two children off a bisection of the cells; false if a child is not a polygon
/// with holes (never expected after the pinch repairs).
inline bool extract_children(const madd_region& r, const madd_triangulation& tr,
                             const madd_graph& g, const std::vector<std::uint8_t>& part,
                             madd_split_result& out) {
  const auto nz = static_cast<std::uint32_t>(tr.z.size());
  const std::size_t nv = nz + tr.faces.size();
  part_boundary b{std::vector<std::uint32_t>(nv, no_index), std::vector<char>(nv, 0), {}};
  std::vector<char> used_by_separator(nz, 0);
  for (std::uint8_t p = 0; p < 2; ++p) {
    madd_region child;
    if (!link_part_boundary(tr, g, part, p, b, used_by_separator)) return false;
    if (!assemble_child(r, tr, g, b, child)) return false;
    out.children[p] = std::move(child);
  }
  out.kept.clear();
  for (std::uint32_t x = 0; x < nz; ++x) {
    const madd_zvertex& zx = tr.z[x];
    if (zx.original || !used_by_separator[x]) continue;
    const madd_loop& l = r.loops[zx.loop];
    const point a = l.points[zx.edge], b2 = l.points[(zx.edge + 1) % l.size()];
    out.kept.push_back({std::min(a, b2), std::max(a, b2), zx.t, zx.p, zx.marker});
  }
  return true;
}

/// Length and smallest angle of the separator of a bisection.
inline void separator_measures(const madd_triangulation& tr, const madd_graph& g,
                               const std::vector<std::uint8_t>& part, madd_split_result& out) {
  out.separator_length = 0.0;
  out.min_angle = 180.0;
  std::vector<int> first_cut(tr.faces.size(), -1);
  for (std::size_t i = 0; i < g.faces.size(); ++i) {
    const madd_cell_face& f = g.faces[i];
    if (!is_cut(f, part)) continue;
    out.separator_length += f.length;
    out.min_angle = std::min(out.min_angle, f.min_angle);
    if (f.tri == no_index) continue;
    if (first_cut[f.tri] < 0) {
      first_cut[f.tri] = static_cast<int>(i);
    } else {
      const madd_cell_face& h = g.faces[first_cut[f.tri]];
      out.min_angle =
          std::min(out.min_angle, angle_deg(g.info[f.tri].c, tr.z[f.z0].p, tr.z[h.z0].p));
    }
  }
}

/// Repair 5.1 of a bisection with pinch vertices `bad` (several cut pieces end there): at
/// every such vertex all cut faces but the cheapest become uncuttable (contracted next).
inline void keep_cheapest_cut_pieces(madd_graph& g, const std::vector<std::uint8_t>& part,
                                     const std::vector<std::uint32_t>& bad) {
  for (const std::uint32_t z : bad) {
    std::int64_t keep = -1;
    for (std::size_t i = 0; i < g.faces.size(); ++i) {
      const madd_cell_face& f = g.faces[i];
      if (!is_cut(f, part) || (f.z0 != z && f.z1 != z)) continue;
      if (keep < 0 || f.weight < g.faces[keep].weight) keep = static_cast<std::int64_t>(i);
    }
    for (std::size_t i = 0; i < g.faces.size(); ++i) {
      madd_cell_face& f = g.faces[i];
      if (static_cast<std::int64_t>(i) != keep && is_cut(f, part) && (f.z0 == z || f.z1 == z))
        f.cuttable = false;
    }
  }
}

/// Bisects the contracted graph with repairs; on success fills out (children, measures).
template <GraphPartitioner P>
bool bisect_region(const madd_region& r, const madd_triangulation& tr, madd_graph& g,
                   const madd_split_options& o, const P& partitioner, madd_split_result& out) {
  const bisection_options bo{o.max_part_fraction, o.seed, target_share(o.quota)};
  for (int attempt = 0; attempt <= o.max_repairs; ++attempt) {
    if (g.nodes < 2) {
      out.failure = "every candidate separator was contracted by the repairs";
      return false;
    }
    const partition_graph pg = contracted_graph(g);
    std::vector<std::uint8_t> np = connected_bisection(pg, partitioner, bo);
    if (o.graph.smoothing) out.smoothing_moves += smooth_bisection(tr, g, pg, np, bo, o.quota >= 2);
    const std::vector<std::uint8_t> part = cell_parts(g, np);
    const std::vector<std::uint32_t> bad = pinch_vertices(tr, g, part);
    if (bad.empty()) {
      if (!extract_children(r, tr, g, part, out)) {
        out.failure = "a child is not a polygon with holes";
        return false;
      }
      separator_measures(tr, g, part, out);
      out.graph_nodes = g.nodes;
      return true;
    }
    // 5.1: contract all but the cheapest cut piece at every vertex where several end.
    ++out.repairs;
    keep_cheapest_cut_pieces(g, part, bad);
    contract(g);
  }
  out.failure = "the repairs did not converge";
  return false;
}

/// One refinement level of split_region: the region triangulated at spacing
/// o.target_length * 2^-level, its graph (algorithm 1 without junction triangles falls back
/// to algorithm 2 on this triangulation), and a bisection with repairs. ok is false, with
/// failure set, when the level gives no acceptable separator.
template <GraphPartitioner P>
madd_split_result split_at_level(const madd_region& r, const madd_split_options& o,
                                 const P& partitioner, int level) {
  const double h = std::ldexp(o.target_length, -level);
  madd_split_result cur;
  cur.level = level;
  if (z_point_count(r, h) > max_z_points) {
    cur.failure = too_many_z_points(h);
    return cur;
  }
  const madd_triangulation tr = triangulate_region(r, h, o.max_encroachment_depth);
  madd_graph g = build_madd_graph(tr, o.graph);
  if (o.graph.algorithm == 1 && g.junctions == 0) {
    // No junction triangle at all (an exactly symmetric boundary, e.g. a refined square,
    // has only right-angled Delaunay triangles at every level): use algorithm 2's
    // Delaunay-edge separators on this triangulation.
    madd_graph_options go = o.graph;
    go.algorithm = 2;
    g = build_madd_graph(tr, go);
    cur.fallback = true;
  }
  // no separator within max(h, clearance) of a feature
  forbid_cuts_near_features(r, tr, g, std::max(h, o.feature_clearance));
  cur.z_points = tr.z.size();
  cur.junctions = g.junctions;
  if (g.nodes < 2) {
    cur.failure = "no acceptable separator (" + std::to_string(g.junctions) +
                  " junction triangles, " + std::to_string(tr.z.size()) +
                  " boundary points) after " + std::to_string(level + 1) + " refinement levels";
    return cur;
  }
  if (!bisect_region(r, tr, g, o, partitioner, cur)) {
    cur.failure += " (refinement level " + std::to_string(level) + ")";
    return cur;
  }
  distribute_features(r, cur.children);
  cur.ok = true;
  cur.max_fraction = split_balance(cur.children[0].area, cur.children[1].area, o.quota);
  return cur;
}

/// The medial-axis split of a region (one MADD step with dynamic refinement, algorithm 2 when
/// algorithm 1 finds nothing): refinement levels until a split's balance is within
/// accepted_balance, at most extra_levels after the first valid split; the best balanced one
/// is kept.
template <GraphPartitioner P>
madd_split_result medial_axis_split(const madd_region& r, const madd_split_options& o,
                                    const P& partitioner) {
  madd_split_result best;
  best.failure = "no refinement level was tried";
  int stop_level = o.max_levels;
  for (int level = 0; level < stop_level; ++level) {
    ++best.levels_tried;
    madd_split_result cur = split_at_level(r, o, partitioner, level);
    if (!cur.ok) {
      if (!best.ok) best.failure = std::move(cur.failure);
      continue;
    }
    cur.levels_tried = best.levels_tried;
    if (!best.ok || cur.max_fraction < best.max_fraction) best = std::move(cur);
    if (best.max_fraction <= accepted_balance(o)) break;
    if (best.max_fraction <= o.imbalance_bound && best.graph_nodes >= coarse_graph_nodes) break;
    stop_level = std::min(stop_level, level + 1 + o.extra_levels);
  }
  if (!best.ok && o.graph.algorithm == 1) {
    // Algorithm 1 cuts only through junction triangles; an exactly symmetric boundary (a
    // refined square: every Delaunay triangle right-angled) has none at any level. The
    // second algorithm's Delaunay-edge separators split such regions.
    madd_split_options o2 = o;
    o2.graph.algorithm = 2;
    madd_split_result r2 = medial_axis_split(r, o2, partitioner);
    r2.levels_tried += best.levels_tried;
    r2.fallback = true;
    if (!r2.ok) r2.failure = best.failure + "; algorithm 2: " + r2.failure;
    return r2;
  }
  return best;
}

/// Splits a region in two: the medial-axis split, else (features block every medial-axis
/// separator) the straight-chord split of chord_split.hpp. Deterministic: a pure function of
/// (r, o) for a deterministic partitioner. Thread-safe when the partitioner is. Never throws
/// for a region that cannot be split: ok is false and failure says why.
template <GraphPartitioner P>
madd_split_result split_region(const madd_region& r, const madd_split_options& o,
                               const P& partitioner) {
  madd_split_result res = medial_axis_split(r, o, partitioner);
  if (res.ok || r.features.empty()) return res;
  madd_split_result chord = chord_split(r, o);
  chord.levels_tried += res.levels_tried;
  if (!chord.ok) chord.failure = res.failure + "; " + chord.failure;
  return chord;
}

} // namespace pdd::detail
