/// \file metis.hpp
/// pdd::metis_partitioner: the default GraphPartitioner, over METIS 5 (the partitioner of the
/// dissertation's implementation, section 5.1). Available when PDD_HAVE_METIS is defined (the
/// pdd::pdd CMake target defines it when METIS, e.g. Debian's libmetis-dev, is found).
#pragma once

#ifdef PDD_HAVE_METIS

#include <pdd/concepts/graph_partitioner.hpp>
#include <pdd/errors.hpp>
#include <pdd/partition/detail/csr.hpp>
#include <pdd/partition/detail/exact.hpp>
#include <pdd/partition/detail/fm.hpp>
#include <pdd/partition/detail/metis_input.hpp>
#include <pdd/partition/detail/multilevel.hpp>

#include <metis.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <mutex>
#include <new>
#include <string>
#include <vector>

namespace pdd {

/// Which METIS entry point bisects.
enum class metis_scheme {
  recursive, ///< METIS_PartGraphRecursive (multilevel recursive bisection)
  kway       ///< METIS_PartGraphKway with nparts = 2 (multilevel k-way)
};

namespace detail {
/// Serialises METIS calls. METIS draws its random numbers from one process-wide generator
/// (Debian's build: the C library's srand/rand, which every call reseeds), so concurrent calls
/// would interleave their draws and lose determinism.
inline std::mutex& metis_mutex() {
  static std::mutex m;
  return m;
}
} // namespace detail

/// Models GraphPartitioner with METIS. Parallel edges count with their summed weight; self loops
/// are ignored. Real weights are scaled to METIS's 32-bit integers (each total to 2^29, every
/// positive weight to at least 1; zero edge weights become 1 since METIS needs positive edge
/// weights); METIS's target part weights are target_fraction and the rest, its imbalance bound
/// 2 max_part_fraction; the result is then polished by FM
/// passes on the real weights, which only lower (excess over the bound, cut). Graphs of at most
/// 12 vertices are bisected exactly by enumeration instead (optimal, and clear of METIS's
/// corner cases on tiny graphs).
struct metis_partitioner {
  /// METIS entry point. On MADD-like graphs (duals of Delaunay triangulations with 200-3000
  /// vertices, weights = areas and lengths) and on random holey grids k-way gave 1-3% lower
  /// mean cuts than recursive bisection at the same ncuts; on plain grids they were within 1%
  /// (measurements in tests/partition/README.md).
  metis_scheme scheme = metis_scheme::kway;
  /// METIS_OPTION_NCUTS: independent METIS runs, the best kept (>= 1); 4 lowered the mean cut
  /// by 1-9% against 1, at about twice the time.
  int ncuts = 4;

  /// Bisects g: part[v] is 0 or 1, both parts non-empty when g has >= 2 vertices; balance as
  /// GraphPartitioner states. METIS_OPTION_SEED is derived from o.seed.
  /// \throws decomposition_error if a weight is negative or not finite or o.max_part_fraction
  /// is outside [0.5, 1]; limit_error if the graph exceeds METIS's 32-bit range; std::bad_alloc
  /// if METIS runs out of memory; internal_error if METIS fails otherwise.
  /// Complexity O((n + m) log n) (METIS's multilevel scheme).
  /// Thread-safety: may be called concurrently; METIS calls are serialised by a mutex. METIS
  /// reseeds the C library's rand(): code that calls rand() concurrently in another thread can
  /// change METIS's result, and rand()'s sequence changes after a call.
  std::vector<std::uint8_t> bisect(const partition_graph& g, const bisection_options& o) const {
    detail::check_bisection_options(o);
    if (ncuts < 1) throw decomposition_error("metis_partitioner: ncuts must be >= 1");
    const detail::ml_graph mg = detail::to_ml_graph(g);
    const detail::part_limits limits =
        detail::part_weight_limits(o, detail::total_vertex_weight(mg));
    if (boost::num_vertices(mg) <= detail::exact_bisection_max_vertices)
      return detail::exact_bisection(mg, limits);
    std::vector<std::uint8_t> part = run_metis(mg, o);
    const std::size_t ones = std::count(part.begin(), part.end(), std::uint8_t{1});
    if (ones == 0 || ones == part.size()) // METIS left a part empty: bisect without it
      return detail::multilevel_bisection(mg, limits, detail::multilevel_parameters{}, o.seed);
    detail::fm_refine(mg, part, limits, 8);
    return part;
  }

private:
  std::vector<std::uint8_t> run_metis(const detail::ml_graph& mg,
                                      const bisection_options& o) const {
    detail::metis_input<idx_t> in = detail::to_metis_input<idx_t>(mg);
    idx_t nvtxs = static_cast<idx_t>(boost::num_vertices(mg)), ncon = 1, nparts = 2, cut = 0;
    real_t ubvec = static_cast<real_t>(std::max(2.0 * o.max_part_fraction, 1.001));
    std::array<real_t, 2> tpwgts{static_cast<real_t>(o.target_fraction),
                                 static_cast<real_t>(1.0 - o.target_fraction)};
    idx_t options[METIS_NOPTIONS];
    METIS_SetDefaultOptions(options);
    options[METIS_OPTION_SEED] = static_cast<idx_t>((o.seed ^ (o.seed >> 31)) & 0x7fffffffU);
    options[METIS_OPTION_NCUTS] = ncuts;
    options[METIS_OPTION_NUMBERING] = 0;
    std::vector<idx_t> part(in.vwgt.size(), 0);
    int status = 0;
    {
      const std::lock_guard<std::mutex> lock(detail::metis_mutex());
      auto* entry = scheme == metis_scheme::kway ? &METIS_PartGraphKway : &METIS_PartGraphRecursive;
      status = entry(&nvtxs, &ncon, in.xadj.data(), in.adjncy.data(), in.vwgt.data(), nullptr,
                     in.adjwgt.data(), &nparts, tpwgts.data(), &ubvec, options, &cut, part.data());
    }
    if (status == METIS_ERROR_MEMORY) throw std::bad_alloc();
    if (status != METIS_OK)
      throw internal_error("metis_partitioner: METIS failed with status " + std::to_string(status));
    for (const idx_t p : part)
      PDD_ASSERT(p == 0 || p == 1);
    return std::vector<std::uint8_t>(part.begin(), part.end());
  }
};
static_assert(GraphPartitioner<metis_partitioner>);

} // namespace pdd

#endif // PDD_HAVE_METIS
