// One thread means one thread (issue 37): with --threads 1 (pdd-mesh, pdd-triangle) or
// generate_options::threads = 1 (the library), nothing of a run runs in parallel, its quality
// check, verification and statistics included: the CPU time it takes is at most its wall time
// (10 % and 50 ms of slack for the process's start and the kernel's accounting). Before, the
// checks and statistics of a "one thread" pdd-mesh run used all cores (1.7x its wall time).
#include "test_files.hpp"
#include "test_support.hpp"

#include <pdd/generate.hpp>
#include <pdd/io/poly.hpp>

#include <gtest/gtest.h>

#include <sys/resource.h>

#include <chrono>
#include <string>

namespace one_thread_test {
namespace {

/// User + system seconds of `who` (RUSAGE_SELF or RUSAGE_CHILDREN).
double cpu_seconds(int who) {
  rusage u{};
  getrusage(who, &u);
  const auto s = [](const timeval& t) { return t.tv_sec + t.tv_usec * 1e-6; };
  return s(u.ru_utime) + s(u.ru_stime);
}

/// Runs `body` and returns {CPU seconds of `who`, wall seconds} it took.
template <class Body>
std::pair<double, double> cpu_and_wall(int who, Body&& body) {
  const double cpu0 = cpu_seconds(who);
  const auto t0 = std::chrono::steady_clock::now();
  body();
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return {cpu_seconds(who) - cpu0, wall};
}

const std::string pipe_poly = pdd::test::bundled_data("pipe.poly").string();

} // namespace

TEST(OneThread, PddMeshWithVerificationAndStatistics) {
  const auto stats = pdd::test::temp_path("stats.json");
  for (const char* n : {"1", "8"}) {
    int code = -1;
    const auto [cpu, wall] = cpu_and_wall(RUSAGE_CHILDREN, [&] {
      code = pdd::test::run_command("'" + std::string(PDD_MESH_EXE) + "' '" + pipe_poly +
                                    "' --max-area 4e-6 --subdomains " + n +
                                    " --threads 1 --verify -q --stats '" + stats.string() + "'")
                 .code;
    });
    EXPECT_EQ(code, 0);
    EXPECT_LE(cpu, 1.1 * wall + 0.05) << "N = " << n << ": " << cpu << " CPU s in " << wall << " s";
  }
}

TEST(OneThread, PddTriangle) {
  const auto dir = pdd::test::fresh_dir("triangle");
  const auto input = dir / "pipe.poly";
  pdd::test::write_text(input, pdd::test::read_text(pipe_poly));
  int code = -1;
  const auto [cpu, wall] = cpu_and_wall(RUSAGE_CHILDREN, [&] {
    code = pdd::test::run_command("'" + std::string(PDD_TRIANGLE_EXE) + "' -pq20.7a0.000004 '" +
                                  input.string() + "' --threads 1 --subdomains 8")
               .code;
  });
  EXPECT_EQ(code, 0);
  EXPECT_LE(cpu, 1.1 * wall + 0.05) << cpu << " CPU s in " << wall << " s";
}

TEST(OneThread, Generate) {
  const pdd::pslg d = pdd::read_poly(pipe_poly);
  pdd::generate_options o;
  o.criteria.max_area = 4e-6;
  o.threads = 1;
  for (const std::size_t n : {1, 8}) {
    o.subdomains = n;
    std::size_t triangles = 0;
    const auto [cpu, wall] =
        cpu_and_wall(RUSAGE_SELF, [&] { triangles = pdd::generate(d, o).mesh.triangles.size(); });
    EXPECT_GT(triangles, 100000u);
    EXPECT_LE(cpu, 1.1 * wall + 0.05) << "N = " << n << ": " << cpu << " CPU s in " << wall << " s";
  }
}

} // namespace one_thread_test
