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
//            [--kernel cgal|native] [--resume|--overwrite]
//
// Every subdomain file is bitwise the one `pdd-mesh ... --output-per-subdomain DIR` writes with
// the same N, and so are the index and the manifest (rank 0 keeps it as the ranks report their
// finished pieces; its fingerprint is pdd-mesh's, so either program resumes the other's
// directory). --resume hands out only the subdomains whose pieces are not intact; a non-empty
// directory is refused without --resume or --overwrite. Exit codes as pdd-mesh (exit_code.hpp),
// the same on every rank; rank 0 prints the error, and a failed run leaves no subdomain file of
// its own, no index and no statistics. The disk-space check (rank 0, on the plan's estimate,
// before any file) refuses with exit code 1 on every rank.
#include "../exit_code.hpp"
#include "../mesh_options.hpp"
#include "../resume_options.hpp"
#include "../version_flag.hpp"

#include <pdd/geometry/properties.hpp>
#include <pdd/io/atomic_file.hpp>
#include <pdd/io/poly.hpp>
#ifndef PDD_PERMISSIVE
#include <pdd/kernels/cgal/mesher.hpp>
#endif
#include <pdd/kernels/native/mesher.hpp>
#include <pdd/mesh/quality.hpp>
#include <pdd/mesh/quality_check.hpp>
#include <pdd/mesh/sinks.hpp>
#include <pdd/mesh/statistics_sink.hpp>
#include <pdd/mpi/collectively.hpp>
#include <pdd/mpi/mesh_subdomains.hpp>
#include <pdd/mpi/resumable_piece_sink.hpp>
#include <pdd/mpi/same_decomposition.hpp>
#include <pdd/mpi/vtu_directory_sink.hpp>
#include <pdd/pipeline.hpp>
#include <pdd/pipeline/system.hpp>
#include <pdd/shielding/shield_statistics.hpp>
#include <pdd/sizing/min_sizing.hpp>
#include <pdd/sizing/uniform.hpp>
#include <pdd/version.hpp>

#include <CLI/CLI.hpp>
#include <mpi.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <string>
#include <thread>
#include <type_traits>
#include <vector>

namespace {

using namespace pdd::drivers; // exit codes, mesh_options

/// The options shared with pdd-mesh (mesh_options.hpp), --resume and --overwrite.
struct mpi_options : mesh_options {
  resume_options resume;
};

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
  pdd::mesh_statistics st;                                       ///< rank 0: over all ranks
  pdd::shielding_statistics sst;                                 ///< rank 0: over all ranks
  std::size_t pieces_kept = 0, pieces_meshed = 0, triangles = 0; ///< rank 0: the manifest's
  std::size_t planned_n = 0; ///< the plan's N and path before decoupling, as pdd-mesh's
  std::string planned_path;  ///< fingerprint has them
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
  r.planned_n = r.path->subdomains();
  r.planned_path = pdd::path_name(r.path->plan().path);
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

/// Rank 0 (the others return an empty manifest): the disk-space check (with --resume the
/// pieces the manifest lists count as free) and the output directory
/// (pdd::drivers::prepare_output_directory: refused when not empty without --resume or
/// --overwrite; with --resume the fingerprint checked and the intact pieces kept).
template <class M>
pdd::piece_manifest prepare_directory(const mpi_options& o, mpi_run<M>& r) {
  if (r.rank != 0) return {};
  const std::filesystem::path dir = o.per_subdomain_dir;
  check_disk_space(o, r.path->planned_triangles(), r.path->subdomains(),
                   o.resume.resume ? resumable_bytes(dir) : 0);
  return prepare_output_directory(dir, o.format, o.resume,
                                  mesh_fingerprint(o, r.planned_n, r.planned_path, pdd::version));
}

/// The ids of rank 0's kept pieces, on every rank.
std::vector<pdd::index_t> broadcast_kept(MPI_Comm comm, const pdd::piece_manifest& m) {
  std::vector<unsigned long long> ids;
  for (const auto& [id, record] : m.pieces)
    ids.push_back(id);
  unsigned long long n = ids.size();
  MPI_Bcast(&n, 1, MPI_UNSIGNED_LONG_LONG, 0, comm);
  ids.resize(n);
  MPI_Bcast(ids.data(), static_cast<int>(n), MPI_UNSIGNED_LONG_LONG, 0, comm);
  return {ids.begin(), ids.end()};
}

/// Meshes over the ranks into `sink` (N == 1: on rank 0 alone).
template <class M, class Sink>
void mesh_over_ranks(mpi_run<M>& r, Sink& sink, pdd::mpi::resumable_piece_sink& files) {
  if (r.path->subdomains() <= 1) {
    pdd::mpi::collectively(r.comm, [&] { mesh_whole_on_rank_0(r, sink); });
  } else {
    r.meshing = pdd::mpi::mesh_subdomains(r.comm, r.path->decoupled(), r.path->meshing(), M{},
                                          r.threads, sink, files);
  }
}

/// Phase 2: prepares the output directory (rank 0, before any file: prepare_directory), then
/// meshes the subdomains that are not kept over the ranks into per-subdomain files of the
/// --format (each checked before it is written; rank 0 keeps the manifest); a failure on any
/// rank removes every rank's new files (and, unless resumed, the manifest).
template <class M>
void mesh_distributed(const mpi_options& o, mpi_run<M>& r) {
  const auto t0 = std::chrono::steady_clock::now();
  const std::filesystem::path dir = o.per_subdomain_dir;
  // rank 0 decides; every rank ends with its verdict
  pdd::piece_manifest manifest =
      pdd::mpi::collectively(r.comm, [&] { return prepare_directory(o, r); });
  r.path->keep_subdomains(broadcast_kept(r.comm, manifest));
  std::optional<pdd::mpi::resumable_piece_sink> files;
  pdd::mpi::collectively(r.comm, [&] {
    files.emplace(r.comm, dir, o.format, std::move(manifest),
                  [dir](const pdd::piece_manifest& m) { save_manifest(dir, m); });
  });
  pdd::quality_check_sink checked(*files, r.domain, r.options.criteria, r.sizing);
  pdd::statistics_sink measured(checked, r.domain, r.sizing);
  try {
    mesh_over_ranks(r, measured, *files);
  } catch (const std::exception&) {
    files->remove_written(); // no index was written: leave no pieces of a failed run either
    std::error_code ec;      // best effort too; the run's own error is the one to report
    if (r.rank == 0 && !o.resume.resume)
      std::filesystem::remove(dir / pdd::piece_manifest_name, ec);
    throw;
  }
  gather_statistics(measured, r);
  r.pieces_kept = files->kept().size();
  r.pieces_meshed = files->meshed();
  r.triangles = files->triangles();
  r.t_mesh = pdd::seconds_since(t0);
}

/// The --stats JSON (rank 0).
template <class M>
nlohmann::json statistics_json(const mpi_options& o, const mpi_run<M>& r) {
  const pdd::generate_statistics& gs = r.path->statistics();
  nlohmann::json j;
  j["input"] = o.input;
  j["triangles"] = r.triangles; // the kept pieces' and the new ones'
  j["subdomains"] = gs.subdomains;
  j["per_subdomain_dir"] = o.per_subdomain_dir;
  j["format"] = pdd::to_string(o.format);
  j["resumed"] = o.resume.resume;
  j["pieces_kept"] = r.pieces_kept; // intact pieces of the run resumed, not meshed again
  j["pieces_meshed"] = r.pieces_meshed;
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
int run(const mpi_options& o, mpi_run<M>& r) {
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
                r.triangles, r.path->subdomains(), r.ranks, r.threads, r.t_total,
                r.meshing.imbalance());
    std::printf("pdd-mesh-mpi: min angle %.3f deg, max area / bound %.4f\n", r.st.min_angle_deg,
                r.st.max_area_ratio);
    std::printf("pdd-mesh-mpi: wrote %s/%s and %zu subdomain files (%s)\n",
                o.per_subdomain_dir.c_str(), pdd::piece_index_name(o.format), r.path->subdomains(),
                pdd::to_string(o.format));
    if (o.resume.resume)
      std::printf("pdd-mesh-mpi: resumed: %zu pieces kept, %zu meshed\n", r.pieces_kept,
                  r.pieces_meshed);
    if (!o.stats.empty()) std::printf("pdd-mesh-mpi: wrote %s\n", o.stats.c_str());
  }
  return ok;
}

/// Parses the options (rank 0 prints help and usage errors) and runs; every rank returns the
/// same exit code, rank 0 prints the error.
/// Runs with kernel M (the run's pipeline is gone before MPI_Finalize).
template <class M>
int run_with(const mpi_options& o, const mpi_job& job) {
  mpi_run<M> r;
  static_cast<mpi_job&>(r) = job;
  return run(o, r);
}

int parse_and_run(int argc, char** argv, const mpi_job& job) {
  mpi_options o;
  CLI::App app{"pdd-mesh-mpi: pdd-mesh --output-per-subdomain over the ranks of an MPI job"};
  pdd::drivers::add_version_flag(app, "pdd-mesh-mpi");
  auto* per =
      add_mesh_options(app, o, "meshing threads per rank (default: the node's cores / its ranks)")
          ->required();
  add_resume_options(app, o.resume, per);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int rc = job.rank == 0 ? app.exit(e) : e.get_exit_code();
    return rc == 0 ? ok : usage;
  }
  auto body = [&] {
#ifdef PDD_PERMISSIVE
    return run_with<pdd::native::mesher>(o, job); // the only kernel (--kernel checks it)
#else
    return o.kernel == "native" ? run_with<pdd::native::mesher>(o, job)
                                : run_with<pdd::cgal::mesher>(o, job);
#endif
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
