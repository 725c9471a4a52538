// pdd-mesh --format binary with pdd-convert (its .vtu pieces and .pvtu byte for byte pdd-mesh's
// VTU output; clean errors for truncated, tampered and wrong-version files, and no half output),
// and the disk-space check up front (refusal with the estimate and no output; the estimate
// against the bytes actually written).
#include <pdd/io/binary_mesh.hpp>
#include <pdd/io/piece_files.hpp>
#include <pdd/io/piece_manifest.hpp>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "test_files.hpp"
#include "test_support.hpp"

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace binary_output_test {
namespace fs = std::filesystem;

namespace {

pdd::test::command_result run(const std::string& exe, const std::string& args) {
  return pdd::test::run_command("'" + exe + "' " + args);
}

const std::string pipe_options =
    pdd::test::bundled_data("pipe.poly").string() + " --max-area 1e-3 --subdomains 16 -q";

/// pdd-mesh's per-subdomain output of the pipe in `format` into dir (with --stats dir.json).
void mesh_pipe(const fs::path& dir, const std::string& format, const std::string& extra = "") {
  const auto r =
      run(PDD_MESH_EXE, pipe_options + " --format " + format + " --output-per-subdomain " +
                            dir.string() + " --stats " + dir.string() + ".json " + extra);
  ASSERT_EQ(r.code, 0) << r.output;
}

/// The bytes of the pieces and the index in dir (not the manifest, pdd::piece_manifest_name).
std::uintmax_t bytes_in(const fs::path& dir) {
  std::uintmax_t n = 0;
  for (const auto& e : fs::directory_iterator(dir))
    if (e.path().filename() != pdd::piece_manifest_name) n += e.file_size();
  return n;
}

} // namespace

TEST(PddConvert, OutputEqualsPddMeshsVtuOutput) {
  const fs::path root = pdd::test::fresh_dir("convert");
  mesh_pipe(root / "vtu", "vtu");
  mesh_pipe(root / "bin", "binary");
  const auto r = run(PDD_CONVERT_EXE,
                     (root / "bin" / "mesh.pddi").string() + " " + (root / "converted").string());
  ASSERT_EQ(r.code, 0) << r.output;
  std::vector<std::string> names = pdd::test::dir_entries(root / "vtu");
  std::erase(names, pdd::piece_manifest_name); // pdd-mesh's manifest: pdd-convert writes none
  ASSERT_EQ(names.size(), 17u);
  EXPECT_EQ(pdd::test::dir_entries(root / "converted"), names);
  std::size_t same = 0;
  for (const std::string& n : names)
    same += pdd::test::read_text(root / "vtu" / n) == pdd::test::read_text(root / "converted" / n);
  EXPECT_EQ(same, 17u) << "files differ from pdd-mesh's VTU output";
  // one piece -> one .vtu
  const auto one = run(PDD_CONVERT_EXE, (root / "bin" / "subdomain_7.pddm").string() + " " +
                                            (root / "seven.vtu").string() + " -q");
  ASSERT_EQ(one.code, 0) << one.output;
  EXPECT_EQ(pdd::test::read_text(root / "seven.vtu"),
            pdd::test::read_text(root / "vtu" / "subdomain_7.vtu"));
  // the binary output is less than half the VTU output (about 14 against 35 bytes per triangle)
  EXPECT_LT(2 * bytes_in(root / "bin"), bytes_in(root / "vtu"));
}

TEST(PddConvert, BadFilesAreCleanErrorsWithNoHalfOutput) {
  const fs::path root = pdd::test::fresh_dir("convert_bad");
  mesh_pipe(root / "bin", "binary");
  const fs::path piece = root / "bin" / "subdomain_9.pddm";
  const std::string good = pdd::test::read_text(piece);
  const auto convert = [&](const std::string& what) {
    const auto r =
        run(PDD_CONVERT_EXE, (root / "bin" / "mesh.pddi").string() + " " + (root / "out").string());
    EXPECT_EQ(r.code, 1) << r.output;
    EXPECT_NE(r.output.find("pdd-convert: error: " + piece.string() + ": "), std::string::npos)
        << r.output;
    EXPECT_NE(r.output.find(what), std::string::npos) << r.output;
    EXPECT_TRUE(pdd::test::dir_entries(root / "out").empty()) << "half output left";
  };
  fs::resize_file(piece, good.size() - 3);
  convert("truncated");
  std::string tampered = good;
  tampered[100] = static_cast<char>(tampered[100] ^ 1);
  pdd::test::write_text(piece, tampered);
  convert("checksum mismatch");
  std::string version = good;
  version[8] = 9;
  pdd::test::write_text(piece, version);
  convert("binary mesh version 9; this reader reads version 1 only");
  // a VTU input, a missing file, no arguments
  mesh_pipe(root / "vtu", "vtu");
  const auto vtu = run(PDD_CONVERT_EXE, (root / "vtu" / "mesh.pvtu").string() + " x");
  EXPECT_EQ(vtu.code, 1) << vtu.output;
  EXPECT_NE(vtu.output.find("already VTU"), std::string::npos) << vtu.output;
  EXPECT_EQ(run(PDD_CONVERT_EXE, (root / "none.pddm").string() + " x.vtu").code, 1);
  EXPECT_EQ(run(PDD_CONVERT_EXE, "").code, 2);
}

TEST(DiskCheck, RefusesUpFrontWithTheEstimateAndWritesNothing) {
  const fs::path root = pdd::test::fresh_dir("disk_check");
  for (const char* format : {"vtu", "binary"}) {
    const fs::path dir = root / format;
    const auto r =
        run(PDD_MESH_EXE, pipe_options + " --format " + format +
                              " --assume-free-bytes 20000 --output-per-subdomain " + dir.string());
    EXPECT_EQ(r.code, 1) << r.output;
    EXPECT_NE(r.output.find("pdd-mesh: error: the per-subdomain output would need about"),
              std::string::npos)
        << r.output;
    EXPECT_NE(r.output.find(std::string(format) + " format"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("has 2e+04 bytes free (--assume-free-bytes)"), std::string::npos)
        << r.output;
    EXPECT_FALSE(fs::exists(dir)) << format;
    // enough room, or no check: the run goes ahead
    mesh_pipe(dir, format, "--assume-free-bytes 100000000");
    EXPECT_TRUE(fs::exists(dir / pdd::piece_index_name(std::string(format) == "binary"
                                                           ? pdd::piece_format::binary
                                                           : pdd::piece_format::vtu)));
  }
  mesh_pipe(root / "unchecked", "binary", "--no-disk-check");
  // usage: both, or either without a per-subdomain output
  EXPECT_EQ(run(PDD_MESH_EXE, pipe_options +
                                  " --no-disk-check --assume-free-bytes 5 "
                                  "--output-per-subdomain " +
                                  (root / "x").string())
                .code,
            2);
  EXPECT_EQ(run(PDD_MESH_EXE, pipe_options + " --format binary").code, 2);
  EXPECT_EQ(run(PDD_MESH_EXE, pipe_options + " --format xml --output-per-subdomain x").code, 2);
}

// The estimate the check uses against the bytes written (pipe, about 6.3K triangles, 16
// pieces, and 0.1M triangles, 32 pieces): within 20 %.
TEST(DiskCheck, EstimateMatchesTheBytesWritten) {
  const fs::path root = pdd::test::fresh_dir("disk_estimate");
  std::size_t checked = 0;
  for (const char* area : {"1e-3", "4e-5"})
    for (const auto f : {pdd::piece_format::vtu, pdd::piece_format::binary}) {
      const fs::path dir = root / (std::string(pdd::to_string(f)) + area);
      const auto r =
          run(PDD_MESH_EXE, pdd::test::bundled_data("pipe.poly").string() + " --max-area " + area +
                                " -q --format " + pdd::to_string(f) + " --output-per-subdomain " +
                                dir.string() + " --stats " + dir.string() + ".json");
      ASSERT_EQ(r.code, 0) << r.output;
      const auto j = nlohmann::json::parse(pdd::test::read_text(dir.string() + ".json"));
      EXPECT_EQ(j["format"], pdd::to_string(f));
      EXPECT_EQ(j["per_subdomain_dir"], dir.string());
      EXPECT_TRUE(j["output"].is_null());
      const double estimate = pdd::estimated_piece_bytes(f, j["estimated_triangles"].get<double>(),
                                                         j["subdomains"].get<double>());
      const double written = static_cast<double>(bytes_in(dir));
      EXPECT_GT(estimate, 0.8 * written) << dir;
      EXPECT_LT(estimate, 1.2 * written) << dir;
      ++checked;
    }
  EXPECT_EQ(checked, 4u);
}

} // namespace binary_output_test
