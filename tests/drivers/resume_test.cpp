// pdd-mesh --output-per-subdomain --resume (issue 40): a run killed with SIGKILL at fixed-seed
// moments and resumed writes, file for file and byte for byte, the directory of a clean run
// (pieces, index and manifest; both formats); a truncated and a tampered piece are meshed again,
// not trusted; a changed option or input is refused with what differs; a non-empty directory is
// refused without --resume or --overwrite; --stats counts the pieces kept and meshed.
#include <pdd/io/piece_files.hpp>
#include <pdd/io/piece_manifest.hpp>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "same_files.hpp"
#include "test_files.hpp"
#include "test_support.hpp"

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>
#include <vector>

namespace resume_test {
namespace fs = std::filesystem;
using pdd::test::expect_same_files;
using pdd::test::read_json;

namespace {

const std::string pipe_poly = pdd::test::bundled_data("pipe.poly").string();

/// pdd-mesh on `poly` with `args` (-q added), killed with SIGKILL after `seconds` (0: never).
pdd::test::command_result pdd_mesh(const std::string& poly, const std::string& args,
                                   double seconds = 0.0) {
  char limit[64] = "";
  if (seconds > 0.0) std::snprintf(limit, sizeof limit, "timeout -s KILL %.3f ", seconds);
  return pdd::test::run_command(std::string(limit) + "'" + PDD_MESH_EXE + "' '" + poly + "' -q " +
                                args);
}

/// The per-subdomain options of a run into dir in `format`.
std::string into(const fs::path& dir, const std::string& format) {
  return "--format " + format + " --output-per-subdomain '" + dir.string() + "'";
}

} // namespace

// Killed at 4 fixed-seed moments per format (the pipe at 2e-6 in 32 pieces: about 1 s on two
// cores; under AddressSanitizer, PDD_TEST_SANITIZED, 1e-5: the same 32 pieces in a fifth of the
// triangles, since 2e-6 took 200 s of CI's test time; the moments between 30 and 95 % of the
// clean run's wall time, so that a loaded machine kills as late), then resumed: the directory
// equals the clean run's, every file, manifest included; some pieces are kept.
TEST(Resume, AKilledRunResumedEqualsACleanRunByteForByte) {
  const fs::path root = pdd::test::fresh_dir("killed");
#ifdef PDD_TEST_SANITIZED
  const std::string options = "--max-area 1e-5 --subdomains 32 ";
#else
  const std::string options = "--max-area 2e-6 --subdomains 32 ";
#endif
  for (const std::string format : {"vtu", "binary"}) {
    const fs::path clean = root / ("clean_" + format);
    const auto t0 = std::chrono::steady_clock::now();
    ASSERT_EQ(pdd_mesh(pipe_poly, options + into(clean, format)).code, 0);
    const std::chrono::duration<double> wall = std::chrono::steady_clock::now() - t0;
    ASSERT_TRUE(fs::exists(clean / pdd::piece_manifest_name));
    std::mt19937 random(40);
    std::uniform_real_distribution<double> moment(0.3 * wall.count(), 0.95 * wall.count());
    std::size_t kept = 0;
    for (int run = 0; run < 4; ++run) {
      const fs::path out = root / (format + std::to_string(run));
      const double t = moment(random);
      const auto killed = pdd_mesh(pipe_poly, options + into(out, format), t);
      const fs::path stats = root / (format + std::to_string(run) + ".json");
      const auto r = pdd_mesh(pipe_poly, options + into(out, format) + " --resume --stats '" +
                                             stats.string() + "'");
      const std::string what = format + " killed at " + std::to_string(t) + " s";
      ASSERT_EQ(r.code, 0) << what << ":\n" << r.output;
      EXPECT_EQ(expect_same_files(clean, out, what), 32u + 2u) << what; // pieces, index, manifest
      const nlohmann::json j = read_json(stats);
      EXPECT_EQ(j["pieces_kept"].get<std::size_t>() + j["pieces_meshed"].get<std::size_t>(), 32u);
      kept += j["pieces_kept"].get<std::size_t>();
      std::printf("%s killed at %.3f s of %.3f (exit %d): %zu pieces kept on resume\n",
                  format.c_str(), t, wall.count(), killed.code,
                  j["pieces_kept"].get<std::size_t>());
      fs::remove_all(out);
    }
    EXPECT_GT(kept, 0u) << format << ": no killed run left a piece to keep";
  }
}

// A truncated piece, a piece with one byte changed (same size), a missing index and a stray
// temporary: the two pieces are meshed again, the other 14 kept; the result equals a clean run,
// pdd-verify passes on it, and a second --resume keeps all 16.
TEST(Resume, TruncatedAndTamperedPiecesAreMeshedAgain) {
  const fs::path root = pdd::test::fresh_dir("tampered");
  const std::string options = "--max-area 1e-4 --subdomains 16 ";
  for (const std::string format : {"vtu", "binary"}) {
    const pdd::piece_format f =
        format == "binary" ? pdd::piece_format::binary : pdd::piece_format::vtu;
    const fs::path clean = root / ("clean_" + format), out = root / format;
    const fs::path stats = root / (format + ".json");
    ASSERT_EQ(pdd_mesh(pipe_poly, options + into(clean, format)).code, 0);
    ASSERT_EQ(pdd_mesh(pipe_poly, options + into(out, format)).code, 0);
    const fs::path truncated = out / pdd::piece_file_name(3, f);
    fs::resize_file(truncated, fs::file_size(truncated) - 5);
    const fs::path tampered = out / pdd::piece_file_name(5, f);
    std::string bytes = pdd::test::read_text(tampered);
    bytes[bytes.size() / 2] = static_cast<char>(bytes[bytes.size() / 2] ^ 0x10);
    pdd::test::write_text(tampered, bytes);
    fs::remove(out / pdd::piece_index_name(f));
    pdd::test::write_text(
        out / (".subdomain_7" + std::string(pdd::piece_extension(f)) + ".pdd-tmp-0123456789abcdef"),
        "half a piece");
    const auto r = pdd_mesh(pipe_poly, options + into(out, format) + " --resume --stats '" +
                                           stats.string() + "'");
    ASSERT_EQ(r.code, 0) << r.output;
    nlohmann::json j = read_json(stats);
    EXPECT_EQ(j["pieces_kept"], 14) << format;
    EXPECT_EQ(j["pieces_meshed"], 2) << format;
    EXPECT_EQ(j["resumed"], true);
    EXPECT_EQ(expect_same_files(clean, out, format), 16u + 2u);
    const auto v =
        pdd::test::run_command("'" + std::string(PDD_VERIFY_EXE) + "' '" +
                               (out / pdd::piece_index_name(f)).string() + "' '" + pipe_poly + "'");
    EXPECT_EQ(v.code, 0) << v.output;
    ASSERT_EQ(pdd_mesh(pipe_poly,
                       options + into(out, format) + " --resume --stats '" + stats.string() + "'")
                  .code,
              0);
    j = read_json(stats);
    EXPECT_EQ(j["pieces_kept"], 16) << format;
    EXPECT_EQ(j["pieces_meshed"], 0) << format;
  }
}

// A resume with another option or another input is refused (exit 1) with what differs, and
// leaves the directory as it was.
TEST(Resume, AChangedOptionOrInputIsRefused) {
  const fs::path root = pdd::test::fresh_dir("changed");
  const fs::path out = root / "out", poly = root / "pipe.poly";
  fs::copy_file(pipe_poly, poly);
  ASSERT_EQ(pdd_mesh(poly.string(), "--max-area 0.001 --subdomains 8 " + into(out, "vtu")).code, 0);
  const std::string manifest = pdd::test::read_text(out / pdd::piece_manifest_name);
  const auto area =
      pdd_mesh(poly.string(), "--max-area 0.002 --subdomains 8 --resume " + into(out, "vtu"));
  EXPECT_EQ(area.code, 1) << area.output;
  EXPECT_NE(area.output.find("option --max-area differs: 0.001 in the manifest, 0.002 now"),
            std::string::npos)
      << area.output;
  const auto format =
      pdd_mesh(poly.string(), "--max-area 0.001 --subdomains 8 --resume " + into(out, "binary"));
  EXPECT_EQ(format.code, 1) << format.output;
  EXPECT_NE(format.output.find("option --format differs: vtu in the manifest, binary now"),
            std::string::npos)
      << format.output;
  {
    std::ofstream append(poly, std::ios::app);
    append << "# one more line\n";
  }
  const auto input =
      pdd_mesh(poly.string(), "--max-area 0.001 --subdomains 8 --resume " + into(out, "vtu"));
  EXPECT_EQ(input.code, 1) << input.output;
  EXPECT_NE(input.output.find("input differs: "), std::string::npos) << input.output;
  EXPECT_EQ(pdd::test::read_text(out / pdd::piece_manifest_name), manifest);
  EXPECT_TRUE(fs::exists(out / "mesh.pvtu"));
}

// Without --resume or --overwrite a non-empty directory is refused (exit 1) and left alone;
// --overwrite replaces pdd's files (a file of the user's stays); both flags: usage (exit 2).
TEST(Resume, ANonEmptyDirectoryNeedsResumeOrOverwrite) {
  const fs::path root = pdd::test::fresh_dir("non_empty");
  const fs::path clean = root / "clean", out = root / "out";
  const std::string options = "--max-area 1e-3 --subdomains 8 ";
  ASSERT_EQ(pdd_mesh(pipe_poly, options + into(clean, "vtu")).code, 0);
  fs::create_directories(out);
  pdd::test::write_text(out / "notes.txt", "mine");
  const auto refused = pdd_mesh(pipe_poly, options + into(out, "vtu"));
  EXPECT_EQ(refused.code, 1) << refused.output;
  EXPECT_NE(refused.output.find("is not empty: --resume continues the run that wrote it, "
                                "--overwrite replaces its pieces"),
            std::string::npos)
      << refused.output;
  EXPECT_EQ(pdd::test::dir_entries(out), std::vector<std::string>{"notes.txt"});
  // a finished run's directory, and one of another run (other N: pieces 8..15 are stale)
  ASSERT_EQ(
      pdd_mesh(pipe_poly, "--max-area 1e-3 --subdomains 16 --overwrite " + into(out, "vtu")).code,
      0);
  EXPECT_EQ(pdd_mesh(pipe_poly, options + into(out, "vtu")).code, 1);
  const auto r = pdd_mesh(pipe_poly, options + "--overwrite " + into(out, "vtu"));
  ASSERT_EQ(r.code, 0) << r.output;
  fs::remove(out / "notes.txt");
  EXPECT_EQ(expect_same_files(clean, out, "--overwrite"), 8u + 2u);
  EXPECT_EQ(pdd_mesh(pipe_poly, options + "--resume --overwrite " + into(out, "vtu")).code, 2);
  EXPECT_EQ(pdd_mesh(pipe_poly, options + "--resume").code, 2); // no per-subdomain output
}

// The disk-space check of a --resume counts the bytes of the pieces it may keep as free: a
// finished run resumes where the whole output would not fit any more, a fresh run is refused.
TEST(Resume, TheDiskCheckCountsThePiecesKept) {
  const fs::path root = pdd::test::fresh_dir("disk");
  const fs::path out = root / "out";
  const std::string options = "--max-area 1e-3 --subdomains 16 --assume-free-bytes 30000 ";
  ASSERT_EQ(pdd_mesh(pipe_poly, "--max-area 1e-3 --subdomains 16 " + into(out, "vtu")).code, 0);
  const auto fresh = pdd_mesh(pipe_poly, options + into(root / "fresh", "vtu"));
  EXPECT_EQ(fresh.code, 1) << fresh.output;
  EXPECT_NE(fresh.output.find("would need about"), std::string::npos) << fresh.output;
  const auto resumed = pdd_mesh(pipe_poly, options + "--resume " + into(out, "vtu"));
  EXPECT_EQ(resumed.code, 0) << resumed.output;
}

// A full disk (a 256 KiB tmpfs, --no-disk-check) fails the run with exit 1 and leaves no piece (the
// durable-output rule); once there is space (the tmpfs remounted at 64 MiB), --resume finishes and
// the directory equals a clean run's, every file (the pipe at 1e-4 in 8 pieces, both formats).
TEST(Resume, AfterAFullDiskResumeFinishesAsACleanRun) {
  const fs::path root = pdd::test::fresh_dir("full_disk");
  const fs::path disk = pdd::test::temp_path("resume_full_disk");
  pdd::test::small_file_system full(disk, "256k");
  if (!full.mounted()) GTEST_SKIP() << "cannot mount a tmpfs here (not root)";
  const std::string options = "--max-area 1e-4 --subdomains 8 --no-disk-check ";
  for (const std::string format : {"vtu", "binary"}) {
    const fs::path clean = root / format, out = disk / format;
    ASSERT_EQ(pdd_mesh(pipe_poly, options + into(clean, format)).code, 0);
    const auto failed = pdd_mesh(pipe_poly, options + into(out, format));
    EXPECT_EQ(failed.code, 1) << failed.output;
    EXPECT_NE(failed.output.find("No space left on device"), std::string::npos) << failed.output;
    ASSERT_TRUE(full.resize("64m"));
    const auto r = pdd_mesh(pipe_poly, options + "--resume " + into(out, format));
    ASSERT_EQ(r.code, 0) << format << ": " << r.output;
    EXPECT_EQ(expect_same_files(clean, out, format + " after a full disk"), 8u + 2u);
    fs::remove_all(out);
    ASSERT_TRUE(full.resize("256k"));
  }
}

} // namespace resume_test
