// The MPI backend end to end (closed loops and a general PSLG): `mpiexec -n P pdd-mesh-mpi`
// against the threaded `pdd-mesh --output-per-subdomain` (every file bitwise equal, and
// pdd-verify passes on it), the statistics, and failures (a throwing kernel through the library
// API, bad input): every rank ends, rank 0 reports once, nothing is left in the output folder.
// ctest sets OMPI_ALLOW_RUN_AS_ROOT(_CONFIRM) (CI runs as root); PDD_MPIEXEC_FLAGS holds
// --oversubscribe for Open MPI (P > cores here).
#include "general_domains.hpp"
#include "same_files.hpp"
#include "test_files.hpp"

#include <pdd/io/poly.hpp>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;
using pdd::test::expect_same_files;
using pdd::test::run_command;

std::string mpiexec(int ranks) {
  return std::string(PDD_MPIEXEC) + " -n " + std::to_string(ranks) + " " + PDD_MPIEXEC_FLAGS + " ";
}

/// p in single quotes, for the shell.
std::string shell_quoted(const fs::path& p) {
  std::string q(1, '\''); // (not "'" + p.string(): GCC 12 warns falsely about it)
  q += p.string();
  q += '\'';
  return q;
}

/// The options of a case: input, --max-area, --subdomains and the kernel.
struct mesh_case {
  fs::path input;
  std::string max_area;
  int subdomains;
#ifdef PDD_PERMISSIVE
  std::string kernel = "native"; // the only kernel of a permissive build
#else
  std::string kernel = "cgal";
#endif
};

std::string case_options(const mesh_case& c) {
  return shell_quoted(c.input) + " --max-area " + c.max_area + " --subdomains " +
         std::to_string(c.subdomains) + " --kernel " + c.kernel + " --quiet";
}

/// The threaded run's folder (made once per case): pdd-mesh on 2 threads.
fs::path threaded_output(const mesh_case& c, const std::string& name) {
  static std::map<std::string, fs::path> done;
  const std::string key = name + "_n" + std::to_string(c.subdomains) + "_" + c.kernel;
  if (done.count(key)) return done[key];
  const fs::path dir = pdd::test::fresh_dir("threaded_" + key);
  const auto r = run_command(std::string(PDD_MESH_EXE) + " " + case_options(c) +
                             " --threads 2 --output-per-subdomain " + shell_quoted(dir / "out") +
                             " --stats " + shell_quoted(dir / "stats.json"));
  EXPECT_EQ(r.code, 0) << r.output;
  return done[key] = dir;
}

/// pdd-verify on the output folder `out` of case c: every piece and every interface.
void expect_verified_output(const fs::path& out, const mesh_case& c, const std::string& what) {
  const auto r =
      run_command(std::string(PDD_VERIFY_EXE) + " " + shell_quoted(out / "mesh.pvtu") + " " +
                  shell_quoted(c.input) + " --max-area " + c.max_area + " --quiet");
  EXPECT_EQ(r.code, 0) << what << ": pdd-verify\n" << r.output;
}

/// Runs the case on each number of ranks (2, 3 and 4 unless given) and compares every file with
/// the threaded run's, and the statistics that do not depend on the run (triangles, angles,
/// ratio, histogram); pdd-verify passes on every output.
void expect_bitwise_as_threaded(const mesh_case& c, const std::string& name,
                                const std::vector<int>& rank_counts = {2, 3, 4}) {
  const fs::path threaded = threaded_output(c, name);
  const auto expected = nlohmann::json::parse(pdd::test::read_text(threaded / "stats.json"));
  for (const int ranks : rank_counts) {
    const std::string what =
        name + " N=" + std::to_string(c.subdomains) + " P=" + std::to_string(ranks);
    const fs::path dir = pdd::test::fresh_dir("mpi_" + name + "_" + std::to_string(ranks));
    const auto r = run_command(mpiexec(ranks) + PDD_MESH_MPI_EXE + " " + case_options(c) +
                               " --threads 1 --output-per-subdomain " + shell_quoted(dir / "out") +
                               " --stats " + shell_quoted(dir / "stats.json"));
    ASSERT_EQ(r.code, 0) << what << "\n" << r.output;
    // N pieces and the index, every byte the threaded run's
    EXPECT_EQ(expect_same_files(threaded / "out", dir / "out", what),
              static_cast<std::size_t>(c.subdomains) + 2) // pieces, index, manifest
        << what;
    expect_verified_output(dir / "out", c, what);
    const auto got = nlohmann::json::parse(pdd::test::read_text(dir / "stats.json"));
    EXPECT_EQ(got["ranks"], ranks) << what;
    EXPECT_EQ(got["subdomains"], c.subdomains) << what;
    for (const char* key : {"kernel", "triangles", "min_angle_deg", "max_angle_deg", "max_ratio",
                            "max_area_ratio", "angle_histogram_deg", "shielded_triangles"})
      EXPECT_EQ(got[key], expected[key]) << what << ": " << key;
    std::size_t meshings = 0;
    for (const auto& rank : got["per_rank"])
      meshings += rank["meshings"].get<std::size_t>();
    EXPECT_EQ(meshings, static_cast<std::size_t>(c.subdomains)) << what;
    EXPECT_GE(got["imbalance"].get<double>(), 1.0) << what;
  }
}

const fs::path data = fs::path(PDD_SOURCE_DIR) / "examples" / "data";

TEST(MpiKey, EverySubdomainFileBitwiseAsThreaded) {
  for (const int n : {16, 64})
    expect_bitwise_as_threaded({data / "key.poly", "2e-3", n}, "key");
}

// 5 to 8 ranks (2 to 4 above), oversubscribed on CI's two cores: a rank may own a single
// subdomain, or none of the first round.
TEST(MpiKey, EverySubdomainFileBitwiseAsThreadedOnFiveToEightRanks) {
  expect_bitwise_as_threaded({data / "key.poly", "2e-3", 16}, "key", {5, 6, 7, 8});
}

TEST(MpiPipe, EverySubdomainFileBitwiseAsThreaded) {
  for (const int n : {16, 64})
    expect_bitwise_as_threaded({data / "pipe.poly", "2e-3", n}, "pipe");
}

// The native kernel (--kernel native) through MPI: every piece bitwise the threaded run's.
TEST(MpiNative, EverySubdomainFileBitwiseAsThreaded) {
  expect_bitwise_as_threaded({data / "key.poly", "2e-3", 16, "native"}, "key_native");
  expect_bitwise_as_threaded({data / "pipe.poly", "2e-3", 64, "native"}, "pipe_native");
}

// A domain that is not one of closed loops (issue 13): the layered domain decoupled from its
// five faces, the segments between them interfaces.
TEST(MpiGeneral, EverySubdomainFileBitwiseAsThreaded) {
  const fs::path poly = pdd::test::temp_path("mpi_layered.poly");
  pdd::pslg layered = pdd::test::layered_domain();
  layered.regions.clear(); // the uniform path: N = 16 exactly
  pdd::write_poly(poly, layered);
  expect_bitwise_as_threaded({poly, "2e-3", 16}, "layered");
  // with a dangling crack, an isolated well and an internal boundary inside its faces
  const fs::path combined_poly = pdd::test::temp_path("mpi_combined.poly");
  pdd::pslg combined = pdd::test::combined_domain();
  combined.regions.clear();
  pdd::write_poly(combined_poly, combined);
  expect_bitwise_as_threaded({combined_poly, "2e-3", 16}, "combined");
}

// Texas: input angles down to 7.29 deg, shielded (dissertation ch. 8).
TEST(MpiSmallAngle, EverySubdomainFileBitwiseAsThreaded) {
  const fs::path texas = pdd::test::shared_data_dir() / "texas.poly";
  if (pdd::test::shared_data_dir().empty() || !fs::exists(texas))
    GTEST_SKIP() << "no ../shared/data/texas.poly";
  for (const int n : {16, 64})
    expect_bitwise_as_threaded({texas, "400", n}, "texas");
  const auto stats = nlohmann::json::parse(
      pdd::test::read_text(threaded_output({texas, "400", 16}, "texas") / "stats.json"));
  EXPECT_GT(stats["shielded_triangles"].get<std::size_t>(), 0u) << "no small angle was shielded";
}

/// Without --subdomains: pdd-mesh-mpi on 2 ranks of 1 thread plans the N that pdd-mesh plans on
/// 2 threads, and writes the same files; returns that N.
int expect_automatic_plan_as_threaded(const fs::path& input, const std::string& max_area) {
  const fs::path dir = pdd::test::fresh_dir("automatic");
  const std::string options = shell_quoted(input) + " --max-area " + max_area + " -q";
  const auto threaded = run_command(
      std::string(PDD_MESH_EXE) + " " + options + " --threads 2 --output-per-subdomain " +
      shell_quoted(dir / "threaded") + " --stats " + shell_quoted(dir / "threaded.json"));
  EXPECT_EQ(threaded.code, 0) << threaded.output;
  const auto mpi = run_command(mpiexec(2) + PDD_MESH_MPI_EXE + " " + options +
                               " --threads 1 --output-per-subdomain " + shell_quoted(dir / "mpi") +
                               " --stats " + shell_quoted(dir / "mpi.json"));
  EXPECT_EQ(mpi.code, 0) << mpi.output;
  const auto planned = nlohmann::json::parse(pdd::test::read_text(dir / "threaded.json"));
  const int n = planned["subdomains"].get<int>();
  EXPECT_EQ(nlohmann::json::parse(pdd::test::read_text(dir / "mpi.json"))["subdomains"], n);
  EXPECT_EQ(expect_same_files(dir / "threaded", dir / "mpi", "automatic N"),
            static_cast<std::size_t>(n) + 2);
  return n;
}

// A small key: the automatic plan is the whole domain (N = 1), meshed by rank 0 alone.
TEST(MpiKey, AutomaticPlanOfOneSubdomainAsThreaded) {
  EXPECT_EQ(expect_automatic_plan_as_threaded(data / "key.poly", "2e-3"), 1);
}

TEST(MpiPipe, AutomaticPlanAsThreadedOnAllRanksThreads) {
  EXPECT_GT(expect_automatic_plan_as_threaded(data / "pipe.poly", "2e-5"), 1);
}

// --format binary: the .pddm pieces and the .pddi index bitwise those of the threaded run.
TEST(MpiPipe, BinaryPiecesBitwiseAsThreaded) {
  const std::string options =
      shell_quoted(data / "pipe.poly") + " --max-area 2e-3 --subdomains 16 --format binary --quiet";
  const fs::path dir = pdd::test::fresh_dir("binary");
  const auto threaded =
      run_command(std::string(PDD_MESH_EXE) + " " + options +
                  " --threads 2 --output-per-subdomain " + shell_quoted(dir / "threaded"));
  ASSERT_EQ(threaded.code, 0) << threaded.output;
  ASSERT_TRUE(fs::exists(dir / "threaded" / "mesh.pddi"));
  for (const int ranks : {2, 3}) {
    const std::string out = std::string(1, 'p').append(std::to_string(ranks));
    const auto r = run_command(mpiexec(ranks) + PDD_MESH_MPI_EXE + " " + options +
                               " --threads 1 --output-per-subdomain " + shell_quoted(dir / out));
    ASSERT_EQ(r.code, 0) << r.output;
    EXPECT_EQ(expect_same_files(dir / "threaded", dir / out, std::string("binary P=").append(out)),
              18u);
  }
}

/// pdd_mpi_throwing_mesher on the key, N = 16, into dir, failing on subdomain `fail` (with
/// `kind` "unresolvable": by a pdd::unresolvable_input_error).
pdd::test::command_result run_throwing(int ranks, const fs::path& dir, int fail,
                                       const std::string& kind = "") {
  return run_command(mpiexec(ranks) + PDD_MPI_THROWING_MESHER_EXE + " " +
                     shell_quoted(data / "key.poly") + " 2e-3 16 " + shell_quoted(dir) + " " +
                     std::to_string(fail) + (kind.empty() ? "" : " " + kind));
}

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (auto p = text.find(what); p != std::string::npos; p = text.find(what, p + 1))
    ++n;
  return n;
}

TEST(MpiFailures, ThrowingKernelEndsEveryRankWithNoOutput) {
  for (const int ranks : {2, 3}) {
    for (const int fail : {0, 5, 15}) {
      const std::string what = "P=" + std::to_string(ranks) + " fail=" + std::to_string(fail);
      const fs::path dir = pdd::test::fresh_dir("throwing");
      const auto r = run_throwing(ranks, dir / "out", fail);
      EXPECT_EQ(r.code, 4) << what << "\n" << r.output;
      EXPECT_EQ(count(r.output, "error: subdomain " + std::to_string(fail) + ": injected failure"),
                1u)
          << what << "\n"
          << r.output;
      EXPECT_TRUE(pdd::test::dir_entries(dir / "out").empty()) << what << ": files left behind";
    }
  }
}

// An input limit of the kernel keeps its class across ranks (its own exit code, 5).
TEST(MpiFailures, UnresolvableInputKeepsItsClassAcrossRanks) {
  for (const int fail : {0, 9}) {
    const std::string what = "P=3 fail=" + std::to_string(fail);
    const fs::path dir = pdd::test::fresh_dir("unresolvable");
    const auto r = run_throwing(3, dir / "out", fail, "unresolvable");
    EXPECT_EQ(r.code, 5) << what << "\n" << r.output;
    EXPECT_EQ(
        count(r.output, "error: subdomain " + std::to_string(fail) + ": injected input limit"), 1u)
        << what << "\n"
        << r.output;
    EXPECT_TRUE(pdd::test::dir_entries(dir / "out").empty()) << what << ": files left behind";
  }
}

TEST(MpiFailures, TheSameProgramWithoutTheFailureSucceeds) {
  const fs::path dir = pdd::test::fresh_dir("not_throwing");
  const auto r = run_throwing(3, dir / "out", -1);
  ASSERT_EQ(r.code, 0) << r.output;
  EXPECT_NE(r.output.find("meshed 16 subdomains"), std::string::npos) << r.output;
  EXPECT_EQ(pdd::test::dir_entries(dir / "out").size(), 17u);
  // the library's files are the driver's
  const fs::path threaded = threaded_output({data / "key.poly", "2e-3", 16}, "key");
  EXPECT_EQ(expect_same_files(threaded / "out", dir / "out", "library API", false), 17u);
}

// The disk-space check: rank 0 decides before any file, every rank ends with exit code 1.
TEST(MpiFailures, DiskCheckRefusesOnEveryRankWithNoOutput) {
  for (const char* format : {"vtu", "binary"}) {
    const fs::path dir = pdd::test::fresh_dir(std::string("disk_").append(format));
    const auto r =
        run_command(mpiexec(3) + PDD_MESH_MPI_EXE + " " + shell_quoted(data / "pipe.poly") +
                    " --max-area 2e-3 --subdomains 16 --threads 1 --format " + format +
                    " --assume-free-bytes 10000 --output-per-subdomain " +
                    shell_quoted(dir / "out") + " --stats " + shell_quoted(dir / "s.json"));
    EXPECT_EQ(r.code, 1) << format << "\n" << r.output;
    EXPECT_EQ(count(r.output, "pdd-mesh-mpi: error: the per-subdomain output would need about"), 1u)
        << r.output;
    EXPECT_NE(r.output.find("has 1e+04 bytes free (--assume-free-bytes)"), std::string::npos)
        << r.output;
    EXPECT_FALSE(fs::exists(dir / "out")) << format;
    EXPECT_FALSE(fs::exists(dir / "s.json")) << format;
  }
}

TEST(MpiFailures, BadInputIsReportedOnceByRankZero) {
  const fs::path dir = pdd::test::fresh_dir("bad_input");
  const auto missing =
      run_command(mpiexec(3) + PDD_MESH_MPI_EXE + " " + shell_quoted(dir / "missing.poly") +
                  " --output-per-subdomain " + shell_quoted(dir / "out") + " --stats " +
                  shell_quoted(dir / "s.json"));
  EXPECT_EQ(missing.code, 1) << missing.output;
  EXPECT_EQ(count(missing.output, "pdd-mesh-mpi: error:"), 1u) << missing.output;
  EXPECT_EQ(count(missing.output, "missing.poly"), 1u) << missing.output;
  EXPECT_FALSE(fs::exists(dir / "out" / "mesh.pvtu"));
  EXPECT_FALSE(fs::exists(dir / "s.json"));
  // a self-intersecting domain: a geometry error, with the file name, from rank 0 only
  const std::string bowtie = pdd::test::write_temp_file(
      "bowtie.poly", "4 2 0 0\n1 0 0\n2 1 1\n3 1 0\n4 0 1\n4 0\n1 1 2\n2 2 3\n3 3 4\n4 4 1\n0\n");
  const auto invalid = run_command(mpiexec(2) + PDD_MESH_MPI_EXE + " " + shell_quoted(bowtie) +
                                   " --output-per-subdomain " + shell_quoted(dir / "out2"));
  EXPECT_EQ(invalid.code, 1) << invalid.output;
  EXPECT_EQ(count(invalid.output, "pdd-mesh-mpi: error: " + bowtie), 1u) << invalid.output;
  EXPECT_FALSE(fs::exists(dir / "out2" / "mesh.pvtu"));
  // usage: the output folder is required
  const auto usage = run_command(mpiexec(2) + PDD_MESH_MPI_EXE + " " + shell_quoted(bowtie));
  EXPECT_EQ(usage.code, 2) << usage.output;
}

} // namespace
