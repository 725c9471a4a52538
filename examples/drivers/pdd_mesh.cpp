// pdd-mesh: guaranteed-quality 2D Delaunay meshing of a Triangle .poly domain, decoupled into
// subdomains that are meshed in parallel (dissertation ch. 6), or monolithic (--subdomains 1).
//
//   pdd-mesh INPUT.poly [-o OUT.{vtu,node,msh,svg}] [--min-angle DEG] [--max-area A]
//            [--subdomains N] [--threads T] [--output-per-subdomain DIR] [--verify]
//            [--compare-monolithic] [--stats FILE.json] [--svg FILE.svg] [--quiet]
//
// Exit codes: 0 ok, 1 bad input, 2 usage, 3 verification failed, 4 internal error.
#include "exit_code.hpp"

#include <pdd/errors.hpp>
#include <pdd/generate.hpp>
#include <pdd/geometry/properties.hpp>
#include <pdd/io/atomic_file.hpp>
#include <pdd/io/poly.hpp>
#include <pdd/io/svg.hpp>
#include <pdd/io/write_mesh.hpp>
#include <pdd/mesh/merge.hpp>
#include <pdd/mesh/quality.hpp>
#include <pdd/mesh/sinks.hpp>
#include <pdd/mesh/statistics_sink.hpp>
#include <pdd/mesh/verify.hpp>
#include <pdd/pipeline/system.hpp>
#include <pdd/shielding/shield_statistics.hpp>
#include <pdd/sizing/uniform.hpp>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <atomic>
#include <chrono>
#include <cstdio>
#include <iostream>
#include <limits>
#include <mutex>
#include <optional>
#include <string>

namespace {

using namespace pdd::drivers; // exit codes

struct cli_options {
  std::string input, output, per_subdomain_dir, stats, svg;
  double min_angle = pdd::mesh_criteria{}.min_angle_deg;
  double max_area = std::numeric_limits<double>::infinity();
  std::size_t subdomains = 0;
  unsigned threads = 0;
  bool verify = false, compare_monolithic = false, quiet = false;
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
  void subdomain_done(std::size_t triangles) {
    const std::size_t done = done_.fetch_add(1) + 1;
    const std::size_t tri = triangles_.fetch_add(triangles) + triangles;
    if (!enabled_) return;
    const std::lock_guard lock(mutex_);
    const double s = pdd::detail::seconds_since(t0_);
    const double eta = done < total_ ? s / static_cast<double>(done) * (total_ - done) : 0.0;
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
  std::size_t total_ = 0;
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

int run(const cli_options& o) {
  const auto t_start = std::chrono::steady_clock::now();
  progress bar(!o.quiet && pdd::detail::stderr_is_terminal());

  bar.stage("reading input");
  const pdd::pslg domain = pdd::read_poly(o.input);
  const pdd::pslg_properties props = pdd::analyze(domain); // validates, throws geometry_error
  // Input angles below 60 deg are shielded (dissertation 8.1): each becomes one shielded
  // triangle whose smallest angle is the input angle; the quality bound holds elsewhere.
  const double t_read = pdd::detail::seconds_since(t_start);

  pdd::generate_options g;
  g.criteria = {.min_angle_deg = o.min_angle, .max_area = o.max_area};
  g.subdomains = o.subdomains;
  g.threads = o.threads;
  const pdd::uniform_sizing sizing{o.max_area};

  bar.stage("decomposing and meshing");
  std::optional<pdd::triangle_mesh> mesh;
  pdd::generate_statistics gs;
  std::optional<pdd::mesh_statistics> st;
  std::optional<pdd::shielding_statistics> sst;
  if (!o.per_subdomain_dir.empty()) {
    // nothing is kept: each subdomain mesh is measured on its way to its file
    pdd::vtu_directory_sink files(o.per_subdomain_dir);
    pdd::statistics_sink measured(files, domain, sizing);
    progress_sink sink(measured, bar);
    gs = pdd::generate(domain, g, sink);
    st = measured.statistics();
    sst = measured.shielding();
  } else {
    pdd::merge_sink merged(o.threads);
    progress_sink sink(merged, bar);
    if (o.subdomains == 1) {
      pdd::generate_result r = pdd::generate(domain, g);
      gs = std::move(r.statistics);
      mesh = std::move(r.mesh);
    } else {
      gs = pdd::generate(domain, g, sink);
      mesh = merged.take();
      gs.vertices = mesh->vertices.size();
    }
  }

  std::optional<pdd::verification_report> report;
  double t_verify = 0.0; // part of the total
  if (mesh) {
    bar.stage("statistics");
    st = pdd::compute_statistics(*mesh, sizing);
    sst = pdd::compute_shielding_statistics(*mesh, domain);
    if (o.verify) {
      bar.stage("verifying");
      const auto t0 = std::chrono::steady_clock::now();
      pdd::verify_options vo{.criteria = g.criteria};
      // shielded triangles keep their input angle: exempt from the quality check only
      vo.quality_exempt = pdd::find_shielded_triangles(*mesh, domain);
      report = pdd::verify(*mesh, domain, vo, sizing);
      t_verify = pdd::detail::seconds_since(t0);
    }
  }
  std::optional<std::size_t> monolithic_triangles;
  double t_monolithic = 0.0; // not part of this run's total
  if (o.compare_monolithic) {
    bar.stage("monolithic run for comparison");
    const auto t0 = std::chrono::steady_clock::now();
    pdd::generate_options m = g;
    m.subdomains = 1;
    pdd::counting_sink counted; // only the count is reported: the mesh is not kept
    pdd::generate(domain, m, counted);
    monolithic_triangles = counted.triangles();
    t_monolithic = pdd::detail::seconds_since(t0);
  }

  bar.stage("writing");
  const auto t_write0 = std::chrono::steady_clock::now();
  if (mesh && !o.output.empty()) pdd::write_mesh(o.output, *mesh);
  if (mesh && !o.svg.empty()) pdd::write_svg(o.svg, *mesh);
  const double t_write = pdd::detail::seconds_since(t_write0);
  const double t_total = pdd::detail::seconds_since(t_start) - t_monolithic;
  bar.clear();

  const std::size_t triangles = mesh ? mesh->triangles.size() : gs.triangles;
  if (!o.stats.empty()) {
    nlohmann::json j;
    j["input"] = o.input;
    j["triangles"] = triangles;
    j["vertices"] = mesh ? nlohmann::json(mesh->vertices.size()) : nullptr;
    j["subdomains"] = gs.subdomains;
    j["threads"] = gs.threads;
    j["k"] = gs.k;
    j["split_points"] = gs.split_points;
    j["interface_splits"] = gs.interface_splits;
    j["remeshed_subdomains"] = gs.remeshed_subdomains;
    j["area_domain"] = props.area;
    j["min_input_angle_deg"] = props.min_angle_deg;
    j["lfs_min"] = props.lfs_min;
    j["shielded_triangles"] = gs.shielded_triangles;
    j["shield_splits"] = gs.shield_splits;
    if (sst) {
      j["min_angle_unshielded_deg"] = sst->min_angle_unshielded_deg;
      j["max_ratio_unshielded"] = sst->max_ratio_unshielded;
      j["max_ratio_shielded"] = sst->max_ratio_shielded;
    }
    if (st) {
      j["min_angle_deg"] = st->min_angle_deg;
      j["max_angle_deg"] = st->max_angle_deg;
      j["max_ratio"] = st->max_ratio;
      j["max_area_ratio"] = st->max_area_ratio;
      j["area_mesh"] = st->area;
      j["angle_histogram_deg"] = st->angle_histogram;
    }
    j["verified"] = report.has_value();
    j["delaunay_violations"] = report ? nlohmann::json(report->delaunay_violations) : nullptr;
    j["conforming"] = report ? nlohmann::json(report->ok()) : nullptr;
    if (monolithic_triangles) {
      j["monolithic_triangles"] = *monolithic_triangles;
      j["over_refinement_pct"] =
          100.0 *
          (static_cast<double>(triangles) / static_cast<double>(*monolithic_triangles) - 1.0);
    }
    if (gs.subdomains > 1) {
      j["min_separator_angle_deg"] = gs.decomposition.min_separator_angle_deg;
      j["separator_length_total"] = gs.decomposition.separator_length_total;
    }
    j["timings"] = {{"read", t_read},
                    {"decompose", gs.timings.decompose},
                    {"decouple", gs.timings.decouple},
                    {"mesh", gs.timings.mesh},
                    {"merge", gs.timings.merge},
                    {"write", t_write},
                    {"total", t_total}};
    if (report) j["timings"]["verify"] = t_verify;
    if (monolithic_triangles) j["timings"]["monolithic_comparison"] = t_monolithic;
    j["peak_rss_mib"] = pdd::detail::peak_rss_mib();
    pdd::write_file_atomically(o.stats, [&](std::ostream& os) { os << j.dump(2) << '\n'; });
  }

  if (!o.quiet) {
    std::printf("pdd-mesh: %zu triangles in %zu subdomain(s) on %u thread(s), %.3f s\n", triangles,
                gs.subdomains, gs.threads, t_total);
    if (st)
      std::printf("pdd-mesh: min angle %.3f deg, max area / bound %.4f\n", st->min_angle_deg,
                  st->max_area_ratio);
    if (sst && gs.shielded_triangles > 0)
      std::printf("pdd-mesh: %zu shielded triangles (input angles down to %.3f deg), min angle "
                  "of the others %.3f deg\n",
                  gs.shielded_triangles, sst->min_input_angle_deg, sst->min_angle_unshielded_deg);
    if (mesh && !o.output.empty()) std::printf("pdd-mesh: wrote %s\n", o.output.c_str());
    if (!o.per_subdomain_dir.empty())
      std::printf("pdd-mesh: wrote %s/mesh.pvtu and %zu subdomain files\n",
                  o.per_subdomain_dir.c_str(), gs.subdomains);
    if (mesh && !o.svg.empty()) std::printf("pdd-mesh: wrote %s\n", o.svg.c_str());
    if (!o.stats.empty()) std::printf("pdd-mesh: wrote %s\n", o.stats.c_str());
  }
  if (report) {
    if (!report->ok()) {
      std::fprintf(stderr, "pdd-mesh: verification FAILED\n");
      for (const auto& m : report->messages)
        std::fprintf(stderr, "  %s\n", m.c_str());
      return verification_failed;
    }
    if (!o.quiet) std::printf("pdd-mesh: verification passed\n");
  }
  return ok;
}

} // namespace

int main(int argc, char** argv) {
  cli_options o;
  CLI::App app{"pdd-mesh: guaranteed-quality 2D Delaunay meshing of a Triangle .poly domain"};
  app.add_option("input", o.input, "input domain (Triangle .poly)")->required();
  app.add_option("-o,--output", o.output, "output mesh: .vtu, .node (+.ele/.poly), .msh, .svg");
  app.add_option("--min-angle", o.min_angle, "minimum angle in degrees (default 20.7)")
      ->check(CLI::Range(1.0, 34.0));
  app.add_option("--max-area", o.max_area, "maximum triangle area")->check(CLI::PositiveNumber);
  app.add_option("--subdomains", o.subdomains,
                 "number of subdomains (1: monolithic kernel; default: automatic)")
      ->check(CLI::Range(std::size_t{1}, std::size_t{1} << 20));
  app.add_option("--threads", o.threads, "threads (default: all cores)")
      ->check(CLI::Range(1u, 4096u));
  auto* per = app.add_option("--output-per-subdomain", o.per_subdomain_dir,
                             "write one .vtu per subdomain and an index mesh.pvtu into DIR "
                             "(nothing is kept in memory)");
  auto* ver =
      app.add_flag("--verify", o.verify, "verify Delaunay property, conformity, quality and area");
  app.add_flag("--compare-monolithic", o.compare_monolithic,
               "also mesh the whole domain monolithically and report over_refinement_pct");
  app.add_option("--stats", o.stats, "write statistics as JSON to this file");
  auto* svg = app.add_option("--svg", o.svg, "draw the mesh to this SVG file");
  auto* out = app.get_option("--output");
  per->excludes(ver)->excludes(svg)->excludes(out);
  app.add_flag("-q,--quiet", o.quiet, "print nothing but errors");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int rc = app.exit(e);
    return rc == 0 ? ok : usage;
  }
  return pdd::drivers::run_reporting_errors("pdd-mesh", o.input, [&] { return run(o); });
}
