/// \file tiny_features.hpp
/// The tiny features that drive the geometric loop's decompositions (pdd::geometric_decompose):
/// the input vertices whose own feature gap is smaller than the mesh there, on a domain of
/// closed loops (its feature gap field) or on a general PSLG (the gap fields of the faces MADD
/// starts from, each a domain of closed loops).
#pragma once

#include <pdd/core/point.hpp>
#include <pdd/core/pslg.hpp>
#include <pdd/decoupling/feature_driven_sizing.hpp>
#include <pdd/errors.hpp>
#include <pdd/geometry/feature_gap.hpp>
#include <pdd/madd/madd_start.hpp>
#include <pdd/sizing/any_sizing.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <numbers>
#include <utility>
#include <vector>

namespace pdd::detail {

/// A vertex of a feature and its gap (pdd::feature_gap_field::vertex_gap).
struct vertex_gap_sample {
  point at;
  double gap = 0.0;
};

/// The vertex gaps of a domain of closed loops.
inline std::vector<vertex_gap_sample> loop_vertex_gaps(const pslg& g) {
  const feature_gap_field gaps(g);
  std::vector<vertex_gap_sample> out;
  for (index_t v = 0; v < g.vertices.size(); ++v)
    out.push_back({g.vertices[v], gaps.vertex_gap(v)});
  return out;
}

/// The loops of a MADD region as a pslg of closed loops; false when a point repeats (a loop
/// that touches itself or another at a vertex: not a domain pdd::find_loops reads).
inline bool region_loops_pslg(const madd_region& r, pslg& g) {
  std::vector<point> seen;
  for (const madd_loop& l : r.loops) {
    const auto first = static_cast<index_t>(g.vertices.size());
    const auto n = static_cast<index_t>(l.size());
    for (index_t i = 0; i < n; ++i) {
      g.vertices.push_back(l.points[i]);
      g.vertex_markers.push_back(0);
      g.segments.push_back({first + i, first + (i + 1) % n, 0});
    }
  }
  seen = g.vertices;
  std::sort(seen.begin(), seen.end());
  return std::adjacent_find(seen.begin(), seen.end()) == seen.end();
}

/// The vertex gaps of a general PSLG from its regions (pdd::madd_start: the faces, less the
/// caps, and the caps), each read as a domain of its loops alone: the smallest per point. A
/// region whose loops touch at a vertex adds none, nor do the features inside a region
/// (dangling segments, isolated vertices): the samples only shape the decomposition, the graded
/// path takes each k_i from the exact lfs_min of its shielded subdomain.
inline std::vector<vertex_gap_sample> region_vertex_gaps(const madd_start& start) {
  std::vector<vertex_gap_sample> all;
  for (const madd_region& r : start.regions()) {
    pslg g;
    if (!region_loops_pslg(r, g)) continue;
    const std::vector<vertex_gap_sample> own = loop_vertex_gaps(g);
    all.insert(all.end(), own.begin(), own.end());
  }
  std::sort(all.begin(), all.end(), [](const vertex_gap_sample& a, const vertex_gap_sample& b) {
    return std::pair(a.at, a.gap) < std::pair(b.at, b.gap);
  });
  const auto same_point = [](const vertex_gap_sample& a, const vertex_gap_sample& b) {
    return a.at == b.at;
  };
  all.erase(std::unique(all.begin(), all.end(), same_point), all.end());
  return all;
}

/// The vertex gaps the driver is built from: g's own on a domain of closed loops
/// (loop_vertex_gaps), its regions' on a general PSLG (region_vertex_gaps).
inline std::vector<vertex_gap_sample> domain_vertex_gaps(const pslg& g, const madd_start& start) {
  return start.general() ? region_vertex_gaps(start) : loop_vertex_gaps(g);
}

/// The input vertices whose own feature bound 4 sqrt2 (gap/2)^2 lies below min(max_area, f)
/// there (a feature smaller than the mesh), as (that bound / min(max_area, f), sample index),
/// the most binding first (ratio, then sample order).
inline std::vector<std::pair<double, std::size_t>>
binding_features(const std::vector<vertex_gap_sample>& samples, const any_sizing& f,
                 double max_area) {
  std::vector<std::pair<double, std::size_t>> binding;
  for (std::size_t i = 0; i < samples.size(); ++i) {
    const double gap = samples[i].gap;
    if (!std::isfinite(gap) || !(gap > 0.0)) continue;
    const double own = std::numbers::sqrt2 * gap * gap; // 4 sqrt2 (gap / 2)^2
    const double user = std::min(max_area, f.area_at(samples[i].at));
    if (own < user) binding.emplace_back(own / user, i);
  }
  std::sort(binding.begin(), binding.end());
  return binding;
}

/// The `cap` most binding features (binding_features) as the driver of slope `slope`; `found`
/// receives how many.
inline feature_driven_sizing tiny_feature_driver(const std::vector<vertex_gap_sample>& samples,
                                                 const any_sizing& f, double max_area,
                                                 std::size_t cap, double slope,
                                                 std::size_t& found) {
  std::vector<std::pair<double, std::size_t>> binding = binding_features(samples, f, max_area);
  binding.resize(std::min(binding.size(), cap));
  found = binding.size();
  std::vector<point> at;
  std::vector<double> half_gap;
  for (const auto& [ratio, i] : binding) {
    at.push_back(samples[i].at);
    half_gap.push_back(samples[i].gap / 2.0);
  }
  return {f, max_area, std::move(at), std::move(half_gap), slope};
}

} // namespace pdd::detail
