// Benchmark of the plan's size estimate alone (not a test): pdd::estimate_mesh_size on one
// domain under a uniform area bound, as the pipeline's plan calls it without a sizing field (one
// piece per input triangle, halved where the feature gap changes; shields for that bound).
// Prints one JSON line: the estimate, the pieces integrated over and the fastest of REPEATS
// timings (wall and this thread's CPU), the file's reading excluded:
//
//   bench_estimate key|pipe|FILE.poly MAX_AREA [REPEATS]
//
// benchmarks/run_estimate.sh runs it for the "estimate's own time" table in
// benchmarks/results/estimate.md.
#include <pdd/geometry/model_domains.hpp>
#include <pdd/io/poly.hpp>
#include <pdd/pipeline/system.hpp>
#include <pdd/sizing/any_sizing.hpp>
#include <pdd/sizing/mesh_size_estimate.hpp>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <limits>
#include <string>

namespace {

pdd::pslg load(const std::string& name) {
  if (name == "key") return pdd::key_domain();
  if (name == "pipe") return pdd::pipe_domain();
  return pdd::read_poly(name);
}

} // namespace

int main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: %s key|pipe|FILE.poly MAX_AREA [REPEATS]\n", argv[0]);
    return 2;
  }
  const pdd::pslg domain = load(argv[1]);
  const double max_area = std::atof(argv[2]);
  const int repeats = argc > 3 ? std::max(1, std::atoi(argv[3])) : 1;
  double best_wall = std::numeric_limits<double>::infinity(), best_cpu = best_wall;
  pdd::mesh_size_estimate estimate;
  for (int r = 0; r < repeats; ++r) {
    const auto start = std::chrono::steady_clock::now();
    const double cpu_start = pdd::cpu_seconds();
    estimate = pdd::estimate_mesh_size(domain, max_area, pdd::any_sizing{}, 1, max_area);
    best_cpu = std::min(best_cpu, pdd::cpu_seconds() - cpu_start);
    best_wall = std::min(
        best_wall, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
  nlohmann::json j;
  j["input"] = argv[1];
  j["max_area"] = max_area;
  j["input_vertices"] = domain.vertices.size();
  j["input_segments"] = domain.segments.size();
  j["estimated_triangles"] = estimate.triangles;
  j["pieces"] = estimate.pieces;
  j["repeats"] = repeats;
  j["seconds"] = best_wall;
  j["cpu_seconds"] = best_cpu;
  std::cout << j.dump() << '\n';
}
