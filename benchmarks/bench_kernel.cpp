// Benchmark of one kernel alone (not a test): meshes a bundled model domain at a target
// triangle count and prints one JSON line with triangles, seconds, microseconds per triangle
// and peak RSS. Run one size per process so that peak RSS is per run:
//
//   bench_kernel key|pipe TARGET_TRIANGLES [MIN_ANGLE_DEG] [cgal|native]
//
// benchmarks/run_kernel.sh runs the table in benchmarks/results/kernel.md (CGAL kernel),
// benchmarks/run_native_kernel.sh the one in benchmarks/results/native-kernel.md.
#include <pdd/geometry/loops.hpp>
#include <pdd/geometry/model_domains.hpp>
#include <pdd/kernels/cgal/mesher.hpp>
#include <pdd/kernels/native/mesher.hpp>
#include <pdd/mesh/quality.hpp>
#include <pdd/pipeline.hpp>
#include <pdd/pipeline/system.hpp>

#include <nlohmann/json.hpp>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <string>

int main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: %s key|pipe TARGET_TRIANGLES [MIN_ANGLE_DEG] [cgal|native]\n",
                 argv[0]);
    return 2;
  }
  const std::string name = argv[1];
  const double target = std::atof(argv[2]);
  const pdd::pslg domain = name == "key" ? pdd::key_domain() : pdd::pipe_domain();
  pdd::mesh_criteria criteria;
  if (argc > 3) criteria.min_angle_deg = std::atof(argv[3]);
  // Quality meshes at an area bound A have a mean triangle area of about 0.656 A.
  criteria.max_area = pdd::domain_area(domain) / target / pdd::mean_triangle_area_fraction;

  const std::string kernel = argc > 4 ? argv[4] : "cgal";
  if (kernel != "cgal" && kernel != "native") {
    std::fprintf(stderr, "unknown kernel %s (cgal or native)\n", kernel.c_str());
    return 2;
  }
  const pdd::uniform_sizing sizing{criteria.max_area};
  const auto t0 = std::chrono::steady_clock::now();
  const auto result = kernel == "native" ? pdd::native::mesher{}.mesh(domain, criteria, sizing)
                                         : pdd::cgal::mesher{}.mesh(domain, criteria, sizing);
  const double seconds = pdd::seconds_since(t0);
  const double mesh_cpu_seconds = pdd::cpu_seconds(); // the process up to here, not the stats
  const auto st = pdd::compute_statistics(result.mesh);

  nlohmann::json j;
  j["domain"] = name;
  j["kernel"] = kernel;
  j["max_area"] = criteria.max_area;
  j["min_angle_bound_deg"] = criteria.min_angle_deg;
  j["triangles"] = st.triangles;
  j["vertices"] = st.vertices;
  j["seconds"] = seconds;
  j["cpu_seconds"] = pdd::cpu_seconds();
  j["mesh_cpu_seconds"] = mesh_cpu_seconds;
  j["us_per_triangle"] = 1e6 * seconds / static_cast<double>(st.triangles);
  j["min_angle_deg"] = st.min_angle_deg;
  j["peak_rss_mib"] = pdd::peak_rss_mib();
  std::cout << j.dump() << std::endl;
  return 0;
}
