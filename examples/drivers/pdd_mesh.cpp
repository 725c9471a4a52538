// pdd-mesh: guaranteed-quality 2D Delaunay meshing of a Triangle .poly domain, decoupled into
// subdomains that are meshed in parallel (dissertation ch. 6), or monolithic (--subdomains 1).
//
//   pdd-mesh INPUT.poly [-o OUT.{vtu,node,msh,svg}] [--min-angle DEG] [--max-area A]
//            [--subdomains N] [--threads T] [--output-per-subdomain DIR] [--verify]
//            [--compare-monolithic] [--stats FILE.json] [--svg FILE.svg]
//            [--svg-window X0,Y0,X1,Y1] [--svg-histogram FILE.svg] [--quiet]
//            [--sizing EXPR] [--background FILE.node] [--area-grid FILE] [--max-triangles N]
//            [--format vtu|binary] [--no-disk-check] [--assume-free-bytes N]
//            [--geometric-sizing auto|on|off] [-A|--region-attributes] [--resume|--overwrite]
//
// Exit codes: 0 ok, 1 bad input (also a run refused up front: its estimated size exceeds
// --max-triangles or memory, or its per-subdomain output the free disk space), 2 usage, 3
// verification failed, 4 internal error (among them a triangle outside the shielded corners that
// violates the angle or area bound: every mesh is checked before it is written, and nothing is
// written then).
#include "exit_code.hpp"
#include "mesh_options.hpp"
#include "resume_options.hpp"
#include "version_flag.hpp"

#include <pdd/errors.hpp>
#include <pdd/generate.hpp>
#include <pdd/geometry/properties.hpp>
#include <pdd/io/angle_histogram.hpp>
#include <pdd/io/atomic_file.hpp>
#include <pdd/io/poly.hpp>
#include <pdd/io/svg.hpp>
#include <pdd/io/write_mesh.hpp>
#include <pdd/kernels/native/mesher.hpp>
#include <pdd/madd/gradation_options.hpp>
#include <pdd/mesh/merge.hpp>
#include <pdd/mesh/quality.hpp>
#include <pdd/mesh/quality_check.hpp>
#include <pdd/mesh/region_attributes.hpp>
#include <pdd/mesh/resumable_piece_sink.hpp>
#include <pdd/mesh/sinks.hpp>
#include <pdd/mesh/statistics_sink.hpp>
#include <pdd/mesh/verify.hpp>
#include <pdd/mesh/verifying_sink.hpp>
#include <pdd/parallel/parallel_for.hpp>
#include <pdd/pipeline.hpp>
#include <pdd/pipeline/system.hpp>
#include <pdd/shielding/shield_statistics.hpp>
#include <pdd/sizing/any_sizing.hpp>
#include <pdd/sizing/domain_region.hpp>
#include <pdd/sizing/min_sizing.hpp>
#include <pdd/sizing/sizing_range.hpp>
#include <pdd/sizing/uniform.hpp>
#include <pdd/version.hpp>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <atomic>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <limits>
#include <map>
#include <mutex>
#include <optional>
#include <string>
#include <system_error>
#include <vector>

namespace {

using namespace pdd::drivers; // exit codes

/// The options shared with pdd-mesh-mpi (mesh_options.hpp) and pdd-mesh's own.
struct cli_options : pdd::drivers::mesh_options {
  std::string output, svg, svg_histogram;
  std::vector<double> svg_window; ///< x0, y0, x1, y1 of the inset (empty: automatic)
  bool verify = false, compare_monolithic = false;
  bool region_attributes = false;      ///< -A: every triangle's regional attribute with the mesh
  pdd::drivers::resume_options resume; ///< --resume, --overwrite
};

/// Stage lines and the progress bar on stderr, drawn only when stderr is a terminal.
class progress {
public:
  explicit progress(bool enabled) : enabled_(enabled) {}
  void stage(const char* what) const {
    if (enabled_) std::fprintf(stderr, "\r\033[Kpdd-mesh: %s", what);
  }
  void start(std::size_t total) {
    total_ = total;
    t0_ = std::chrono::steady_clock::now();
  }
  /// --resume: the bar starts from the pieces kept (their time is not in the rate).
  void kept(std::size_t pieces) { done_ = kept_ = pieces; }
  void subdomain_done(std::size_t triangles) {
    const std::size_t done = done_.fetch_add(1) + 1;
    const std::size_t tri = triangles_.fetch_add(triangles) + triangles;
    if (!enabled_) return;
    const std::lock_guard lock(mutex_);
    const double s = pdd::seconds_since(t0_);
    const double eta =
        done < total_ ? s / static_cast<double>(done - kept_) * (total_ - done) : 0.0;
    std::fprintf(stderr,
                 "\r\033[Kpdd-mesh: meshing %zu/%zu subdomains, %zu triangles, %.2f M tri/s, "
                 "ETA %.0f s",
                 done, total_, tri, s > 0 ? static_cast<double>(tri) / s / 1e6 : 0.0, eta);
  }
  void clear() const {
    if (enabled_) std::fprintf(stderr, "\r\033[K");
  }

private:
  bool enabled_;
  std::size_t total_ = 0, kept_ = 0;
  std::atomic<std::size_t> done_{0}, triangles_{0};
  std::chrono::steady_clock::time_point t0_;
  std::mutex mutex_;
};

/// A MeshSink that reports progress and hands every mesh on to another sink.
template <pdd::MeshSink Inner>
class progress_sink {
public:
  static constexpr bool retains_meshes = pdd::sink_retains_meshes<Inner>;
  progress_sink(Inner& inner, progress& bar) : inner_(inner), bar_(bar) {}
  void start(pdd::index_t n) {
    bar_.start(n);
    pdd::start_sink(inner_, n);
  }
  void consume(pdd::index_t id, pdd::triangle_mesh&& m) {
    const std::size_t t = m.triangles.size();
    inner_.consume(id, std::move(m));
    bar_.subdomain_done(t);
  }
  void finish() { inner_.finish(); }

private:
  Inner& inner_;
  progress& bar_;
};

/// Everything one pdd-mesh run produces, filled phase by phase.
struct mesh_run {
  pdd::pslg domain;
  pdd::pslg_properties props;
  pdd::generate_options options;
  /// What the mesh is measured and verified against: min(--max-area, the sizing fields).
  pdd::min_sizing<pdd::uniform_sizing, pdd::any_sizing> sizing{pdd::uniform_sizing{}, {}};
  std::string sizing_kind;         ///< names the fields for --stats ("none", "expression", ...)
  pdd::sizing_bounds sizing_range; ///< the bounds of `sizing` over the domain (its faces)
  std::optional<pdd::triangle_mesh> mesh; ///< absent with --output-per-subdomain
  pdd::generate_statistics gs;
  std::optional<pdd::mesh_statistics> st;
  std::optional<pdd::shielding_statistics> sst;
  std::optional<pdd::verification_report> report;
  std::optional<pdd::pieces_report> pieces_report; ///< --verify with --output-per-subdomain
  std::optional<std::size_t> monolithic_triangles;
  std::size_t pieces_kept = 0, pieces_meshed = 0; ///< --output-per-subdomain (--resume)
  std::vector<double> attributes;                 ///< -A: the regional attribute of every triangle
  double t_read = 0.0, t_verify = 0.0, t_monolithic = 0.0, t_write = 0.0, t_total = 0.0;

  std::size_t triangles() const { return mesh ? mesh->triangles.size() : gs.triangles; }
};

/// Reads and validates the input and sets up the options. Input angles below 60 deg are
/// shielded by the pipeline (dissertation 8.1): each becomes one shielded triangle whose
/// smallest angle is the input angle; the quality bound holds elsewhere.
void read_input(const cli_options& o, mesh_run& r) {
  const auto t0 = std::chrono::steady_clock::now();
  r.domain = pdd::read_poly(o.input);
  r.props = pdd::analyze(r.domain); // validates, throws geometry_error
  // Not closed loops (internal or dangling segments, isolated vertices, touching loops,
  // internal boundaries): Triangle's rule; the pipeline decouples it from its faces or meshes
  // it whole (the summary prints its plan_reason).
  if (!r.props.closed_loops) r.domain.rule = pdd::domain_rule::triangle;
  if (!o.quiet && !o.region_attributes && has_region_attributes(r.domain))
    std::printf("pdd-mesh: note: the regions of %s carry attributes; -A writes them with the "
                "mesh\n",
                o.input.c_str());
  r.t_read = pdd::seconds_since(t0);
  r.options = generate_options_for(o, r.domain, r.sizing_kind);
  r.sizing = pdd::min_sizing(pdd::uniform_sizing{o.max_area}, r.options.sizing);
  r.sizing_range = pdd::sizing_range(r.sizing, pdd::domain_region(r.domain).view());
}

/// Meshes into `inner` through the quality check, the statistics and the progress bar.
template <class Pipeline, pdd::MeshSink Inner>
void mesh_checked(Pipeline& pl, Inner& inner, mesh_run& r, progress& bar) {
  pdd::quality_check_sink checked(inner, r.domain, r.options.criteria, r.sizing);
  pdd::statistics_sink measured(checked, r.domain, r.sizing);
  progress_sink sink(measured, bar);
  pl.mesh(sink);
  r.st = measured.statistics();
  r.sst = measured.shielding();
}

/// --verify with --output-per-subdomain: every piece verified in memory before it is written
/// (pdd::verifying_sink: pdd-verify's checks, its interfaces as the neighbours arrive), the
/// pieces that --resume kept read back from their files; t_verify sums the threads' time.
template <class Pipeline>
void mesh_verified(const cli_options& o, Pipeline& pl, pdd::resumable_piece_sink& files,
                   mesh_run& r, progress& bar) {
  pdd::pieces_verifier verifier(r.domain, {.criteria = r.options.criteria}, r.sizing);
  const auto name = [&](pdd::index_t id) { return pdd::piece_file_name(id, o.format); };
  pdd::verifying_sink verified(files, verifier, name);
  mesh_checked(pl, verified, r, bar);
  const auto t0 = std::chrono::steady_clock::now();
  for (const pdd::index_t id : files.kept())
    verifier.add(id, name(id),
                 pdd::read_piece(std::filesystem::path(o.per_subdomain_dir) / name(id)));
  r.pieces_report = verifier.finish();
  r.t_verify = verified.seconds() + pdd::seconds_since(t0);
}

/// --output-per-subdomain: the plan first (its size estimate), the disk-space check on it, the
/// output directory (pdd::drivers::prepare_output_directory: its manifest, with --resume the
/// pieces kept), then the other meshes into files of the --format, each checked and measured on
/// its way (the index comes last; a failed run leaves no piece of its own and, unless resumed,
/// no manifest).
template <pdd::DelaunayMesher M>
void mesh_into_files(const cli_options& o, mesh_run& r, progress& bar) {
  const auto t0 = std::chrono::steady_clock::now();
  pdd::pipeline<M> pl(r.domain, r.options, M{});
  pl.template check_memory<pdd::resumable_piece_sink>(); // up front, before any work
  const std::filesystem::path dir = o.per_subdomain_dir;
  check_disk_space(o, pl.planned_triangles(), pl.subdomains(),
                   o.resume.resume ? pdd::drivers::resumable_bytes(dir) : 0);
  pdd::piece_manifest manifest = pdd::drivers::prepare_output_directory(
      dir, o.format, o.resume,
      pdd::drivers::mesh_fingerprint(o, pl.subdomains(), pdd::path_name(pl.plan().path),
                                     pdd::version));
  pdd::resumable_piece_sink files(
      dir, o.format, std::move(manifest),
      [&](const pdd::piece_manifest& m) { pdd::drivers::save_manifest(dir, m); });
  pl.keep_subdomains(files.kept());
  bar.kept(files.kept().size());
  try {
    if (o.verify)
      mesh_verified(o, pl, files, r, bar);
    else
      mesh_checked(pl, files, r, bar);
  } catch (const pdd::error&) {
    files.remove_written(); // no index was written: leave no pieces of a failed run either
    std::error_code ec;     // best effort too; the run's own error is the one to report
    if (!o.resume.resume) std::filesystem::remove(dir / pdd::piece_manifest_name, ec);
    throw;
  }
  r.gs = std::move(pl.statistics());
  r.gs.timings.total = pdd::seconds_since(t0);
  r.gs.triangles = files.triangles(); // the kept pieces' and the new ones'
  r.pieces_kept = files.kept().size();
  r.pieces_meshed = files.meshed();
}

/// Meshes into a merged mesh, or with --output-per-subdomain into files, measuring each
/// subdomain mesh on its way (nothing is kept). \tparam M the kernel (--kernel).
template <pdd::DelaunayMesher M>
void generate_mesh(const cli_options& o, mesh_run& r, progress& bar) {
  const M mesher;
  if (!o.per_subdomain_dir.empty()) {
    mesh_into_files<M>(o, r, bar);
  } else if (o.subdomains == 1) {
    pdd::generate_result g = pdd::generate(r.domain, r.options, mesher);
    r.gs = std::move(g.statistics);
    r.mesh = std::move(g.mesh);
  } else {
    // Each subdomain mesh is checked and measured in the parallel meshing phase, on its way to
    // the merge, instead of the merged mesh afterwards (at 16M triangles the sequential pass
    // over the merged mesh cost as much as the meshing on two threads).
    pdd::merge_sink merged(o.threads);
    pdd::quality_check_sink checked(merged, r.domain, r.options.criteria, r.sizing);
    pdd::statistics_sink measured(checked, r.domain, r.sizing);
    progress_sink sink(measured, bar);
    r.gs = pdd::generate(r.domain, r.options, sink, mesher);
    r.mesh = merged.take();
    r.gs.vertices = r.mesh->vertices.size();
    r.st = measured.statistics();
    r.st->vertices = r.gs.vertices; // the parts count interface vertices once per side
    r.sst = measured.shielding();
  }
}

/// Statistics of the merged mesh and, with --verify, its verification (pdd::verify with its
/// defaults: shielded or cluster triangles keep their small angle, exempt from the quality check
/// only).
void measure_and_verify(const cli_options& o, mesh_run& r, progress& bar) {
  if (!r.mesh) return;
  if (!r.st) { // the monolithic run (the decoupled ones were checked and measured on the way)
    // Never a silent bad mesh: the O(n) quality check, before anything is written.
    pdd::check_quality(*r.mesh, r.domain, r.options.criteria, r.sizing);
    bar.stage("statistics");
    r.st = pdd::compute_statistics(*r.mesh, r.sizing);
    r.sst = pdd::shielding_statistics_of(*r.mesh, pdd::find_small_input_angles(r.domain), *r.st);
  }
  if (!o.verify) return;
  bar.stage("verifying");
  const auto t0 = std::chrono::steady_clock::now();
  // the library's default verification, as README's example calls it: the faces as generate
  // read them and pdd's one rule for the triangles exempt from the angle bound
  r.report = pdd::verify(*r.mesh, r.domain, {.criteria = r.options.criteria}, r.sizing);
  r.t_verify = pdd::seconds_since(t0);
}

/// --compare-monolithic: the kernel on the whole domain (not part of the total), its mesh
/// checked and measured as every run's is (quality check and statistics: one evaluation of the
/// sizing field per triangle each, which costs as much as the meshing for an expensive
/// expression) and then counted, not kept.
template <pdd::DelaunayMesher M>
void compare_monolithic(mesh_run& r, progress& bar) {
  bar.stage("monolithic run for comparison");
  const auto t0 = std::chrono::steady_clock::now();
  pdd::generate_options m = r.options;
  m.subdomains = 1;
  pdd::counting_sink counted;
  pdd::quality_check_sink checked(counted, r.domain, r.options.criteria, r.sizing);
  pdd::statistics_sink measured(checked, r.domain, r.sizing);
  pdd::generate(r.domain, m, measured, M{});
  r.monolithic_triangles = counted.triangles();
  r.t_monolithic = pdd::seconds_since(t0);
}

/// The per-subdomain part of the --stats JSON: where, in which format, and what --resume kept.
void add_piece_stats(const cli_options& o, const mesh_run& r, nlohmann::json& j) {
  j["per_subdomain_dir"] = o.per_subdomain_dir;
  j["format"] = pdd::to_string(o.format);
  j["resumed"] = o.resume.resume;
  j["pieces_kept"] = r.pieces_kept; // intact pieces of the run resumed, not meshed again
  j["pieces_meshed"] = r.pieces_meshed;
}

/// The mesh and quality part of the --stats JSON.
void add_mesh_stats(const cli_options& o, const mesh_run& r, nlohmann::json& j) {
  const pdd::generate_statistics& gs = r.gs;
  j["input"] = o.input;
  j["output"] = o.output.empty() ? nlohmann::json(nullptr) : nlohmann::json(o.output);
  if (!o.per_subdomain_dir.empty()) add_piece_stats(o, r, j);
  j["triangles"] = r.triangles();
  j["vertices"] = r.mesh ? nlohmann::json(r.mesh->vertices.size()) : nullptr;
  j["estimated_triangles"] = gs.estimated_triangles; // the up-front estimate
  j["subdomains"] = gs.subdomains;
  j["threads"] = gs.threads;
  j["path"] = gs.path; // monolithic, uniform, graded or geometric
  j["plan_reason"] = gs.plan_reason;
  j["sizing_rounds"] = gs.sizing_rounds; // the geometric path's loop (Algorithm 8.3)
  j["estimated_over_refinement"] = gs.estimated_over_refinement;
  j["sizing_round_used"] = gs.sizing_round_used;
  j["geometric_cap"] = gs.geometric_cap; // the loop's cap on subdomains (0: not geometric)
  j["kernel"] = o.kernel;
  j["k"] = gs.k;
  j["split_points"] = gs.split_points;
  j["interface_splits"] = gs.interface_splits;
  j["chord_splits"] = gs.decomposition.chord_splits; // MADD splits beside dense features
  j["remeshed_subdomains"] = gs.remeshed_subdomains;
  j["area_domain"] = r.props.area;
  j["min_input_angle_deg"] = r.props.min_angle_deg;
  j["lfs_min"] = r.props.lfs_min;
  j["shielded_triangles"] = gs.shielded_triangles;
  j["shield_splits"] = gs.shield_splits;
  if (r.sst) {
    j["min_angle_unshielded_deg"] = r.sst->min_angle_unshielded_deg;
    j["max_ratio_unshielded"] = r.sst->max_ratio_unshielded;
    j["max_ratio_shielded"] = r.sst->max_ratio_shielded;
  }
  if (r.st) {
    j["min_angle_deg"] = r.st->min_angle_deg;
    j["max_angle_deg"] = r.st->max_angle_deg;
    j["max_ratio"] = r.st->max_ratio;
    j["max_area_ratio"] = r.st->max_area_ratio;
    j["area_mesh"] = r.st->area;
    j["angle_histogram_deg"] = r.st->angle_histogram;
  }
}

/// The sizing part of the --stats JSON: the fields, their gradation and the graded path.
void add_sizing_stats(const mesh_run& r, nlohmann::json& j) {
  j["sizing"] = r.sizing_kind;
  // max F / min F over the domain's bounding box (null: no bound somewhere)
  j["gradation"] = r.sizing_range.hi / r.sizing_range.lo;
  if (!r.options.sizing || r.gs.subdomains <= 1) return;
  j["graded_path"] = r.gs.graded_path; // false: the interim uniform path (graded_fallback)
  if (!r.gs.graded_path) j["graded_fallback"] = r.gs.graded_fallback;
  j["k_ratio_max"] = r.gs.k_ratio_max;
  j["subdomain_k"] = r.gs.subdomain_k;
  j["lowered_k"] = r.gs.lowered_k; // subdomains whose k_i relation 7.1 lowered
  if (!r.gs.gradation_controlled) return;
  // Algorithm 7.1: measured on the decomposition (conditions left unmet by its termination
  // rule, and whether its most-subdomains cap stopped it)
  j["r1_max"] = r.gs.r1_max;
  j["r2_max"] = r.gs.r2_max;
  j["gradation_splits"] = r.gs.decomposition.splits;
  j["condition_1_unmet"] = r.gs.condition_1_unmet;
  j["condition_2_unmet"] = r.gs.condition_2_unmet;
  j["gradation_capped"] = r.gs.gradation_capped;
}

/// -A: the triangles of each regional attribute, in increasing attribute order.
nlohmann::json region_attribute_stats(const std::vector<double>& attributes) {
  std::map<double, std::size_t> count;
  for (const double a : attributes)
    ++count[a];
  nlohmann::json out = nlohmann::json::array();
  for (const auto& [a, n] : count)
    out.push_back({{"attribute", a}, {"triangles", n}});
  return out;
}

/// The verification, comparison, decomposition and timing part of the --stats JSON.
void add_run_stats(const mesh_run& r, nlohmann::json& j) {
  if (!r.attributes.empty()) j["region_attributes"] = region_attribute_stats(r.attributes);
  j["verified"] = r.report.has_value() || r.pieces_report.has_value();
  j["delaunay_violations"] = r.report ? nlohmann::json(r.report->delaunay_violations) : nullptr;
  j["conforming"] = r.report ? nlohmann::json(r.report->ok()) : nullptr;
  if (r.pieces_report) { // the pieces' own edges and those across their interfaces
    const pdd::pieces_report& p = *r.pieces_report;
    j["delaunay_violations"] = p.delaunay_violations + p.interface_delaunay_violations;
    j["conforming"] = p.ok();
    j["interface_edges_verified"] = p.interface_edges;
  }
  if (r.monolithic_triangles) {
    j["monolithic_triangles"] = *r.monolithic_triangles;
    j["over_refinement_pct"] =
        100.0 *
        (static_cast<double>(r.triangles()) / static_cast<double>(*r.monolithic_triangles) - 1.0);
  }
  if (r.gs.subdomains > 1) {
    j["min_separator_angle_deg"] = r.gs.decomposition.min_separator_angle_deg;
    j["separator_length_total"] = r.gs.decomposition.separator_length_total;
  }
  const pdd::generate_timings& t = r.gs.timings;
  j["timings"] = {{"read", r.t_read},  {"decompose", t.decompose}, {"decouple", t.decouple},
                  {"mesh", t.mesh},    {"merge", t.merge},         {"write", r.t_write},
                  {"total", r.t_total}};
  if (r.report || r.pieces_report) j["timings"]["verify"] = r.t_verify;
  if (r.monolithic_triangles) j["timings"]["monolithic_comparison"] = r.t_monolithic;
  j["peak_rss_mib"] = pdd::peak_rss_mib();
}

/// The summary lines on stdout (not with --quiet).
void print_summary(const cli_options& o, const mesh_run& r) {
  if (r.gs.general_domain) std::printf("pdd-mesh: %s\n", r.gs.plan_reason.c_str());
  std::printf("pdd-mesh: %zu triangles in %zu subdomain(s) on %u thread(s), %.3f s\n",
              r.triangles(), r.gs.subdomains, r.gs.threads, r.t_total);
  if (r.st)
    std::printf("pdd-mesh: min angle %.3f deg, max area / bound %.4f\n", r.st->min_angle_deg,
                r.st->max_area_ratio);
  if (r.sst && r.gs.shielded_triangles > 0)
    std::printf("pdd-mesh: %zu shielded triangles (input angles down to %.3f deg), min angle "
                "of the others %.3f deg\n",
                r.gs.shielded_triangles, r.sst->min_input_angle_deg,
                r.sst->min_angle_unshielded_deg);
  if (r.mesh && !o.output.empty()) std::printf("pdd-mesh: wrote %s\n", o.output.c_str());
  if (!o.per_subdomain_dir.empty())
    std::printf("pdd-mesh: wrote %s/%s and %zu subdomain files (%s)\n", o.per_subdomain_dir.c_str(),
                pdd::piece_index_name(o.format), r.gs.subdomains, pdd::to_string(o.format));
  if (o.resume.resume)
    std::printf("pdd-mesh: resumed: %zu pieces kept, %zu meshed\n", r.pieces_kept, r.pieces_meshed);
  if (r.mesh && !o.svg.empty()) std::printf("pdd-mesh: wrote %s\n", o.svg.c_str());
  if (r.mesh && !o.svg_histogram.empty())
    std::printf("pdd-mesh: wrote %s\n", o.svg_histogram.c_str());
  if (!o.stats.empty()) std::printf("pdd-mesh: wrote %s\n", o.stats.c_str());
}

/// Writes the mesh, its SVG picture and its angle histogram where the options ask for them.
void write_outputs(const cli_options& o, const mesh_run& r) {
  if (r.mesh && !o.output.empty()) pdd::write_mesh(o.output, *r.mesh, r.attributes);
  if (r.mesh && !o.svg.empty()) {
    pdd::svg_options so;
    so.shade_by_area = bool(r.options.sizing); // a graded mesh: show the grading
    if (!o.svg_window.empty())
      so.window =
          pdd::svg_window{o.svg_window[0], o.svg_window[1], o.svg_window[2], o.svg_window[3]};
    pdd::write_svg(o.svg, *r.mesh, so);
  }
  if (r.mesh && !o.svg_histogram.empty()) pdd::write_angle_histogram_svg(o.svg_histogram, *r.mesh);
}

/// The verification's outcome: its messages on stderr and verification_failed when it failed.
int report_verification(const cli_options& o, const mesh_run& r) {
  const bool verified = r.report || r.pieces_report;
  if ((r.report && !r.report->ok()) || (r.pieces_report && !r.pieces_report->ok())) {
    std::fprintf(stderr, "pdd-mesh: verification FAILED\n");
    for (const auto& m : r.report ? r.report->messages : r.pieces_report->messages)
      std::fprintf(stderr, "  %s\n", m.c_str());
    return verification_failed;
  }
  if (verified && !o.quiet) std::printf("pdd-mesh: verification passed\n");
  return ok;
}

/// Meshes with kernel M, verifies (the verification's time is part of the total) and, when
/// asked, meshes the whole domain monolithically with the same kernel for comparison.
template <class M>
void mesh_with_kernel(const cli_options& o, mesh_run& r, progress& bar) {
  generate_mesh<M>(o, r, bar);
  measure_and_verify(o, r, bar);
  if (o.region_attributes && r.mesh) r.attributes = pdd::region_attributes(r.domain, *r.mesh);
  if (o.compare_monolithic) compare_monolithic<M>(r, bar);
}

int run(const cli_options& o) {
  const auto t_start = std::chrono::steady_clock::now();
  progress bar(!o.quiet && pdd::stderr_is_terminal());
  mesh_run r;
  bar.stage("reading input");
  read_input(o, r);
  bar.stage("decomposing and meshing");
#ifdef PDD_PERMISSIVE
  mesh_with_kernel<pdd::native::mesher>(o, r, bar); // the only kernel (--kernel checks it)
#else
  if (o.kernel == "native")
    mesh_with_kernel<pdd::native::mesher>(o, r, bar);
  else
    mesh_with_kernel<pdd::cgal::mesher>(o, r, bar);
#endif
  bar.stage("writing");
  const auto t_write0 = std::chrono::steady_clock::now();
  write_outputs(o, r);
  r.t_write = pdd::seconds_since(t_write0);
  r.t_total = pdd::seconds_since(t_start) - r.t_monolithic;
  bar.clear();
  if (!o.stats.empty()) {
    nlohmann::json j;
    add_mesh_stats(o, r, j);
    add_sizing_stats(r, j);
    add_run_stats(r, j);
    pdd::write_file_atomically(o.stats, [&](std::ostream& os) { os << j.dump(2) << '\n'; });
  }
  if (!o.quiet) print_summary(o, r);
  return report_verification(o, r);
}

} // namespace

int main(int argc, char** argv) {
  cli_options o;
  CLI::App app{"pdd-mesh: guaranteed-quality 2D Delaunay meshing of a Triangle .poly domain"};
  pdd::drivers::add_version_flag(app, "pdd-mesh");
  auto* per = add_mesh_options(app, o, "threads (default: all cores)");
  app.add_option("-o,--output", o.output, "output mesh: .vtu, .node (+.ele/.poly), .msh, .svg");
  app.add_flag("--verify", o.verify,
               "verify Delaunay property, conformity, quality and area (with "
               "--output-per-subdomain: every piece in memory before it is written, and its "
               "interfaces, as pdd-verify checks the files)");
  app.add_flag("--compare-monolithic", o.compare_monolithic,
               "also mesh the whole domain monolithically and report over_refinement_pct");
  auto* svg = app.add_option("--svg", o.svg, "draw the mesh to this SVG file");
  auto* win = app.add_option("--svg-window", o.svg_window,
                             "the --svg picture's zoomed inset: x0,y0,x1,y1 (default: automatic "
                             "for meshes too large to draw every triangle)")
                  ->delimiter(',')
                  ->expected(4)
                  ->needs(svg);
  auto* hist = app.add_option("--svg-histogram", o.svg_histogram,
                              "draw the histogram of the triangle angles to this SVG file");
  auto* attr = app.add_flag(
      "-A,--region-attributes", o.region_attributes,
      "every triangle carries the attribute of the .poly region in its face (0 without one; "
      "Triangle's -A): .vtu cell data region_attribute, the .ele attribute column, .msh "
      "physical tags (integer attributes)");
  pdd::drivers::add_resume_options(app, o.resume, per);
  auto* out = app.get_option("--output");
  per->excludes(svg)->excludes(out)->excludes(win)->excludes(hist)->excludes(attr);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int rc = app.exit(e);
    return rc == 0 ? ok : usage;
  }
  // --threads T: nothing of the run (its checks and statistics included) on more than T threads
  return pdd::drivers::run_reporting_errors(
      "pdd-mesh", o.input, [&] { return pdd::with_threads(o.threads, [&] { return run(o); }); });
}
