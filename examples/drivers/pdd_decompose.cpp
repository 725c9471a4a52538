// pdd-decompose: Medial Axis Domain Decomposition (dissertation ch. 3-5) of a Triangle .poly
// domain into N subdomains whose separators meet the boundary and each other at >= Phi0.
//
//   pdd-decompose INPUT.poly --subdomains N [--min-separator-angle DEG] [--algorithm 1|2]
//                 [--threads T] [--no-smoothing] [--max-refinement-levels L]
//                 [--max-area A] [--svg FILE.svg] [--stats FILE.json] [-o FILE.pdd] [--quiet]
//                 [--vertex-weights | --node-weights FILE.node | --grid-weights FILE]
//                 [--uniform-factor u] [--weight-factor a] [--interpolation p]
//                 [--area-function EXPR | --area-mesh FILE.node | --area-grid FILE]
//                 [--area-ratio R]
//
// Graded MADD (dissertation 4.4, include/pdd/madd/graded_weights.hpp): with a weight source
// the heaviest subdomain (u * area + a * density weight) is split until N subdomains exist;
// with a required-area source the subdomain of largest area / required area is split until
// no ratio exceeds R (--subdomains then only caps the count and may be left out).
//
// --max-area A also shields the small input angles and builds the decoupling path pdd-mesh
// would build for that area bound, and reports k, the split points and the shielded triangles
// (the stats gain k, lfs_min, shortest_separator, split_points, shielded_triangles,
// estimated_triangles): a cheap look at whether a decoupled run is sensible. pdd-mesh uses
// MADD's defaults, which do not smooth: add --no-smoothing to plan exactly its path. Like
// pdd-mesh, it then refuses --min-separator-angle below 60 (the decoupling path and the
// shields need separators at >= 60 deg); a plain decomposition accepts any angle in [1, 89].
//
// A domain that is not one of closed loops (internal or dangling segments, isolated vertices)
// is read by Triangle's rule and decomposed from its faces, as pdd-mesh does; its dangling
// segments and isolated vertices are inner constraints of the subdomains that hold them.
//
// -o writes the decomposition in pdd's text format (include/pdd/io/decomposition_io.hpp),
// which pdd::read_decomposition reads back. Exit codes: 0 ok, 1 bad input or the domain cannot
// be decomposed, 2 usage, 3 the decomposition failed its own check, 4 internal error.
#include "exit_code.hpp"
#include "graded_options.hpp"
#include "version_flag.hpp"

#include <pdd/errors.hpp>
#include <pdd/geometry/properties.hpp>
#include <pdd/io/atomic_file.hpp>
#include <pdd/io/decomposition_io.hpp>
#include <pdd/io/poly.hpp>
#include <pdd/io/svg.hpp>
#include <pdd/madd/decompose.hpp>
#include <pdd/madd/validate_decomposition.hpp>
#include <pdd/parallel/parallel_for.hpp>
#include <pdd/pipeline.hpp>
#include <pdd/pipeline/system.hpp>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <optional>
#include <string>

namespace {

using namespace pdd::drivers; // exit codes

struct cli_options {
  std::string input, output, svg, stats;
  pdd::madd_options madd;
  bool no_smoothing = false, quiet = false;
  double max_area = 0.0; ///< > 0: also plan the decoupling path for this area bound
  pdd::drivers::graded_sources graded;
};

/// Everything one pdd-decompose run produces.
struct decompose_run {
  pdd::pslg domain;
  pdd::pslg_properties props;
  pdd::decomposition d;
  pdd::decomposition_statistics st;
  std::optional<pdd::generate_statistics> path; ///< the decoupling path planned for --max-area
  pdd::decomposition_report check;
  pdd::drivers::graded_run graded;
  double total_s = 0.0;
};

/// MADD alone, or with --max-area the pipeline's own MADD (the same decomposition, taken
/// before decouple() shields it), shields and decoupling path.
void decompose_domain(const cli_options& o, decompose_run& r) {
  if (o.max_area <= 0.0) {
    r.d = pdd::decompose(r.domain, o.madd, pdd::default_partitioner{}, &r.st);
    return;
  }
  pdd::generate_options g;
  g.criteria.max_area = o.max_area;
  g.subdomains = o.madd.subdomains;
  g.threads = o.madd.threads;
  g.madd = o.madd;
  g.check_memory = false;
  pdd::pipeline<> pl(r.domain, g);
  r.d = pl.decompose();
  pl.decouple();
  r.path = pl.statistics();
  r.st = r.path->decomposition;
}

/// The --stats JSON.
nlohmann::json stats_json(const cli_options& o, const decompose_run& r) {
  std::vector<double> lengths = r.st.separator_length_per_subdomain;
  std::sort(lengths.begin(), lengths.end());
  nlohmann::json j;
  j["input"] = o.input;
  j["subdomains"] = r.st.subdomains;
  j["algorithm"] = o.madd.algorithm;
  j["min_separator_angle_deg"] = r.st.min_separator_angle_deg;
  j["separator_length_total"] = r.st.separator_length_total;
  j["separator_length_per_subdomain_median"] = lengths.empty() ? 0.0 : lengths[lengths.size() / 2];
  j["max_area_over_mean"] = r.st.max_area_over_mean;
  j["min_area_over_mean"] = r.st.min_area_over_mean;
  j["area_domain"] = r.props.area;
  j["area_sum"] = r.check.area_sum;
  j["splits"] = r.st.splits;
  j["repairs"] = r.st.repairs;
  j["chord_splits"] = r.st.chord_splits;
  j["smoothing_moves"] = r.st.smoothing_moves;
  j["valid"] = r.check.ok();
  j["time_s"] = r.st.time_s;
  j["total_s"] = r.total_s;
  if (r.path) {
    j["max_area"] = o.max_area;
    j["estimated_triangles"] = r.path->estimated_triangles;
    j["k"] = r.path->k;
    j["lfs_min"] = r.path->lfs_min;
    j["shortest_separator"] = r.path->shortest_separator;
    j["split_points"] = r.path->split_points;
    j["shielded_triangles"] = r.path->shielded_triangles;
  }
  if (o.graded.density() || o.graded.area())
    j["graded"] = pdd::drivers::graded_json(o.graded, r.graded, r.d);
  j["peak_rss_mib"] = pdd::peak_rss_mib();
  return j;
}

/// The summary lines on stdout (not with --quiet).
void print_summary(const cli_options& o, const decompose_run& r) {
  std::printf("pdd-decompose: %zu subdomains, min separator angle %.2f deg, max area / mean "
              "%.3f, separator length %.6g, %.3f s\n",
              r.st.subdomains, r.st.min_separator_angle_deg, r.st.max_area_over_mean,
              r.st.separator_length_total, r.st.time_s);
  if (o.graded.density() || o.graded.area()) {
    const nlohmann::json g = pdd::drivers::graded_json(o.graded, r.graded, r.d);
    if (r.graded.weights)
      std::printf("pdd-decompose: graded (%s): density weight per subdomain %.6g..%.6g, "
                  "u*area + a*weight %.6g..%.6g\n",
                  g["mode"].get<std::string>().c_str(), g["weight_min"].get<double>(),
                  g["weight_max"].get<double>(), g["priority_min"].get<double>(),
                  g["priority_max"].get<double>());
    else
      std::printf("pdd-decompose: graded (area ratio): area / required area per subdomain "
                  "%.4g..%.4g (bound %g)\n",
                  g["area_ratio_min"].get<double>(), g["area_ratio_max"].get<double>(),
                  o.graded.area_ratio);
  }
  if (r.path)
    std::printf("pdd-decompose: decoupling path for max area %g: k %.6g, %zu split points "
                "(about %.0f triangles planned), %zu shielded triangles\n",
                o.max_area, r.path->k, r.path->split_points, r.path->estimated_triangles,
                r.path->shielded_triangles);
  for (const std::string* f : {&o.output, &o.svg, &o.stats})
    if (!f->empty()) std::printf("pdd-decompose: wrote %s\n", f->c_str());
}

int run(cli_options o) {
  const auto t0 = std::chrono::steady_clock::now();
  decompose_run r;
  r.domain = pdd::read_poly(o.input);
  r.props = pdd::analyze(r.domain); // validates
  // not one of closed loops: Triangle's rule, as pdd-mesh reads it (MADD starts from its faces)
  if (!r.props.closed_loops) r.domain.rule = pdd::domain_rule::triangle;
  o.madd.smoothing = !o.no_smoothing;
  r.graded = pdd::drivers::set_split_policy(o.graded, r.domain, o.madd);
  if (!o.quiet && pdd::stderr_is_terminal())
    std::fprintf(stderr, "\r\033[Kpdd-decompose: decomposing into %zu subdomains",
                 o.madd.subdomains);
  decompose_domain(o, r);
  if (!o.quiet && pdd::stderr_is_terminal()) std::fprintf(stderr, "\r\033[K");
  r.check =
      pdd::validate_decomposition(r.d, r.domain, {.min_angle_deg = o.madd.min_separator_angle_deg});
  if (!o.output.empty()) pdd::write_decomposition(o.output, r.d);
  if (!o.svg.empty()) pdd::write_svg(o.svg, r.d);
  r.total_s = pdd::seconds_since(t0);
  if (!o.stats.empty()) {
    const nlohmann::json j = stats_json(o, r);
    pdd::write_file_atomically(o.stats, [&](std::ostream& os) { os << j.dump(2) << '\n'; });
  }
  if (!o.quiet) print_summary(o, r);
  if (!r.check.ok()) {
    std::fprintf(stderr, "pdd-decompose: the decomposition failed its check:\n%s",
                 r.check.summary().c_str());
    return verification_failed;
  }
  return ok;
}

/// The usage rules CLI11 cannot state: --subdomains is required unless a required-area source
/// is given (then it caps the count, by default at 2^20); the graded options do not combine
/// with --max-area. \throws CLI::ParseError.
void check_usage(cli_options& o, bool subdomains_given) {
  if (!o.graded.area() && !subdomains_given)
    throw CLI::RequiredError("--subdomains (or a required-area source: --area-function, "
                             "--area-mesh, --area-grid)");
  if (o.graded.area() && !subdomains_given) o.madd.subdomains = std::size_t{1} << 20;
  if ((o.graded.density() || o.graded.area()) && o.max_area > 0.0)
    throw CLI::ValidationError("--max-area", "plans the uniform decoupling path; it does not "
                                             "combine with the graded MADD options");
}

} // namespace

int main(int argc, char** argv) {
  cli_options o;
  CLI::App app{"pdd-decompose: Medial Axis Domain Decomposition of a Triangle .poly domain"};
  pdd::drivers::add_version_flag(app, "pdd-decompose");
  app.add_option("input", o.input, "input domain (Triangle .poly)")->required();
  o.madd.subdomains = 0;
  auto* subdomains =
      app.add_option("-n,--subdomains", o.madd.subdomains,
                     "number of subdomains N (required unless a required-area source is "
                     "given; then the most subdomains made)")
          ->check(CLI::Range(std::size_t{1}, std::size_t{1} << 20));
  app.add_option("--min-separator-angle", o.madd.min_separator_angle_deg,
                 "Phi0: smallest angle a separator may form, degrees (default 60; at least 60 "
                 "with --max-area)")
      ->check(CLI::Range(1.0, 89.0));
  app.add_option("--algorithm", o.madd.algorithm, "MADD algorithm: 1 (3.4) or 2 (3.5, default)")
      ->check(CLI::IsMember({1, 2}));
  app.add_option("--threads", o.madd.threads, "threads (default: all cores)")
      ->check(CLI::Range(1u, 4096u));
  app.add_option("--max-refinement-levels", o.madd.max_refinement_levels,
                 "dynamic refinement budget (levels r, 2r, 4r, ...)")
      ->check(CLI::Range(1, 30));
  app.add_flag("--no-smoothing", o.no_smoothing, "switch separator smoothing (4.2) off");
  app.add_option("--max-area", o.max_area,
                 "also shield small angles and build the decoupling path for this maximum "
                 "triangle area; report k and the split points (a dry run of pdd-mesh)")
      ->check(CLI::PositiveNumber);
  app.add_option("-o,--output", o.output, "write the decomposition (pdd text format)");
  app.add_option("--svg", o.svg, "draw the domain and the separators to this SVG file");
  app.add_option("--stats", o.stats, "write statistics as JSON to this file");
  app.add_flag("-q,--quiet", o.quiet, "print nothing but errors");
  pdd::drivers::add_graded_options(app, o.graded);
  try {
    app.parse(argc, argv);
    check_usage(o, subdomains->count() > 0);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? 0 : 2;
  }
  // --threads T: nothing of the run (its checks and statistics included) on more than T threads
  return pdd::drivers::run_reporting_errors("pdd-decompose", o.input, [&] {
    return pdd::with_threads(o.madd.threads, [&] { return run(o); });
  });
}
