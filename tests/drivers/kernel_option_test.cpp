// pdd-mesh --kernel: the native kernel from the command line, verified, bitwise identical
// across thread counts, named in --stats; unknown kernels are refused.
#include "test_files.hpp"
#include "test_support.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

namespace kernel_option_test {
namespace {

std::string slurp(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

const std::string exe = std::string("'") + PDD_MESH_EXE + "' ";

} // namespace

TEST(PddMeshKernel, NativeDecoupledIsVerifiedAndThreadIndependent) {
  const std::string input = pdd::test::bundled_data("pipe.poly").string();
  const std::filesystem::path a = pdd::test::temp_path("native_t1.node"),
                              b = pdd::test::temp_path("native_t2.node");
  const auto ele = [](std::filesystem::path p) { return p.replace_extension(".ele"); };
  const auto stats = pdd::test::temp_path("native_stats.json");
  const std::string common = input + " --kernel native --max-area 1e-4 --subdomains 16 -q ";
  const auto r1 = pdd::test::run_command(exe + common + "--threads 1 --verify -o " + a.string() +
                                         " --stats " + stats.string());
  ASSERT_EQ(r1.code, 0) << r1.output;
  const auto r2 = pdd::test::run_command(exe + common + "--threads 2 -o " + b.string());
  ASSERT_EQ(r2.code, 0) << r2.output;
  const nlohmann::json j = nlohmann::json::parse(slurp(stats));
  EXPECT_EQ(j["kernel"], "native");
  EXPECT_EQ(j["verified"], true);
  EXPECT_EQ(j["conforming"], true);
  EXPECT_GT(j["triangles"].get<std::size_t>(), 10000u);
  const std::string ea = slurp(ele(a)), eb = slurp(ele(b));
  EXPECT_FALSE(ea.empty());
  EXPECT_EQ(ea, eb) << "the native kernel's mesh differs between 1 and 2 threads";
  EXPECT_EQ(slurp(a), slurp(b));
}

TEST(PddMeshKernel, UnknownKernelIsRefused) {
  const auto r = pdd::test::run_command(exe + pdd::test::bundled_data("key.poly").string() +
                                        " --kernel triangle -q");
  EXPECT_NE(r.code, 0);
  EXPECT_NE(r.output.find("--kernel"), std::string::npos) << r.output;
}

} // namespace kernel_option_test
