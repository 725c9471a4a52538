// pdd::read_vtu and pdd::read_pvtu: round trips of pdd's own writers (bitwise), and clean
// errors (never a crash, never a read past the end) for truncated or tampered files.
#include <pdd/io/vtu.hpp>
#include <pdd/io/vtu_read.hpp>

#include "mesh_compare.hpp"
#include "random_soup.hpp"
#include "test_files.hpp"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <random>
#include <string>

namespace vtu_read_test {
namespace fs = std::filesystem;

namespace {

using pdd::test::random_triangle_soup;

std::string error_of(const fs::path& p) {
  try {
    (void)pdd::read_vtu(p);
  } catch (const pdd::error& e) {
    return e.what();
  }
  return "";
}

} // namespace

TEST(ReadVtu, RoundTripIsBitwise) {
  for (unsigned seed = 1; seed <= 20; ++seed) {
    const auto m = random_triangle_soup(seed, 1 + seed * 7, seed * 11);
    const auto p = pdd::test::temp_path(std::to_string(seed).append(".vtu"));
    pdd::write_vtu(p, m);
    const pdd::triangle_mesh r = pdd::read_vtu(p);
    EXPECT_TRUE(pdd::test::bitwise_equal(r, m)) << seed;
    EXPECT_TRUE(r.segments.empty());
  }
}

TEST(ReadVtu, TruncationsAreCleanErrorsNamingTheFile) {
  const auto m = random_triangle_soup(3, 9, 12);
  const auto whole = pdd::test::temp_path("whole.vtu");
  pdd::write_vtu(whole, m);
  const std::string bytes = pdd::test::read_text(whole);
  const auto cut = pdd::test::temp_path("cut.vtu");
  std::size_t errors = 0;
  // Every length that loses appended data (the trailing XML after it is not needed).
  const std::size_t data_end = bytes.rfind("\n  </AppendedData>");
  ASSERT_NE(data_end, std::string::npos);
  std::size_t tried = 0;
  // Every 5th length, and each of the last 64 bytes of the data (writing files is the cost).
  for (std::size_t len = 0; len < data_end; len += (len + 64 < data_end ? 5 : 1), ++tried) {
    pdd::test::write_text(cut, bytes.substr(0, len));
    const std::string e = error_of(cut);
    EXPECT_NE(e.find(cut.string()), std::string::npos) << "length " << len << ": " << e;
    errors += !e.empty();
  }
  EXPECT_EQ(errors, tried);
  EXPECT_GT(tried, 100u);
}

TEST(ReadVtu, TamperedFilesAreRefusedWithTheReason) {
  const auto m = random_triangle_soup(4, 6, 5);
  const auto p = pdd::test::temp_path("t.vtu");
  pdd::write_vtu(p, m);
  const std::string good = pdd::test::read_text(p);
  const auto tampered = [&](const std::string& from, const std::string& to) {
    std::string s = good;
    const std::size_t at = s.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    s.replace(at, from.size(), to);
    pdd::test::write_text(p, s);
    return error_of(p);
  };
  EXPECT_NE(tampered("NumberOfPoints=\"6\"", "NumberOfPoints=\"7\"").find("holds"),
            std::string::npos);
  EXPECT_NE(tampered("NumberOfCells=\"5\"", "NumberOfCells=\"99999999999\"").find("exceeds"),
            std::string::npos);
  EXPECT_NE(tampered("header_type=\"UInt64\"", "header_type=\"UInt32\"").find("UInt64"),
            std::string::npos);
  EXPECT_NE(tampered("encoding=\"raw\"", "encoding=\"base64\"").find("AppendedData"),
            std::string::npos);
  EXPECT_NE(tampered("Name=\"connectivity\"", "Name=\"connectivitx\"").find("connectivity"),
            std::string::npos);
  EXPECT_NE(tampered("type=\"UInt8\"", "type=\"Int8\"").find("types"), std::string::npos);
  EXPECT_NE(error_of(pdd::test::temp_path("missing.vtu")).find("cannot open"), std::string::npos);
  // A vertex index out of range in the connectivity block.
  pdd::write_vtu(p, m);
  std::string s = pdd::test::read_text(p);
  const std::string key = "Name=\"connectivity\" format=\"appended\" offset=\"";
  const std::size_t at = s.find(key);
  ASSERT_NE(at, std::string::npos);
  const std::size_t offset = std::stoul(s.substr(at + key.size()));
  const std::size_t data = s.find('_', s.find("<AppendedData")) + 1;
  const std::int32_t missing = 1000;
  ASSERT_LE(data + offset + 8 + sizeof missing, s.size());
  std::memcpy(s.data() + data + offset + 8, &missing, sizeof missing);
  pdd::test::write_text(p, s);
  EXPECT_NE(error_of(p).find("missing point 1000"), std::string::npos) << error_of(p);
}

TEST(ReadPvtu, ListsThePiecesRelativeToItsFolder) {
  const auto dir = pdd::test::fresh_dir("pvtu");
  pdd::write_pvtu(dir / "mesh.pvtu", {"a&b.vtu", "sub/c.vtu"});
  const auto pieces = pdd::read_pvtu(dir / "mesh.pvtu");
  ASSERT_EQ(pieces.size(), 2u);
  EXPECT_EQ(pieces[0], dir / "a&b.vtu");
  EXPECT_EQ(pieces[1], dir / "sub/c.vtu");
  pdd::test::write_text(dir / "bad.pvtu", "<?xml version=\"1.0\"?>\n<VTKFile type=\"Unstr\">");
  EXPECT_THROW((void)pdd::read_pvtu(dir / "bad.pvtu"), pdd::error);
  pdd::test::write_text(dir / "empty.pvtu", "");
  try {
    (void)pdd::read_pvtu(dir / "empty.pvtu");
    FAIL() << "an empty .pvtu was accepted";
  } catch (const pdd::error& e) {
    EXPECT_NE(std::string(e.what()).find("empty.pvtu"), std::string::npos) << e.what();
  }
}

} // namespace vtu_read_test
