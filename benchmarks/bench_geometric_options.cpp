// Benchmark of the geometric loop's driver (not a test): meshes a .poly with pdd::generate at a
// uniform area bound, automatic N, with the driver's feature cap and slope of the first refined
// round set (geometric_decompose_options::first_feature_cap, first_slope; pdd-mesh has no option
// for them), and prints one JSON line: triangles, subdomains, split points, the path and its
// reason, the loop's rounds and cap, the fallback, and the wall seconds of the call.
//
//   bench_geometric_options FILE.poly MAX_AREA FEATURE_CAP SLOPE [THREADS]
//
// SLOPE is a decimal or a fraction P/Q (1/32 is the default slope, 128 the default cap).
// THREADS defaults to 2. The mesh is counted (pdd::counting_sink), not kept. Input that is not
// of closed loops gets Triangle's rule, as in pdd-mesh.
// benchmarks/run_geometric_history.sh runs the tables in benchmarks/results/real-geometries.md.
#include <pdd/errors.hpp>
#include <pdd/generate.hpp>
#include <pdd/geometry/properties.hpp>
#include <pdd/io/poly.hpp>
#include <pdd/mesh/sinks.hpp>

#include <nlohmann/json.hpp>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <iostream>
#include <string>

namespace {

/// A decimal ("0.015") or a fraction ("1/32").
double parse_slope(const std::string& s) {
  const auto slash = s.find('/');
  if (slash == std::string::npos) return std::stod(s);
  return std::stod(s.substr(0, slash)) / std::stod(s.substr(slash + 1));
}

/// The run's statistics and the options that made it, as one JSON object.
nlohmann::json report(const std::string& input, const std::string& slope_text,
                      const pdd::generate_options& options, const pdd::generate_statistics& s,
                      double wall) {
  nlohmann::json j;
  j["input"] = input;
  j["max_area"] = options.criteria.max_area;
  j["feature_cap"] = options.geometric_loop.first_feature_cap;
  j["slope"] = slope_text;
  j["slope_value"] = options.geometric_loop.first_slope;
  j["threads"] = s.threads;
  j["triangles"] = s.triangles;
  j["estimated_triangles"] = s.estimated_triangles;
  j["subdomains"] = s.subdomains;
  j["split_points"] = s.split_points;
  j["path"] = s.path;
  j["plan_reason"] = s.plan_reason;
  j["monolithic_fallback"] = s.monolithic_fallback;
  j["sizing_rounds"] = s.sizing_rounds;
  j["estimated_over_refinement"] = s.estimated_over_refinement;
  j["sizing_round_used"] = s.sizing_round_used;
  j["geometric_cap"] = s.geometric_cap;
  j["mesh_seconds"] = s.timings.mesh;
  j["wall_seconds"] = wall;
  return j;
}

/// Meshes FILE with the driver's cap and slope set (argv as in the file comment) and prints
/// the report.
void run(int argc, char** argv) {
  const std::string input = argv[1];
  pdd::pslg domain = pdd::read_poly(input);
  if (!pdd::analyze(domain).closed_loops) domain.rule = pdd::domain_rule::triangle;
  pdd::generate_options options;
  options.criteria.max_area = std::stod(argv[2]);
  options.threads = argc > 5 ? static_cast<unsigned>(std::stoul(argv[5])) : 2U;
  options.geometric_loop.first_feature_cap = std::stoul(argv[3]);
  options.geometric_loop.first_slope = parse_slope(argv[4]);

  pdd::counting_sink sink;
  const auto t0 = std::chrono::steady_clock::now();
  const pdd::generate_statistics s = pdd::generate(domain, options, sink);
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::cout << report(input, argv[4], options, s, wall).dump() << '\n';
}

} // namespace

int main(int argc, char** argv) {
  if (argc < 5) {
    std::fprintf(stderr, "usage: %s FILE.poly MAX_AREA FEATURE_CAP SLOPE [THREADS]\n", argv[0]);
    return 2;
  }
  try {
    run(argc, argv);
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "bench_geometric_options: %s\n", e.what());
    return 1;
  }
}
