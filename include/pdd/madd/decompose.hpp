/// \file decompose.hpp
/// pdd::decompose: the Medial Axis Domain Decomposition (dissertation ch. 3-4, 5.1) of a
/// domain into N subdomains whose separators meet the boundary and each other at angles
/// >= Phi0.
#pragma once

#include <pdd/concepts/graph_partitioner.hpp>
#include <pdd/core/decomposition.hpp>
#include <pdd/core/pslg.hpp>
#include <pdd/errors.hpp>
#include <pdd/geometry/validate.hpp>
#include <pdd/madd/decomposition_measures.hpp>
#include <pdd/madd/detail/assemble.hpp>
#include <pdd/madd/detail/region.hpp>
#include <pdd/madd/detail/rounds.hpp>
#include <pdd/madd/detail/split.hpp>
#include <pdd/madd/madd_options.hpp>
#include <pdd/madd/madd_start.hpp>
#include <pdd/parallel/parallel_for.hpp>
#include <pdd/partition/default_partitioner.hpp>

#include <tbb/task_arena.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace pdd {

/// Decomposes the domain of g into subdomains by MADD (dissertation ch. 3-4): N-way by divide
/// and conquer (3.7), concurrently in rounds (4.3; each split a pure function of its
/// subdomain, so the result is bitwise identical for every thread count), with dynamic
/// refinement (4.1), smoothing (4.2) and the connectivity and angle repairs of 5.1. Into N,
/// every subdomain has a quota of the N and is split in proportion to it (madd_options::
/// round_fraction says how); by an area bound or a split policy, the largest first.
///
/// Guarantees: exactly N subdomains (or all with area <= max_subdomain_area), each a polygon
/// with holes; every separator angle with the boundary or another separator >= Phi0 (input
/// angles below Phi0 stay, no separator ends there); both sides of an interface share vertex
/// ids; see validate_decomposition().
/// \tparam P a GraphPartitioner (default: METIS when found).
/// A general PSLG (pdd::has_closed_loops false: internal constraints, loops nested without a
/// hole point) starts from its faces (pdd::domain_faces by g.rule; with caps, kept whole, where
/// a corner < 60 deg lies on a segment between two of them, pdd::face_decoupling), each at least
/// one subdomain: a segment between two regions is an interface of the result
/// (edge_tag::on_segment) and gets the vertices of the separators that end on it from either side.
/// Its dangling segments, segments with one face on both sides and isolated vertices become inner
/// constraints (pdd::inner_constraint) of the subdomain that holds them: no separator comes
/// within the split's boundary spacing of them (madd/detail/features.hpp).
/// \pre g is valid (validate()).
/// \throws geometry_error as find_loops for bad input; decomposition_error for bad options, or
/// when the domain cannot be split as asked (a subdomain too thin or with too few junction
/// triangles after max_refinement_levels: the message names the subdomain and the reason).
/// Complexity: about O(sum over splits of |Z| log |Z|); N = 1024 on a pipe cross-section takes
/// well under a second on one core. Thread-safety: reentrant (no shared state).
/// This overload starts from regions found before (pdd::madd_start), so a domain decomposed
/// several times is triangulated once.
template <GraphPartitioner P = default_partitioner>
decomposition decompose(const madd_start& start, const madd_options& o = {},
                        const P& partitioner = {}, decomposition_statistics* stats = nullptr) {
  const auto t0 = std::chrono::steady_clock::now();
  detail::check_madd_options(o);
  detail::madd_state state(start.regions(), o);
  const double global_h = detail::global_refinement_length(state, o);
  const detail::madd_split_options so = detail::split_options_for(o);
  decomposition_statistics st;
  tbb::task_arena arena(o.threads == 0 ? tbb::task_arena::automatic : static_cast<int>(o.threads));
  for (;;) {
    std::optional<std::vector<std::size_t>> order;
    // in the arena: a split policy's own parallel work (Algorithm 7.1 measures its new leaves
    // concurrently) runs on o.threads too
    arena.execute([&] { order = detail::next_round(state, o); });
    if (!order) break; // done
    std::vector<detail::madd_split_result> res(order->size());
    const detail::range_function split_leaves = [&](std::size_t first, std::size_t last) {
      for (std::size_t k = first; k != last; ++k) {
        detail::madd_split_options sk = so;
        sk.target_length = detail::target_length(state.leaves[(*order)[k]].region, o, global_h);
        if (state.by_quota) sk.quota = state.leaves[(*order)[k]].quota;
        res[k] = detail::split_region(state.leaves[(*order)[k]].region, sk, partitioner);
      }
    };
    arena.execute([&] { detail::parallel_ranges(order->size(), 1, split_leaves); });
    ++st.rounds;
    detail::apply_round(state, *order, res, st);
  }
  if (st.splits > 0) st.mean_split_fraction /= static_cast<double>(st.splits);
  decomposition d = detail::assemble_decomposition(state.regions());
  if (stats) {
    st.time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    measure_decomposition(d, st);
    *stats = std::move(st);
  }
  return d;
}

/// decompose on the regions of g (pdd::madd_start(g): validates g).
template <GraphPartitioner P = default_partitioner>
decomposition decompose(const pslg& g, const madd_options& o = {}, const P& partitioner = {},
                        decomposition_statistics* stats = nullptr) {
  detail::check_madd_options(o); // bad options before bad input, as ever
  return decompose(madd_start(g), o, partitioner, stats);
}

} // namespace pdd
