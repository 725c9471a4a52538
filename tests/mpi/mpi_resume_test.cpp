// pdd-mesh-mpi --resume (issue 40): a directory with a deleted and a truncated piece, resumed on
// 3 ranks, equals a clean run byte for byte (pieces, index and manifest), only the two pieces
// are handed out again, and pdd-mesh and pdd-mesh-mpi resume each other's directories; a job
// whose launcher is killed with SIGKILL at fixed-seed moments, then resumed, equals a clean
// run; a changed option is refused naming it; a non-empty directory is refused without
// --resume or --overwrite. ctest sets OMPI_ALLOW_RUN_AS_ROOT(_CONFIRM).
#include "same_files.hpp"
#include "test_files.hpp"

#include <pdd/io/piece_files.hpp>
#include <pdd/io/piece_manifest.hpp>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <random>
#include <string>
#include <vector>

namespace mpi_resume_test {

namespace fs = std::filesystem;
using pdd::test::expect_same_files;
using pdd::test::read_json;
using pdd::test::run_command;

const fs::path pipe_poly = fs::path(PDD_SOURCE_DIR) / "examples" / "data" / "pipe.poly";

/// p in single quotes, for the shell.
std::string quoted(const fs::path& p) {
  std::string q(1, '\'');
  q += p.string();
  q += '\'';
  return q;
}

/// The command line of pdd-mesh-mpi on `ranks` ranks of one thread, on the pipe with `options`,
/// into `out`.
std::string mpi_command(int ranks, const std::string& options, const fs::path& out) {
  return std::string(PDD_MPIEXEC) + " -n " + std::to_string(ranks) + " " + PDD_MPIEXEC_FLAGS + " " +
         PDD_MESH_MPI_EXE + " " + quoted(pipe_poly) + " -q --threads 1 " + options +
         " --output-per-subdomain " + quoted(out);
}

pdd::test::command_result mpi(int ranks, const std::string& options, const fs::path& out) {
  return run_command(mpi_command(ranks, options, out));
}

/// pdd-mesh on 2 threads, the same options, into `out`.
pdd::test::command_result threaded(const std::string& options, const fs::path& out) {
  return run_command(std::string(PDD_MESH_EXE) + " " + quoted(pipe_poly) + " -q --threads 2 " +
                     options + " --output-per-subdomain " + quoted(out));
}

/// The job of mpi_command started in a session of its own, its launcher (mpiexec), or with
/// `one_rank` the last-started of its pdd-mesh-mpi ranks, killed with SIGKILL after `seconds`
/// (negative: as soon as the first piece file is in `out`, polled every 10 ms for at most 60 s,
/// which does not depend on how loaded the machine is);
/// then the job is given 10 s to end by itself, and is killed (by the session's id) if it has
/// not, so that nothing writes into `out` afterwards. Returns the shell's report ("the job
/// outlived the kill" when it had to be killed).
std::string killed_job(int ranks, const std::string& options, const fs::path& out, double seconds,
                       bool one_rank = false) {
  char sleep[64];
  std::snprintf(sleep, sizeof sleep, "sleep %.3f; ", seconds);
  const std::string wait =
      seconds >= 0.0
          ? std::string(sleep)
          : "for i in $(seq 6000); do ls " + quoted(out) +
                " 2>/dev/null | grep -q '^subdomain_.*[.]vtu$' && break; sleep 0.01; done; ";
  const std::string victim =
      one_rank ? "$(pgrep -s $p -f pdd-mesh-mpi | tail -n 1)" : std::string("$p");
  const std::string script = "setsid " + mpi_command(ranks, options, out) +
                             " >/dev/null 2>&1 & p=$!; " + wait + "kill -KILL " + victim +
                             "; for i in $(seq 100); do pgrep -s $p >/dev/null || "
                             "exit 0; sleep 0.1; done; pkill -KILL -s $p; echo the job outlived "
                             "the kill";
  std::string single_quoted = "'";
  for (const char c : script)
    single_quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return run_command("sh -c " + single_quoted + "'").output;
}

/// The meshings of all ranks in a --stats file.
std::size_t meshings(const nlohmann::json& j) {
  std::size_t n = 0;
  for (const auto& rank : j["per_rank"])
    n += rank["meshings"].get<std::size_t>();
  return n;
}

/// Deletes piece `deleted`, truncates piece `truncated` by 5 bytes and removes the index.
void damage(const fs::path& out, pdd::index_t deleted, pdd::index_t truncated) {
  ASSERT_TRUE(fs::remove(out / pdd::piece_file_name(deleted, pdd::piece_format::vtu)));
  const fs::path t = out / pdd::piece_file_name(truncated, pdd::piece_format::vtu);
  fs::resize_file(t, fs::file_size(t) - 5);
  ASSERT_TRUE(fs::remove(out / "mesh.pvtu"));
}

const std::string options16 = "--max-area 1e-4 --subdomains 16";

/// The jobs that are killed: the pipe in 32 pieces, a clean run of about 3 s on 3 ranks in a
/// release build on 2 cores, so that kills at fractions of it land among the pieces. Under
/// AddressSanitizer (PDD_TEST_SANITIZED) a run at the same area takes 4x longer (8-10x on CI's
/// machine, where the two kill tests then outlived their 600 s), and 5x the area keeps it short.
#ifdef PDD_TEST_SANITIZED
const std::string kill_options = "--max-area 1e-5 --subdomains 32";
#else
const std::string kill_options = "--max-area 2e-6 --subdomains 32";
#endif

// A clean pdd-mesh-mpi run on 3 ranks is pdd-mesh's directory, manifest included; with piece 3
// deleted and piece 5 truncated, --resume on 3 ranks hands out those two subdomains only (2
// meshings over all ranks, 14 pieces kept) and the directory equals the clean run's byte for
// byte; pdd-verify passes on it.
TEST(MpiResume, DeletedAndTruncatedPiecesResumedOnThreeRanksEqualACleanRun) {
  const fs::path root = pdd::test::fresh_dir("mpi_resume_damaged");
  const fs::path clean = root / "clean", out = root / "out", stats = root / "stats.json";
  ASSERT_EQ(threaded(options16 + " --stats " + quoted(root / "clean.json"), clean).code, 0);
  const auto first = mpi(3, options16, out);
  ASSERT_EQ(first.code, 0) << first.output;
  EXPECT_EQ(expect_same_files(clean, out, "clean run on 3 ranks"), 16u + 2u);
  damage(out, 3, 5);
  const auto r = mpi(3, options16 + " --resume --stats " + quoted(stats), out);
  ASSERT_EQ(r.code, 0) << r.output;
  const nlohmann::json j = read_json(stats);
  EXPECT_EQ(j["pieces_kept"], 14);
  EXPECT_EQ(j["pieces_meshed"], 2);
  EXPECT_EQ(j["resumed"], true);
  EXPECT_EQ(meshings(j), 2u) << "only the pieces not intact are handed out";
  EXPECT_EQ(j["triangles"], read_json(root / "clean.json")["triangles"]);
  EXPECT_EQ(expect_same_files(clean, out, "resumed on 3 ranks"), 16u + 2u);
  const auto v = run_command(std::string(PDD_VERIFY_EXE) + " " + quoted(out / "mesh.pvtu") + " " +
                             quoted(pipe_poly) + " --max-area 1e-4 --quiet");
  EXPECT_EQ(v.code, 0) << v.output;
}

// The fingerprints are the same: pdd-mesh-mpi on 2 ranks resumes a damaged pdd-mesh directory,
// and pdd-mesh resumes a damaged pdd-mesh-mpi one; both equal the clean run.
TEST(MpiResume, EitherProgramResumesTheOthersDirectory) {
  const fs::path root = pdd::test::fresh_dir("mpi_resume_either");
  const fs::path clean = root / "clean", by_mesh = root / "mesh", by_mpi = root / "mpi";
  ASSERT_EQ(threaded(options16, clean).code, 0);
  ASSERT_EQ(threaded(options16, by_mesh).code, 0);
  damage(by_mesh, 0, 9);
  const auto r = mpi(2, options16 + " --resume", by_mesh);
  ASSERT_EQ(r.code, 0) << r.output;
  EXPECT_EQ(expect_same_files(clean, by_mesh, "pdd-mesh's, resumed by pdd-mesh-mpi"), 16u + 2u);
  ASSERT_EQ(mpi(3, options16, by_mpi).code, 0);
  damage(by_mpi, 15, 1);
  const auto t = threaded(options16 + " --resume", by_mpi);
  ASSERT_EQ(t.code, 0) << t.output;
  EXPECT_EQ(expect_same_files(clean, by_mpi, "pdd-mesh-mpi's, resumed by pdd-mesh"), 16u + 2u);
}

// The launcher killed with SIGKILL as soon as the first piece is written, at 10 % of a clean
// run's wall time and at a fixed-seed moment between 25 and 75 % of it (kill_options on 3
// ranks; moments alone failed on a loaded machine), then --resume on 3 ranks: the directory
// equals the clean run's, every file; some killed job left pieces that were kept, and some was
// interrupted (pieces meshed on resume). Open MPI's ranks notice the launcher's death and end by
// themselves within about 2 s (a late kill may let them finish the job first).
TEST(MpiResume, AJobWhoseLauncherIsKilledResumesToACleanRun) {
  const fs::path root = pdd::test::fresh_dir("mpi_resume_killed");
  const std::string& options = kill_options;
  const fs::path clean = root / "clean";
  const auto t0 = std::chrono::steady_clock::now();
  ASSERT_EQ(mpi(3, options, clean).code, 0);
  const std::chrono::duration<double> wall = std::chrono::steady_clock::now() - t0;
  std::mt19937 random(40);
  std::uniform_real_distribution<double> moment(0.25 * wall.count(), 0.75 * wall.count());
  std::size_t kept = 0, meshed = 0;
  for (int run = 0; run < 3; ++run) {
    const fs::path out = root / ("run" + std::to_string(run));
    const fs::path stats = root / ("run" + std::to_string(run) + ".json");
    // run 0 after the first piece (some piece is kept), run 1 early (the ranks, which end
    // within about 2 s of the launcher, are left pieces to mesh), run 2 at random
    const double t = run == 0 ? -1.0 : run == 1 ? 0.1 * wall.count() : moment(random);
    const std::string report = killed_job(3, options, out, t);
    const std::string what = t < 0 ? std::string("killed after the first piece")
                                   : "killed at " + std::to_string(t) + " s";
    const bool finished = fs::exists(out / "mesh.pvtu");
    const auto r = mpi(3, options + " --resume --stats " + quoted(stats), out);
    ASSERT_EQ(r.code, 0) << what << ":\n" << r.output;
    EXPECT_EQ(expect_same_files(clean, out, what), 32u + 2u) << what;
    const nlohmann::json j = read_json(stats);
    EXPECT_EQ(j["pieces_kept"].get<std::size_t>() + j["pieces_meshed"].get<std::size_t>(), 32u);
    EXPECT_EQ(meshings(j), j["pieces_meshed"].get<std::size_t>()) << what;
    kept += j["pieces_kept"].get<std::size_t>();
    meshed += j["pieces_meshed"].get<std::size_t>();
    std::printf("%s of %.3f%s: %zu pieces kept on resume %s\n", what.c_str(), wall.count(),
                finished ? " (the ranks finished the job)" : "",
                j["pieces_kept"].get<std::size_t>(), report.c_str());
    fs::remove_all(out);
  }
  EXPECT_GT(kept, 0u) << "no killed job left a piece to keep";
  EXPECT_GT(meshed, 0u) << "no killed job was interrupted";
}

// One rank (a pdd-mesh-mpi process, not the launcher) killed with SIGKILL as soon as the first
// piece is written and at a fixed-seed moment between 30 and 70 % of a clean run's wall time:
// the job ends (Open MPI aborts it), and
// --resume on 3 ranks gives the clean run's directory; some kill interrupted the job.
TEST(MpiResume, AJobWithOneRankKilledResumesToACleanRun) {
  const fs::path root = pdd::test::fresh_dir("mpi_resume_rank_killed");
  const std::string& options = kill_options;
  const fs::path clean = root / "clean";
  const auto t0 = std::chrono::steady_clock::now();
  ASSERT_EQ(mpi(3, options, clean).code, 0);
  const std::chrono::duration<double> wall = std::chrono::steady_clock::now() - t0;
  std::mt19937 random(41);
  std::uniform_real_distribution<double> moment(0.3 * wall.count(), 0.7 * wall.count());
  std::size_t meshed = 0;
  for (int run = 0; run < 2; ++run) {
    const fs::path out = root / ("run" + std::to_string(run));
    const fs::path stats = root / ("run" + std::to_string(run) + ".json");
    const double t = run == 0 ? -1.0 : moment(random); // run 0: after the first piece
    const std::string report = killed_job(3, options, out, t, true);
    const std::string what = (t < 0 ? std::string("one rank killed after the first piece")
                                    : "one rank killed at " + std::to_string(t) + " s") +
                             " " + report;
    const auto r = mpi(3, options + " --resume --stats " + quoted(stats), out);
    ASSERT_EQ(r.code, 0) << what << ":\n" << r.output;
    EXPECT_EQ(expect_same_files(clean, out, what), 32u + 2u) << what;
    const nlohmann::json j = read_json(stats);
    EXPECT_EQ(j["pieces_kept"].get<std::size_t>() + j["pieces_meshed"].get<std::size_t>(), 32u);
    meshed += j["pieces_meshed"].get<std::size_t>();
    std::printf("%s: %zu pieces kept on resume\n", what.c_str(),
                j["pieces_kept"].get<std::size_t>());
    fs::remove_all(out);
  }
  EXPECT_GT(meshed, 0u) << "no job was interrupted by the kill";
}

// A resume with another --max-area is refused (exit 1) naming the option, reported once (rank
// 0), and the directory is left as it was.
TEST(MpiResume, AChangedOptionIsRefusedNamingIt) {
  const fs::path root = pdd::test::fresh_dir("mpi_resume_changed");
  const fs::path out = root / "out";
  ASSERT_EQ(mpi(3, "--max-area 0.001 --subdomains 8", out).code, 0);
  const std::string manifest = pdd::test::read_text(out / pdd::piece_manifest_name);
  const auto r = mpi(3, "--max-area 0.002 --subdomains 8 --resume", out);
  EXPECT_EQ(r.code, 1) << r.output;
  const std::string phrase = "option --max-area differs: 0.001 in the manifest, 0.002 now";
  const std::size_t at = r.output.find(phrase);
  EXPECT_NE(at, std::string::npos) << r.output;
  EXPECT_EQ(r.output.find(phrase, at + 1), std::string::npos) << "reported twice:\n" << r.output;
  EXPECT_EQ(pdd::test::read_text(out / pdd::piece_manifest_name), manifest);
  EXPECT_TRUE(fs::exists(out / "mesh.pvtu"));
}

// Without --resume or --overwrite a non-empty directory is refused (exit 1) and left alone;
// --overwrite replaces pdd's files (a file of the user's stays) and equals a clean run; both
// flags: usage (exit 2).
TEST(MpiResume, ANonEmptyDirectoryNeedsResumeOrOverwrite) {
  const fs::path root = pdd::test::fresh_dir("mpi_resume_non_empty");
  const fs::path clean = root / "clean", out = root / "out";
  const std::string options = "--max-area 1e-3 --subdomains 8";
  ASSERT_EQ(mpi(3, options, clean).code, 0);
  fs::create_directories(out);
  pdd::test::write_text(out / "notes.txt", "mine");
  const auto refused = mpi(3, options, out);
  EXPECT_EQ(refused.code, 1) << refused.output;
  EXPECT_NE(refused.output.find("is not empty: --resume continues the run that wrote it, "
                                "--overwrite replaces its pieces"),
            std::string::npos)
      << refused.output;
  EXPECT_EQ(pdd::test::dir_entries(out), std::vector<std::string>{"notes.txt"});
  ASSERT_EQ(mpi(2, "--max-area 1e-3 --subdomains 16 --overwrite", out).code, 0);
  EXPECT_EQ(mpi(3, options, out).code, 1); // a finished run's directory
  const auto r = mpi(3, options + " --overwrite", out);
  ASSERT_EQ(r.code, 0) << r.output;
  EXPECT_TRUE(fs::exists(out / "notes.txt"));
  fs::remove(out / "notes.txt");
  EXPECT_EQ(expect_same_files(clean, out, "--overwrite"), 8u + 2u);
  EXPECT_EQ(mpi(2, options + " --resume --overwrite", out).code, 2);
}

} // namespace mpi_resume_test
