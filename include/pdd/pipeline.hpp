/// \file pipeline.hpp
/// pdd::pipeline: the stepwise uniform decoupling pipeline (MADD -> decoupling path ->
/// parallel meshing -> sink), with its options (pdd::generate_options), statistics and the
/// planning rules (automatic subdomain count, memory estimate). pdd::generate (generate.hpp)
/// is the one-call path.
#pragma once

#include <pdd/concepts/delaunay_mesher.hpp>
#include <pdd/concepts/executor.hpp>
#include <pdd/concepts/graph_partitioner.hpp>
#include <pdd/concepts/mesh_sink.hpp>
#include <pdd/decoupling/decouple.hpp>
#include <pdd/decoupling/decoupled_decomposition.hpp>
#include <pdd/pipeline/detail/plan.hpp>
#include <pdd/pipeline/system.hpp>
#include <pdd/errors.hpp>
#include <pdd/geometry/loops.hpp>
#include <pdd/core/pslg.hpp>
#include <pdd/geometry/validate.hpp>
#include <pdd/kernels/cgal/mesher.hpp>
#include <pdd/madd/decompose.hpp>
#include <pdd/madd/decomposition.hpp>
#include <pdd/madd/decomposition_statistics.hpp>
#include <pdd/madd/madd_options.hpp>
#include <pdd/core/mesh_criteria.hpp>
#include <pdd/core/triangle_mesh.hpp>
#include <pdd/meshing/mesh_subdomains.hpp>
#include <pdd/parallel/tbb_executor.hpp>
#include <pdd/partition/default_partitioner.hpp>
#include <pdd/shielding/apply_shields.hpp>
#include <pdd/shielding/shield.hpp>
#include <pdd/shielding/shield_decomposition.hpp>
#include <pdd/sizing/uniform.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace pdd {

/// Options of pdd::generate and pdd::pipeline.
struct generate_options {
  /// Quality and uniform size bounds of every triangle.
  mesh_criteria criteria;
  /// N, the number of subdomains. 0: automatic (pdd::automatic_subdomains); 1: the kernel
  /// meshes the whole domain at once (no decomposition).
  std::size_t subdomains = 0;
  /// Threads of every stage; 0: all cores.
  unsigned threads = 0;
  /// MADD options; its `subdomains` and `threads` are overridden by the two fields above.
  madd_options madd;
  /// Multiplies the decoupling parameter k of Theorem 15 (in (0, 1] keeps the guarantee).
  double k_scale = 1.0;
  /// > 0: use this k instead (experiments; see decoupling_options::k_override).
  double k_override = 0.0;
  /// Invariance repair rounds (see mesh_subdomains; the theory says none are ever needed).
  unsigned max_repairs = 3;
  /// Refuse (pdd::limit_error) an area bound whose mesh would not fit in physical memory.
  bool check_memory = true;
  /// Automatic N: the number of triangles aimed at per subdomain (see automatic_subdomains).
  double target_subdomain_triangles = 60000.0;
  /// Automatic N: at least this many subdomains per thread when running on several threads.
  unsigned min_subdomains_per_thread = 4;
  /// Automatic N: no subdomain is planned below this many triangles.
  double min_subdomain_triangles = 5000.0;
  /// Automatic N: fall back to N = 1 when the decoupling path has more split points than this
  /// fraction of the estimated triangles. That happens when k is held down by a small input
  /// feature (k <= lfs_min): the uniform method then refines every separator to that scale
  /// and would over-refine the mesh (dissertation 6.3; the graded method of ch. 7 is the
  /// remedy). A requested N (subdomains > 0) is always used.
  double max_split_point_fraction = 0.05;
};

/// Wall-clock seconds of the stages.
struct generate_timings {
  double decompose = 0.0; ///< MADD (0 when N == 1)
  double decouple = 0.0;  ///< k and the decoupling path
  double mesh = 0.0;      ///< kernel on every subdomain, checks, delivery to the sink
  double merge = 0.0;     ///< the sink's finish() (the in-memory merge)
  double total = 0.0;
};

/// What a pipeline run did.
struct generate_statistics {
  std::size_t subdomains = 0;       ///< N used
  unsigned threads = 0;             ///< the executor's concurrency
  double estimated_triangles = 0.0; ///< the plan's estimate (infinity without an area bound)
  double k = 0.0;                   ///< decoupling parameter (0 when N == 1)
  double lfs_min = 0.0;             ///< min over subdomains (0 when N == 1)
  double shortest_separator = 0.0;  ///< L (0 when N == 1)
  std::size_t split_points = 0;     ///< vertices inserted on the separators
  std::size_t interface_splits = 0; ///< interface pieces the kernel split (should be 0)
  /// Input angles < 60 deg shielded (dissertation 8.1): shielded triangles in the mesh.
  std::size_t shielded_triangles = 0;
  std::size_t shield_splits = 0; ///< shield edges the kernel split (0; a split one throws)
  std::size_t remeshed_subdomains = 0;
  std::size_t repair_rounds = 0;
  /// The automatic plan decomposed the domain but fell back to N = 1 because the decoupling
  /// path was too fine (see generate_options::max_split_point_fraction).
  bool monolithic_fallback = false;
  std::size_t triangles = 0; ///< triangles delivered
  std::size_t vertices = 0;  ///< vertices of the merged mesh (generate without a sink only)
  generate_timings timings;
  decomposition_statistics decomposition; ///< MADD's measurements (N > 1)
  std::vector<subdomain_report> per_subdomain;
};

/// Mean triangle area of a quality mesh under a uniform area bound A, as a fraction of A
/// (CGAL's kernel, 20.7 deg, measured on squares from 19K to 4M triangles: 0.655-0.659).
inline constexpr double mean_triangle_area_fraction = 0.656;

/// Expected triangle count of a uniform mesh of a domain of the given area under bound A:
/// area / (0.656 A); infinity when A is not finite (the mesh is then graded by the geometry
/// and small). Complexity O(1).
inline double estimate_triangles(double domain_area, const mesh_criteria& criteria) {
  if (!std::isfinite(criteria.max_area)) return std::numeric_limits<double>::infinity();
  return domain_area / (mean_triangle_area_fraction * criteria.max_area);
}

/// The automatic number of subdomains for an expected mesh of E triangles on P threads.
///
/// The kernel's cost per triangle grows with the size of what it meshes (pdd::cgal::mesher
/// with its heap queue, one core, unit square: 1.7 us/triangle at 19K triangles, 1.8 at 75K,
/// 2.2 at 250K, 2.9 at 1M, 3.5 at 4M), so even one thread gains from meshing small subdomains
/// (key domain, 4.5M triangles, one thread: 17.1 s monolithic, 5.0-5.2 s with N = 75-220,
/// MADD 30-50 ms); the dissertation's rule (6.4) is N >= E / 1.6M for Triangle, whose curve is
/// much flatter. We take N = max(ceil(E / target), min_per_thread * P) (the second term only
/// for P > 1: over-decomposition for load balance, 6.4), capped at E / min_triangles, and
/// N = 1 (the kernel on the whole domain) when that leaves fewer than 2 subdomains or E is
/// not finite (no area bound). target = o.target_subdomain_triangles (default 60K),
/// min_per_thread = o.min_subdomains_per_thread (4), min_triangles = o.min_subdomain_triangles
/// (5K). The defaults are a first choice to be tuned by benchmarks (benchmarks/results).
/// Complexity O(1).
inline std::size_t automatic_subdomains(double estimated_triangles, unsigned threads,
                                        const generate_options& o) {
  if (!std::isfinite(estimated_triangles) || estimated_triangles <= 0.0) return 1;
  double n = std::ceil(estimated_triangles / std::max(1.0, o.target_subdomain_triangles));
  if (threads > 1) n = std::max(n, static_cast<double>(o.min_subdomains_per_thread) * threads);
  n = std::min(n, std::floor(estimated_triangles / std::max(1.0, o.min_subdomain_triangles)));
  return n < 2.0 ? 1 : static_cast<std::size_t>(std::min(n, 1e7));
}

/// Estimated peak memory (bytes) of meshing E triangles as N subdomains on P threads: the
/// kernel's working set for the subdomains in flight (CGAL: about 150-170 bytes per triangle
/// at its peak, output included; 1.3 x the mean subdomain for size variation) plus, when the
/// sink keeps the meshes, the stored subdomain meshes and the merged mesh (about 26 bytes per
/// triangle each: 16 for the triangle and its marker, 10 for half a vertex). N = 1: the
/// kernel on everything. Complexity O(1).
inline double estimate_peak_bytes(double triangles, std::size_t subdomains, unsigned threads,
                                  bool retains_meshes) {
  constexpr double kernel_bytes = 170.0, mesh_bytes = 26.0;
  if (subdomains <= 1) return triangles * kernel_bytes;
  const double n = static_cast<double>(subdomains);
  const double in_flight = std::min<double>(std::max(1u, threads), n) * 1.3 * (triangles / n);
  return in_flight * kernel_bytes + (retains_meshes ? 2.0 * triangles * mesh_bytes : 0.0);
}

namespace detail {
/// \throws pdd::limit_error when the estimate exceeds 90% of physical memory, or a mesh kept in
/// memory would exceed 32-bit indices.
inline void check_memory_plan(double triangles, std::size_t subdomains, unsigned threads,
                              bool retains_meshes, double max_area) {
  if (!std::isfinite(triangles)) return;
  const auto gib = [](double b) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.1f GiB", b / 1073741824.0);
    return std::string(buf);
  };
  const std::string what = "max_area " + std::to_string(max_area) + " gives about " +
                           std::to_string(static_cast<long long>(triangles)) + " triangles";
  if (retains_meshes && triangles / 2.0 * 1.05 >= static_cast<double>(no_index))
    throw limit_error(what + ": more vertices than 32-bit indices allow in one mesh; use a "
                             "file sink (vtu_directory_sink) or a larger max_area");
  const double need = estimate_peak_bytes(triangles, subdomains, threads, retains_meshes);
  const double have = static_cast<double>(physical_memory_bytes());
  if (have > 0.0 && need > 0.9 * have)
    throw limit_error(what + ", needing about " + gib(need) + " of memory at the peak (" +
                      std::to_string(subdomains) + " subdomains, " + std::to_string(threads) +
                      " threads" + (retains_meshes ? ", kept in memory" : "") +
                      "); the machine has " + gib(have) +
                      (retains_meshes ? ". Use a file sink (vtu_directory_sink)," : ". Use") +
                      " more subdomains or a larger max_area");
}
} // namespace detail

/// The uniform decoupling pipeline in stages (dissertation 6.4, Algorithm 6.1):
/// decompose() runs MADD into N subdomains, decouple() computes k and the decoupling path
/// (Theorem 15, Lemma 9), mesh(sink) meshes every subdomain independently on the executor and
/// streams the meshes to a MeshSink. Each stage runs the earlier ones if needed; the results
/// of each stage can be inspected (and changed) before the next.
/// With N = 1 there is no decomposition: mesh() runs the kernel on the whole domain and
/// delivers it as subdomain 0.
/// \tparam M a DelaunayMesher. \tparam P a GraphPartitioner. \tparam E an Executor (built from
/// options.threads when it takes a thread count).
/// Thread-safety: one pipeline object is used from one thread (its stages run in parallel
/// inside).
template <DelaunayMesher M = cgal::mesher, GraphPartitioner P = default_partitioner,
          Executor E = tbb_executor>
class pipeline {
public:
  /// Validates the domain (pdd::validate) and plans N (automatic_subdomains when
  /// options.subdomains == 0).
  /// \throws pdd::geometry_error for an invalid domain.
  pipeline(pslg domain, generate_options options, M mesher = {}, P partitioner = {})
      : domain_(std::move(domain)), options_(std::move(options)), mesher_(std::move(mesher)),
        partitioner_(std::move(partitioner)),
        executor_(detail::make_executor<E>(options_.threads)) {
    validate(domain_);
    area_ = domain_area(domain_);
    stats_.threads = executor_.concurrency();
    stats_.estimated_triangles = estimate_triangles(area_, options_.criteria);
    stats_.subdomains = options_.subdomains != 0 ? options_.subdomains
                                                 : automatic_subdomains(stats_.estimated_triangles,
                                                                        stats_.threads, options_);
  }

  /// N, the number of subdomains this pipeline uses.
  std::size_t subdomains() const noexcept { return stats_.subdomains; }
  /// The domain area (pdd::domain_area).
  double domain_area_value() const noexcept { return area_; }
  const generate_options& options() const noexcept { return options_; }
  const pslg& domain() const noexcept { return domain_; }

  /// \throws pdd::limit_error when meshing into a sink of type S (kept in memory or not, see
  /// sink_retains_meshes) would not fit in physical memory (see estimate_peak_bytes).
  template <MeshSink S>
  void check_memory() const {
    if (options_.check_memory)
      detail::check_memory_plan(planned_triangles(), stats_.subdomains, stats_.threads,
                                sink_retains_meshes<S>, options_.criteria.max_area);
  }

  /// Stage 1: MADD into N subdomains (nothing when N == 1; the decomposition is then empty).
  /// \throws pdd::decomposition_error when the domain cannot be split as asked.
  const decomposition& decompose() {
    if (decomposed_) return decomposition_;
    const auto t0 = std::chrono::steady_clock::now();
    if (stats_.subdomains > 1) {
      madd_options mo = options_.madd;
      mo.subdomains = stats_.subdomains;
      mo.max_subdomain_area = std::numeric_limits<double>::infinity();
      mo.threads = options_.threads;
      decomposition_ = pdd::decompose(domain_, mo, partitioner_, &stats_.decomposition);
      stats_.subdomains = decomposition_.subdomains.size();
    }
    stats_.timings.decompose = detail::seconds_since(t0);
    decomposed_ = true;
    return decomposition_;
  }

  /// Stage 2: the decoupling path (runs decompose() first if needed). Empty when N == 1,
  /// including after an automatic plan's fallback (statistics().monolithic_fallback).
  /// \throws as pdd::decouple.
  const decoupled_decomposition& decouple() {
    if (decoupled_) return decoupled_decomposition_;
    decompose();
    const auto t0 = std::chrono::steady_clock::now();
    if (stats_.subdomains > 1) {
      // Algorithm 8.2: shield the small angles of every subdomain; k then comes from the
      // shielded subdomains D_i' (Theorem 24 (3)).
      std::vector<subdomain_shields> shields;
      if (detail::has_small_angles(decomposition_))
        shields = shield_decomposition(decomposition_, options_.criteria.max_area, executor_,
                                       shield_length_cap(unshielded_k()));
      decoupling_options dopt{options_.criteria, options_.k_override, options_.k_scale};
      decoupled_decomposition_ = pdd::decouple(decomposition_, dopt, executor_);
      decoupled_decomposition_.shields.resize(shields.size());
      for (std::size_t s = 0; s < shields.size(); ++s)
        decoupled_decomposition_.shields[s] = std::move(shields[s].triangles);
      stats_.shielded_triangles = decoupled_decomposition_.num_shielded_triangles();
      stats_.k = decoupled_decomposition_.k;
      stats_.lfs_min = decoupled_decomposition_.lfs_min;
      stats_.shortest_separator = decoupled_decomposition_.shortest_separator;
      stats_.split_points = decoupled_decomposition_.num_split_points();
      if (options_.subdomains == 0 &&
          static_cast<double>(stats_.split_points) >
              options_.max_split_point_fraction * stats_.estimated_triangles)
        fall_back_to_whole_domain();
    }
    stats_.timings.decouple = detail::seconds_since(t0);
    decoupled_ = true;
    return decoupled_decomposition_;
  }

  /// Stage 3: meshes every subdomain (runs decouple() first if needed) and delivers the
  /// meshes to `sink` (see pdd::mesh_subdomains; N == 1: the whole domain as subdomain 0).
  /// \throws pdd::limit_error (check_memory<S>), pdd::meshing_error with the subdomain id,
  /// pdd::decoupling_error when invariance repairs run out.
  template <MeshSink S>
  const generate_statistics& mesh(S& sink) {
    decouple();
    check_memory<S>();
    const auto t0 = std::chrono::steady_clock::now();
    detail::timed_sink<S> timed{sink};
    if (stats_.subdomains <= 1) {
      timed.start(1);
      triangle_mesh m = mesh_whole(stats_.shielded_triangles);
      stats_.triangles = m.triangles.size();
      timed.consume(0, std::move(m));
      timed.finish();
    } else {
      meshing_statistics ms =
          mesh_subdomains(decoupled_decomposition_, {options_.criteria, options_.max_repairs},
                          mesher_, executor_, timed);
      stats_.triangles = ms.triangles();
      stats_.interface_splits = ms.interface_splits;
      stats_.shield_splits = ms.shield_splits;
      stats_.shielded_triangles = decoupled_decomposition_.num_shielded_triangles();
      stats_.remeshed_subdomains = ms.remeshed_subdomains;
      stats_.repair_rounds = ms.repair_rounds;
      stats_.split_points = decoupled_decomposition_.num_split_points();
      stats_.per_subdomain = std::move(ms.subdomains);
    }
    stats_.timings.merge = timed.finish_seconds;
    stats_.timings.mesh = detail::seconds_since(t0) - timed.finish_seconds;
    const generate_timings& t = stats_.timings;
    stats_.timings.total = t.decompose + t.decouple + t.mesh + t.merge;
    return stats_;
  }

  /// The triangles the memory check plans for: the estimate from the area bound, plus, once
  /// the decoupling path exists, 4 per split point (the kernel grades out from the separators).
  double planned_triangles() const noexcept {
    return stats_.estimated_triangles + 4.0 * static_cast<double>(stats_.split_points);
  }

  /// The kernel on the whole domain (the N == 1 path), markers 0. Input angles < 60 deg are
  /// shielded first (pdd::shield, Algorithm 8.2 with N = 1): the kernel meshes D' and the
  /// shielded triangles are added as they are.
  /// \throws pdd::meshing_error(-1, ...) from the kernel, or when it split a shield edge;
  /// pdd::geometry_error as pdd::shield.
  triangle_mesh mesh_whole() const {
    std::size_t shielded = 0;
    return mesh_whole(shielded);
  }
  /// As mesh_whole(); `shielded_triangles` receives the number of shielded triangles.
  triangle_mesh mesh_whole(std::size_t& shielded_triangles) const {
    const shielded_domain sd = shield(domain_, options_.criteria.max_area);
    shielded_triangles = sd.triangles.size();
    if (sd.triangles.empty())
      return mesher_.mesh(domain_, options_.criteria, uniform_sizing{}).mesh;
    mesher_result r = mesher_.mesh(sd.domain, options_.criteria, uniform_sizing{});
    const std::size_t splits = add_shield_triangles(r, sd.domain, sd.triangles, 0);
    if (splits != 0)
      throw meshing_error(-1, std::to_string(splits) +
                                  " shield edge(s) were split by the kernel (Theorem 24 (5) "
                                  "excludes it for a Ruppert-type kernel)");
    return std::move(r.mesh);
  }

  /// The statistics so far.
  const generate_statistics& statistics() const noexcept { return stats_; }
  generate_statistics& statistics() noexcept { return stats_; }
  /// The decoupled decomposition (after decouple(); may be changed before mesh()).
  decoupled_decomposition& decoupled() noexcept { return decoupled_decomposition_; }
  const E& executor() const noexcept { return executor_; }

private:
  /// The decoupling parameter of the unshielded decomposition (caps the shields' l_i through
  /// pdd::shield_length_cap, see pdd::shield_decomposition).
  double unshielded_k() const {
    if (options_.k_override > 0.0) return options_.k_override;
    const std::vector<double> lfs = detail::subdomain_lfs(decomposition_, executor_);
    double shortest = std::numeric_limits<double>::infinity();
    for (const subdomain& sd : decomposition_.subdomains)
      for (std::size_t l = 0; l < sd.loops.size(); ++l)
        for (std::size_t i = 0; i < sd.loops[l].size(); ++i)
          if (sd.tags[l][i].type == edge_tag::kind::interface) {
            const point a = decomposition_.vertices[sd.loops[l][i]];
            const point b = decomposition_.vertices[sd.loops[l][(i + 1) % sd.loops[l].size()]];
            shortest = std::min(shortest, std::hypot(b.x - a.x, b.y - a.y));
          }
    return options_.k_scale * decoupling_parameter(*std::min_element(lfs.begin(), lfs.end()),
                                                   shortest, options_.criteria);
  }

  void fall_back_to_whole_domain() {
    stats_.monolithic_fallback = true;
    stats_.subdomains = 1;
    stats_.k = stats_.lfs_min = stats_.shortest_separator = 0.0;
    stats_.split_points = 0;
    stats_.shielded_triangles = 0;
    stats_.decomposition = {};
    decomposition_ = {};
    decoupled_decomposition_ = {};
  }

  pslg domain_;
  generate_options options_;
  M mesher_;
  P partitioner_;
  E executor_;
  double area_ = 0.0;
  bool decomposed_ = false, decoupled_ = false;
  decomposition decomposition_;
  decoupled_decomposition decoupled_decomposition_;
  generate_statistics stats_;
};

} // namespace pdd
