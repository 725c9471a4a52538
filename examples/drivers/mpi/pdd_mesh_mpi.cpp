// pdd-mesh-mpi: pdd-mesh's per-subdomain run over the ranks of an MPI job (dissertation
// Algorithm 7.2): every rank builds the same decoupled decomposition (it is deterministic; the
// ranks check that they agree), rank 0 hands the subdomains out largest first to whichever rank
// asks, every rank meshes on its own threads and writes its subdomain files, and rank 0 writes
// the .pvtu index and the statistics once every rank has succeeded.
//
//   mpiexec -n P pdd-mesh-mpi INPUT.poly --output-per-subdomain DIR [--min-angle DEG]
//            [--max-area A] [--sizing EXPR] [--background FILE.node] [--area-grid FILE]
//            [--subdomains N] [--threads T] [--stats FILE.json] [--quiet]
//            [--format vtu|binary] [--no-disk-check] [--assume-free-bytes N]
//            [--kernel cgal|native]
//
// Every subdomain file is bitwise the one `pdd-mesh ... --output-per-subdomain DIR` writes with
// the same N. Exit codes as pdd-mesh (exit_code.hpp), the same on every rank; rank 0 prints the
// error, and a failed run leaves no subdomain file, no index and no statistics. The disk-space
// check (rank 0, on the plan's estimate, before any file) refuses with exit code 1 on every rank.
#include "../exit_code.hpp"
#include "../mesh_options.hpp"
#include "../version_flag.hpp"

#include <pdd/geometry/properties.hpp>
#include <pdd/io/atomic_file.hpp>
#include <pdd/io/poly.hpp>
#include <pdd/kernels/cgal/mesher.hpp>
#include <pdd/kernels/native/mesher.hpp>
#include <pdd/mesh/quality.hpp>
#include <pdd/mesh/quality_check.hpp>
#include <pdd/mesh/sinks.hpp>
#include <pdd/mesh/statistics_sink.hpp>
#include <pdd/mpi/collectively.hpp>
#include <pdd/mpi/mesh_subdomains.hpp>
#include <pdd/mpi/same_decomposition.hpp>
#include <pdd/mpi/vtu_directory_sink.hpp>
#include <pdd/pipeline.hpp>
#include <pdd/pipeline/system.hpp>
#include <pdd/shielding/shield_statistics.hpp>
#include <pdd/sizing/min_sizing.hpp>
#include <pdd/sizing/uniform.hpp>

#include <CLI/CLI.hpp>
#include <mpi.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <optional>
#include <string>
#include <thread>
#include <type_traits>
#include <vector>

namespace {

using namespace pdd::drivers; // exit codes, mesh_options

/// This rank of the MPI job.
struct mpi_job {
  MPI_Comm comm = MPI_COMM_WORLD;
  int rank = 0, ranks = 1;
};

/// Everything one run produces, filled phase by phase (each rank its own).
/// \tparam M the kernel (--kernel).
template <class M>
struct mpi_run : mpi_job {
  unsigned threads = 1;     ///< this rank's meshing threads
  unsigned all_threads = 1; ///< the meshing threads of all ranks
  pdd::pslg domain;
  pdd::generate_options options;
  pdd::min_sizing<pdd::uniform_sizing, pdd::any_sizing> sizing{pdd::uniform_sizing{}, {}};
  std::string sizing_kind;
  std::optional<pdd::pipeline<M>> path; ///< decomposition and decoupling path
  pdd::mpi::distributed_meshing_statistics meshing;
  pdd::mesh_statistics st;       ///< rank 0: over all ranks
  pdd::shielding_statistics sst; ///< rank 0: over all ranks
  double t_path = 0.0, t_mesh = 0.0, t_total = 0.0, peak_rss_mib = 0.0;
};

/// --threads, or this node's cores shared among the ranks on this node.
unsigned threads_per_rank(MPI_Comm comm, unsigned asked) {
  if (asked > 0) return asked;
  MPI_Comm node;
  MPI_Comm_split_type(comm, MPI_COMM_TYPE_SHARED, 0, MPI_INFO_NULL, &node);
  int local = 1;
  MPI_Comm_size(node, &local);
  MPI_Comm_free(&node);
  return std::max(1u, std::thread::hardware_concurrency() / static_cast<unsigned>(local));
}

/// Phase 1, on every rank alike: reads and validates the input and builds the decoupled
/// decomposition. An automatic N is planned for the threads of all ranks together (the same on
/// every rank, and the N `pdd-mesh --threads <all ranks' threads>` plans).
template <class M>
void build_path(const mesh_options& o, mpi_run<M>& r) {
  const auto t0 = std::chrono::steady_clock::now();
  r.domain = pdd::read_poly(o.input);
  // validates (throws geometry_error); not closed loops: Triangle's rule, as pdd-mesh reads it
  if (!pdd::analyze(r.domain).closed_loops) r.domain.rule = pdd::domain_rule::triangle;
  if (!o.quiet && r.rank == 0 && has_region_attributes(r.domain))
    std::printf("pdd-mesh-mpi: note: the regional attributes of %s are not written with the "
                "pieces (pdd-mesh -A writes them)\n",
                o.input.c_str());
  r.options = generate_options_for(o, r.domain, r.sizing_kind);
  r.options.threads = o.subdomains > 0 ? r.threads : r.all_threads;
  r.sizing = pdd::min_sizing(pdd::uniform_sizing{o.max_area}, r.options.sizing);
  r.path.emplace(r.domain, r.options);
  r.path->template check_memory<pdd::counting_sink>();
  r.path->decouple();
  r.t_path = pdd::seconds_since(t0);
}

/// N == 1 (asked, or the automatic plan's fallback): rank 0 meshes the whole domain as
/// pdd-mesh does; the other ranks wait.
template <class M, class Sink>
void mesh_whole_on_rank_0(mpi_run<M>& r, Sink& sink) {
  if (r.rank == 0) r.path->mesh(sink);
}

/// Gathers every rank's statistics to rank 0 and combines them in rank order (extremes,
/// counts and the histogram are those of the threaded run; the area sum may differ in its
/// last bits).
template <class M, class Measured>
void gather_statistics(const Measured& measured, mpi_run<M>& r) {
  struct totals {
    pdd::mesh_statistics st;
    pdd::shielding_statistics sst;
    double peak_rss_mib;
  };
  static_assert(std::is_trivially_copyable_v<totals>);
  const totals mine{measured.statistics(), measured.shielding(), pdd::peak_rss_mib()};
  std::vector<totals> all(r.rank == 0 ? static_cast<std::size_t>(r.ranks) : 0);
  MPI_Gather(&mine, sizeof(totals), MPI_BYTE, all.data(), sizeof(totals), MPI_BYTE, 0, r.comm);
  for (const totals& t : all) {
    pdd::accumulate(r.st, t.st);
    pdd::accumulate(r.sst, t.sst);
    r.peak_rss_mib = std::max(r.peak_rss_mib, t.peak_rss_mib);
  }
}

/// Phase 2: checks the free disk space (rank 0, before any file), then meshes the subdomains
/// over the ranks into per-subdomain files of the --format (each checked before it is
/// written); a failure on any rank removes every rank's files.
template <class M>
void mesh_distributed(const mesh_options& o, mpi_run<M>& r) {
  const auto t0 = std::chrono::steady_clock::now();
  // rank 0 decides whether the output fits on disk; every rank ends with its verdict
  pdd::mpi::collectively(r.comm, [&] {
    if (r.rank == 0) check_disk_space(o, r.path->planned_triangles(), r.path->subdomains());
  });
  std::optional<pdd::mpi::piece_directory_sink> files;
  pdd::mpi::collectively(r.comm, [&] { files.emplace(r.comm, o.per_subdomain_dir, o.format); });
  pdd::quality_check_sink checked(*files, r.domain, r.options.criteria, r.sizing);
  pdd::statistics_sink measured(checked, r.domain, r.sizing);
  try {
    if (r.path->subdomains() <= 1) {
      pdd::mpi::collectively(r.comm, [&] { mesh_whole_on_rank_0(r, measured); });
    } else {
      r.meshing = pdd::mpi::mesh_subdomains(r.comm, r.path->decoupled(), r.path->meshing(), M{},
                                            r.threads, measured);
    }
  } catch (const std::exception&) {
    files->remove_written(); // no index was written: leave no pieces of a failed run either
    throw;
  }
  gather_statistics(measured, r);
  r.t_mesh = pdd::seconds_since(t0);
}

/// The --stats JSON (rank 0).
template <class M>
nlohmann::json statistics_json(const mesh_options& o, const mpi_run<M>& r) {
  const pdd::generate_statistics& gs = r.path->statistics();
  nlohmann::json j;
  j["input"] = o.input;
  j["triangles"] = r.st.triangles;
  j["subdomains"] = gs.subdomains;
  j["ranks"] = r.ranks;
  j["threads_per_rank"] = r.threads;
  j["kernel"] = o.kernel;
  j["k"] = gs.k;
  j["split_points"] = gs.split_points;
  j["sizing"] = r.sizing_kind;
  j["interface_splits"] = r.meshing.meshing.interface_splits;
  j["remeshed_subdomains"] = r.meshing.meshing.remeshed_subdomains;
  j["min_angle_deg"] = r.st.min_angle_deg;
  j["max_angle_deg"] = r.st.max_angle_deg;
  j["max_ratio"] = r.st.max_ratio;
  j["max_area_ratio"] = r.st.max_area_ratio;
  j["area_mesh"] = r.st.area;
  j["angle_histogram_deg"] = r.st.angle_histogram;
  j["shielded_triangles"] = r.sst.shielded_triangles;
  j["min_angle_unshielded_deg"] = r.sst.min_angle_unshielded_deg;
  j["imbalance"] = r.meshing.imbalance();
  for (const pdd::mpi::rank_report& rr : r.meshing.ranks)
    j["per_rank"].push_back(
        {{"meshings", rr.meshings}, {"triangles", rr.triangles}, {"busy_s", rr.busy_seconds}});
  j["timings"] = {{"path", r.t_path}, {"mesh", r.t_mesh}, {"total", r.t_total}};
  j["peak_rss_mib_max_rank"] = r.peak_rss_mib;
  return j;
}

template <class M>
int run(const mesh_options& o, mpi_run<M>& r) {
  const auto t0 = std::chrono::steady_clock::now();
  r.threads = threads_per_rank(r.comm, o.threads);
  MPI_Allreduce(&r.threads, &r.all_threads, 1, MPI_UNSIGNED, MPI_SUM, r.comm);
  // no MPI call inside a step that may throw on some ranks only
  pdd::mpi::collectively(r.comm, [&] { build_path(o, r); });
  pdd::mpi::collectively(r.comm,
                         [&] { pdd::mpi::check_same_decomposition(r.comm, r.path->decoupled()); });
  mesh_distributed(o, r);
  r.t_total = pdd::seconds_since(t0);
  if (r.rank != 0) return ok;
  if (!o.stats.empty()) {
    const nlohmann::json j = statistics_json(o, r);
    pdd::write_file_atomically(o.stats, [&](std::ostream& os) { os << j.dump(2) << '\n'; });
  }
  if (!o.quiet) {
    std::printf("pdd-mesh-mpi: %zu triangles in %zu subdomain(s) on %d rank(s) x %u thread(s), "
                "%.3f s (imbalance %.3f)\n",
                r.st.triangles, r.path->subdomains(), r.ranks, r.threads, r.t_total,
                r.meshing.imbalance());
    std::printf("pdd-mesh-mpi: min angle %.3f deg, max area / bound %.4f\n", r.st.min_angle_deg,
                r.st.max_area_ratio);
    std::printf("pdd-mesh-mpi: wrote %s/%s and %zu subdomain files (%s)\n",
                o.per_subdomain_dir.c_str(), pdd::piece_index_name(o.format), r.path->subdomains(),
                pdd::to_string(o.format));
    if (!o.stats.empty()) std::printf("pdd-mesh-mpi: wrote %s\n", o.stats.c_str());
  }
  return ok;
}

/// Parses the options (rank 0 prints help and usage errors) and runs; every rank returns the
/// same exit code, rank 0 prints the error.
/// Runs with kernel M (the run's pipeline is gone before MPI_Finalize).
template <class M>
int run_with(const mesh_options& o, const mpi_job& job) {
  mpi_run<M> r;
  static_cast<mpi_job&>(r) = job;
  return run(o, r);
}

int parse_and_run(int argc, char** argv, const mpi_job& job) {
  mesh_options o;
  CLI::App app{"pdd-mesh-mpi: pdd-mesh --output-per-subdomain over the ranks of an MPI job"};
  pdd::drivers::add_version_flag(app, "pdd-mesh-mpi");
  add_mesh_options(app, o, "meshing threads per rank (default: the node's cores / its ranks)")
      ->required();
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int rc = job.rank == 0 ? app.exit(e) : e.get_exit_code();
    return rc == 0 ? ok : usage;
  }
  auto body = [&] {
    return o.kernel == "native" ? run_with<pdd::native::mesher>(o, job)
                                : run_with<pdd::cgal::mesher>(o, job);
  };
  if (job.rank == 0) return run_reporting_errors("pdd-mesh-mpi", o.input, body);
  try {
    return body();
  } catch (const pdd::error& e) {
    return exit_code_for(e);
  } catch (const std::exception&) {
    return internal;
  }
}

} // namespace

int main(int argc, char** argv) {
  int provided = 0;
  MPI_Init_thread(&argc, &argv, MPI_THREAD_FUNNELED, &provided);
  mpi_job job;
  MPI_Comm_rank(job.comm, &job.rank);
  MPI_Comm_size(job.comm, &job.ranks);
  int rc = internal;
  if (provided < MPI_THREAD_FUNNELED) {
    if (job.rank == 0)
      std::fprintf(stderr, "pdd-mesh-mpi: internal error: the MPI library does not support "
                           "MPI_THREAD_FUNNELED\n");
  } else {
    rc = parse_and_run(argc, argv, job);
  }
  MPI_Finalize();
  return rc;
}
