// Durable output (issue 37): every file pdd-mesh writes is complete under its final name or
// absent, whenever the run is killed (SIGKILL at fixed-seed random moments, a merged VTU and
// per-subdomain pieces), and a full file system is bad input (exit 1, "No space left on device")
// that leaves no piece, no index and no temporary file behind. The sync to disk itself (fsync
// of the file before its rename and of the directory after, io/detail/atomic_file.hpp) guards
// against a power loss, which no test here can cause.
#include "test_files.hpp"
#include "test_support.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <random>
#include <string>
#include <vector>

namespace durable_output_test {
namespace fs = std::filesystem;

namespace {

const std::string pipe_poly = pdd::test::bundled_data("pipe.poly").string();

/// pdd-mesh on the pipe at `max_area` (2e-6: about 1 s on two cores, 70 MB of merged VTU) with
/// `args`, killed with SIGKILL after `seconds` (0: never).
pdd::test::command_result pdd_mesh(const std::string& args, double seconds = 0.0,
                                   const char* max_area = "2e-6") {
  char limit[64] = "";
  if (seconds > 0.0) std::snprintf(limit, sizeof limit, "timeout -s KILL %.3f ", seconds);
  return pdd::test::run_command(std::string(limit) + "'" + PDD_MESH_EXE + "' '" + pipe_poly +
                                "' --max-area " + max_area + " -q " + args);
}

/// The files in dir whose names do not start with '.' (temporaries of a killed run do).
std::vector<std::string> visible_files(const fs::path& dir) {
  std::vector<std::string> out;
  for (const std::string& name : pdd::test::dir_entries(dir))
    if (name[0] != '.') out.push_back(name);
  return out;
}

/// A tmpfs of `size` mounted at dir, unmounted on destruction; mounted() is false where the
/// test may not mount (not root, no mount namespace rights).

} // namespace

TEST(DurableOutput, AKilledRunLeavesACompleteFileOrNone) {
  const fs::path dir = pdd::test::fresh_dir("killed");
  const fs::path reference = dir / "reference.vtu";
  ASSERT_EQ(pdd_mesh("-o '" + reference.string() + "'").code, 0);
  const std::string complete = pdd::test::read_text(reference);
  std::mt19937 random(37);
  std::uniform_real_distribution<double> moment(0.05, 1.5);
  int absent = 0, whole = 0;
  for (int run = 0; run < 10; ++run) {
    const fs::path out = dir / ("run" + std::to_string(run) + ".vtu");
    const double t = moment(random);
    pdd_mesh("-o '" + out.string() + "'", t);
    if (!fs::exists(out)) {
      ++absent;
      continue;
    }
    EXPECT_TRUE(pdd::test::read_text(out) == complete) << "killed at " << t << " s: torn file";
    ++whole;
  }
  std::printf("killed runs: %d left no file, %d a complete one\n", absent, whole);
  EXPECT_EQ(absent + whole, 10);
}

TEST(DurableOutput, AKilledPerSubdomainRunLeavesCompletePiecesAndNoIndex) {
  const fs::path dir = pdd::test::fresh_dir("killed_pieces");
  const fs::path reference = dir / "reference";
  for (const char* format : {"vtu", "binary"}) {
    fs::remove_all(reference);
    ASSERT_EQ(pdd_mesh("--subdomains 32 --format " + std::string(format) +
                       " --output-per-subdomain '" + reference.string() + "'")
                  .code,
              0);
    std::mt19937 random(41);
    std::uniform_real_distribution<double> moment(0.05, 1.2);
    for (int run = 0; run < 6; ++run) {
      const fs::path out = dir / (std::string(format) + std::to_string(run));
      const double t = moment(random);
      const auto r = pdd_mesh("--subdomains 32 --format " + std::string(format) +
                                  " --output-per-subdomain '" + out.string() + "'",
                              t);
      if (!fs::exists(out)) continue;
      const std::vector<std::string> names = visible_files(out);
      const bool finished = r.code == 0;
      for (const std::string& name : names) {
        if (name == "pdd-manifest.json") continue; // lists the pieces so far (resume_test)
        const bool index = name == "mesh.pvtu" || name == "mesh.pddi";
        EXPECT_TRUE(finished || !index) << format << " killed at " << t << " s: an index";
        EXPECT_TRUE(pdd::test::read_text(out / name) == pdd::test::read_text(reference / name))
            << format << " killed at " << t << " s: " << name << " is torn";
      }
    }
  }
}

TEST(DurableOutput, AFullFileSystemIsBadInputAndLeavesNothing) {
  const fs::path dir = pdd::test::temp_path("full_fs");
  pdd::test::small_file_system full(dir, "1m");
  if (!full.mounted()) GTEST_SKIP() << "cannot mount a tmpfs here (not root)";
  for (const std::string& args :
       {std::string("--subdomains 16 --no-disk-check --output-per-subdomain '") +
            (dir / "vtu").string() + "'",
        std::string("--subdomains 16 --no-disk-check --format binary --output-per-subdomain '") +
            (dir / "binary").string() + "'",
        std::string("-o '") + (dir / "merged.vtu").string() + "'"}) {
    // 2e-5: about 270K triangles, several MB in every format, a tenth of the default's work
    const auto r = pdd_mesh(args, 0.0, "2e-5");
    EXPECT_EQ(r.code, 1) << args << "\n" << r.output;
    EXPECT_NE(r.output.find("No space left on device"), std::string::npos) << r.output;
    EXPECT_EQ(r.output.find("internal error"), std::string::npos) << r.output;
  }
  for (const auto& e : fs::recursive_directory_iterator(dir))
    EXPECT_TRUE(e.is_directory()) << "left behind: " << e.path();
}

} // namespace durable_output_test
