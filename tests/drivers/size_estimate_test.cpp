// The up-front size estimate and refusal of pdd-mesh (issue 17 item 5): a needle that would
// need billions of triangles is refused before any meshing, within seconds and little memory,
// naming its small angle; a spike is meshed, and refused under --max-triangles below its
// estimate; the estimate is within a factor 2 of the triangles made on the shared geometries.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "test_files.hpp"
#include "test_support.hpp"

#include <chrono>
#include <filesystem>
#include <fstream>
#include <string>

namespace size_estimate_test {
namespace {

nlohmann::json read_json(const std::filesystem::path& p) {
  std::ifstream in(p);
  return nlohmann::json::parse(in);
}

/// The pdd-mesh command line with these arguments.
std::string pdd_mesh(const std::string& args) {
  std::string c = "'";
  c += PDD_MESH_EXE;
  c += "' ";
  c += args;
  return c;
}

/// The shell prefix that caps the address space at 1 GiB; empty under AddressSanitizer or
/// ThreadSanitizer, whose shadow memory alone reserves terabytes of address space.
std::string address_space_limit() {
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
  return "";
#elif defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(thread_sanitizer)
  return "";
#else
  return "ulimit -v 1048576; ";
#endif
#else
  return "ulimit -v 1048576; ";
#endif
}

/// An isosceles triangle with base 1 and the given height.
std::string spike_poly(const std::string& height) {
  return "3 2 0 0\n1 0 0\n2 1 0\n3 0.5 " + height + "\n3 0\n1 1 2\n2 2 3\n3 3 1\n0\n";
}

} // namespace

TEST(SizeEstimate, NeedleIsRefusedUpFrontNamingItsAngle) {
  // The needle of issue 17: width 1, length 4.4e9 (an angle of 1.3e-8 deg). Under a 1 GiB
  // address-space limit (ulimit -v; not under the sanitizers) it must be refused with exit 1
  // (bad input); meshing it would run until it holds tens of GiB.
  const std::string poly = pdd::test::write_temp_file(
      "needle.poly", "3 2 0 0\n1 0 1\n2 1 0\n3 0.5 4444444422\n3 0\n1 1 2\n2 2 3\n3 3 1\n0\n");
  const auto t0 = std::chrono::steady_clock::now();
  const auto r =
      pdd::test::run_command(address_space_limit() + pdd_mesh(poly + " --max-area 1.48e7 -q"));
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  EXPECT_EQ(r.code, 1) << r.output;
  EXPECT_LT(seconds, 10.0); // a generous guard: the estimate does not mesh
  for (const char* part : {"triangles", "by the area bound alone", "the angle of",
                           "at vertex 2 (0.5, 4.44444e+09)", "GiB"})
    EXPECT_NE(r.output.find(part), std::string::npos) << part << "\n" << r.output;
}

TEST(SizeEstimate, SpikeIsMeshedAndRefusedBelowItsEstimate) {
  // Aspect 10^4:1 at A = 100: the estimate follows the wedge (about 3.3e4 triangles; 76 by
  // area), the kernel makes about 2.1e4.
  const std::string poly = pdd::test::write_temp_file("spike.poly", spike_poly("10000"));
  const auto stats = pdd::test::temp_path("spike.json");
  const std::string exe = pdd_mesh(poly + " --max-area 100 --subdomains 1 -q");
  const auto ok = pdd::test::run_command(exe + " --stats " + stats.string());
  ASSERT_EQ(ok.code, 0) << ok.output;
  const auto j = read_json(stats);
  const double estimate = j["estimated_triangles"].get<double>();
  const double made = j["triangles"].get<double>();
  EXPECT_GT(estimate, 100.0 * 76.0); // far above area / (0.656 A): the features count
  EXPECT_LT(estimate / made, 2.0);
  EXPECT_GT(estimate / made, 0.5);
  const auto refused = pdd::test::run_command(exe + " --max-triangles " +
                                              std::to_string(static_cast<long long>(estimate / 2)));
  EXPECT_EQ(refused.code, 1) << refused.output;
  EXPECT_NE(refused.output.find("max_triangles"), std::string::npos) << refused.output;
  EXPECT_NE(refused.output.find("at vertex 2"), std::string::npos) << refused.output;
}

TEST(SizeEstimate, WithinAFactorTwoOnTheSharedGeometries) {
  const auto dir = pdd::test::shared_data_dir();
  if (dir.empty()) GTEST_SKIP() << "../shared/data is absent";
  struct input {
    const char* file;
    const char* max_area; // "" : quality only (graded by the geometry alone)
  };
  const input inputs[] = {{"lake_superior.poly", ""},
                          {"lake_superior.poly", "1e-4"},
                          {"texas.poly", ""},
                          {"mesh2d_airfoil_3element.poly", ""},
                          {"mesh2d_airfoil_3element.poly", "1e-4"},
                          {"guitar.poly", ""},
                          {"triangle_A.poly", ""}};
  int checked = 0;
  for (const input& in : inputs) {
    const auto stats = pdd::test::temp_path("shared.json");
    const std::string area = *in.max_area ? std::string(" --max-area ") + in.max_area : "";
    const auto r = pdd::test::run_command(
        pdd_mesh((dir / in.file).string() + area + " --subdomains 1 -q --stats " + stats.string()));
    ASSERT_EQ(r.code, 0) << in.file << area << "\n" << r.output;
    const auto j = read_json(stats);
    const double ratio = j["estimated_triangles"].get<double>() / j["triangles"].get<double>();
    EXPECT_LT(ratio, 2.0) << in.file << area;
    EXPECT_GT(ratio, 0.5) << in.file << area;
    ++checked;
  }
  EXPECT_EQ(checked, 7);
}

} // namespace size_estimate_test
