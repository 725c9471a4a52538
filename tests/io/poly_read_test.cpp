// Reading Triangle .poly files: valid variants, every malformed case, the shared geometries.
#include "test_files.hpp"

#include <pdd/errors.hpp>
#include <pdd/io/poly.hpp>

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <fstream>
#include <iterator>
#include <map>
#include <random>
#include <regex>
#include <sstream>
#include <string>

namespace poly_read_test {
namespace {

pdd::pslg parse(const std::string& text, const std::filesystem::path& node_dir = {}) {
  std::istringstream in(text);
  return pdd::parse_poly(in, "file.poly", node_dir);
}

/// Expects parse(text) to throw pdd::input_error at `line` whose message holds `word`.
void expect_error(const std::string& text, std::size_t line, const std::string& word,
                  const std::filesystem::path& node_dir = {}) {
  SCOPED_TRACE("input:\n" + text);
  try {
    (void)parse(text, node_dir);
    ADD_FAILURE() << "no exception; expected an error at line " << line << " about '" << word
                  << "'";
  } catch (const pdd::input_error& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("file.poly:" + std::to_string(line) + ":"), std::string::npos) << msg;
    EXPECT_EQ(e.line(), line) << msg;
    EXPECT_EQ(e.file(), "file.poly");
    EXPECT_NE(msg.find(word), std::string::npos) << "'" << word << "' not in: " << msg;
  } catch (const std::exception& e) {
    ADD_FAILURE() << "wrong exception type: " << e.what();
  }
}

const std::string square_rest = "4 1\n1 1 2 5\n2 2 3 5\n3 3 4 5\n4 4 1 5\n0\n";
const std::string square_vertices = "4 2 0 1\n1 0 0 1\n2 1 0 1\n3 1 1 1\n4 0 1 1\n";

} // namespace

TEST(PolyRead, OneBasedSquare) {
  const auto g = parse(square_vertices + square_rest);
  ASSERT_EQ(g.vertices.size(), 4u);
  EXPECT_EQ(g.vertices[2], (pdd::point{1, 1}));
  EXPECT_EQ(g.vertex_markers, (std::vector<int>{1, 1, 1, 1}));
  ASSERT_EQ(g.segments.size(), 4u);
  EXPECT_EQ(g.segments[0].a, 0u);
  EXPECT_EQ(g.segments[0].b, 1u);
  EXPECT_EQ(g.segments[3].a, 3u);
  EXPECT_EQ(g.segments[3].b, 0u);
  EXPECT_EQ(g.segments[1].marker, 5);
  EXPECT_TRUE(g.holes.empty());
  EXPECT_TRUE(g.regions.empty());
}

TEST(PolyRead, ZeroBasedSquare) {
  const auto g = parse("4 2 0 0\n0 0 0\n1 1 0\n2 1 1\n3 0 1\n"
                       "4 0\n0 0 1\n1 1 2\n2 2 3\n3 3 0\n1\n0 0.5 0.5\n");
  ASSERT_EQ(g.vertices.size(), 4u);
  EXPECT_EQ(g.vertex_markers, (std::vector<int>{0, 0, 0, 0}));
  ASSERT_EQ(g.segments.size(), 4u);
  EXPECT_EQ(g.segments[3].a, 3u);
  EXPECT_EQ(g.segments[3].b, 0u);
  EXPECT_EQ(g.segments[3].marker, 0);
  ASSERT_EQ(g.holes.size(), 1u);
  EXPECT_EQ(g.holes[0], (pdd::point{0.5, 0.5}));
  // Vertex id 4 is out of range for a 0-based file with 4 vertices.
  expect_error("4 2 0 0\n0 0 0\n1 1 0\n2 1 1\n3 0 1\n1 0\n0 3 4\n0\n", 7, "out of range");
  // Vertex id 0 is out of range for a 1-based file.
  expect_error(square_vertices + "1 0\n1 0 1\n0\n", 7, "out of range");
}

TEST(PolyRead, CommentsBlankLinesTabsAndCrlfEverywhere) {
  const std::string text = "# leading comment\n\n   \t\n"
                           "4 2 1 1 # header with a comment\r\n"
                           "# between records\n"
                           "1\t0 0 7.5 1#no space before the comment\n"
                           "\n"
                           "2 1 0 -3e2 1   \n"
                           "  3   1  1 +4 2 # three\n"
                           "4 0 1 0 1\n"
                           "#\n"
                           "4 1 # segments\n1 1 2 5\n\n2 2 3 5\n3 3 4 5 # x\n4 4 1 5\n"
                           "# holes\n 1 \n1 0.25 0.75 # hole\n"
                           "# regions\n\n2\n1 0.5 0.5 3 0.01\n2 0.6 0.6 4 # no area\n"
                           "# trailing comment\n\n";
  const auto g = parse(text);
  ASSERT_EQ(g.vertices.size(), 4u);
  EXPECT_EQ(g.vertex_markers, (std::vector<int>{1, 1, 2, 1})); // attributes dropped
  EXPECT_EQ(g.segments.size(), 4u);
  ASSERT_EQ(g.holes.size(), 1u);
  EXPECT_EQ(g.holes[0], (pdd::point{0.25, 0.75}));
  ASSERT_EQ(g.regions.size(), 2u);
  EXPECT_EQ(g.regions[0].p, (pdd::point{0.5, 0.5}));
  EXPECT_EQ(g.regions[0].attribute, 3.0);
  EXPECT_EQ(g.regions[0].max_area, 0.01);
  EXPECT_EQ(g.regions[1].attribute, 4.0);
  EXPECT_EQ(g.regions[1].max_area, 4.0); // omitted area: the attribute, as Triangle reads it
}

TEST(PolyRead, NumberForms) {
  const auto g = parse("3 2 0 0\n1 1e2 -2.5E-3\n2 +0.5 .25\n3 -0 5.\n0 0\n0\n");
  EXPECT_EQ(g.vertices[0], (pdd::point{100.0, -0.0025}));
  EXPECT_EQ(g.vertices[1], (pdd::point{0.5, 0.25}));
  EXPECT_TRUE(std::signbit(g.vertices[2].x));
  EXPECT_EQ(g.vertices[2].y, 5.0);
}

TEST(PolyRead, RegionsSectionIsOptionalAndMayBeEmpty) {
  EXPECT_TRUE(parse(square_vertices + square_rest).regions.empty());
  EXPECT_TRUE(parse(square_vertices + square_rest + "0\n").regions.empty());
  const auto g = parse(square_vertices + square_rest + "1\n1 0.5 0.5 -2 1e-3\n");
  ASSERT_EQ(g.regions.size(), 1u);
  EXPECT_EQ(g.regions[0].attribute, -2.0);
  EXPECT_EQ(g.regions[0].max_area, 1e-3);
}

TEST(PolyRead, MalformedHeaders) {
  expect_error("", 1, "vertex header");
  expect_error("# only a comment\n", 2, "ended");
  expect_error("4 2 0\n", 1, "fields");
  expect_error("4 2 0 1 7\n", 1, "fields");
  expect_error("4 two 0 1\n", 1, "integer");
  expect_error("4 3 0 1\n", 1, "dimension 2");
  expect_error("4 2 0 2\n", 1, "0 or 1");
  expect_error("-4 2 0 1\n", 1, "non-negative");
  expect_error("3000000000 2 0 1\n", 1, "2^31");
  expect_error("99999999999999999999999 2 0 1\n", 1, "out of range");
  expect_error("# c\n1000 2 0 0\n1 0 0\n2 0 0\n", 2, "cannot fit");
  expect_error("4 2 -1 1\n", 1, "non-negative");
  expect_error("4 2 100000 1\n1 0 0\n", 1, "cannot fit");
  expect_error("4.0 2 0 1\n", 1, "integer");
}

TEST(PolyRead, MalformedVertices) {
  expect_error("2 2 0 0\n1 1.5abc 0\n2 0 0\n0 0\n0\n", 2, "number");
  expect_error("2 2 0 0\n1 nan 0\n2 0 0\n0 0\n0\n", 2, "finite");
  expect_error("2 2 0 0\n1 0 -inf\n2 0 0\n0 0\n0\n", 2, "finite");
  expect_error("2 2 0 0\n1 0 1e999\n2 0 0\n0 0\n0\n", 2, "range");
  expect_error("2 2 0 0\n1 0 x\n2 0 0\n0 0\n0\n", 2, "number");
  expect_error("2 2 0 0\n1 0 1,5\n2 0 0\n0 0\n0\n", 2, "number");
  expect_error("2 2 0 0\n1 0 0\n3 0 0\n0 0\n0\n", 3, "consecutive");
  expect_error("2 2 0 0\n2 0 0\n3 0 0\n0 0\n0\n", 2, "0 or 1");
  expect_error("2 2 0 0\n-1 0 0\n0 0 0\n0 0\n0\n", 2, "0 or 1");
  expect_error("2 2 0 1\n1 0 0\n2 0 0 1\n0 0\n0\n", 2, "fields");    // missing marker
  expect_error("2 2 0 0\n1 0 0 1\n2 0 0\n0 0\n0\n", 2, "fields");    // extra field
  expect_error("2 2 1 0\n1 0 0 zz\n2 0 0 1\n0 0\n0\n", 2, "number"); // bad attribute
  expect_error("2 2 0 1\n1 0 0 1.5\n2 0 0 1\n0 0\n0\n", 2, "integer");
  expect_error("2 2 0 1\n1 0 0 3000000000\n2 0 0 1\n0 0\n0\n", 2, "range of int");
  expect_error("2 2 0 0\n1.0 0 0\n2 0 0\n0 0\n0\n", 2, "integer");
  // Truncated inside the vertex section: the line after the last one.
  expect_error("3 2 0 0\n1 0 0\n2 1 0\n", 4, "vertex 3 of 3");
  expect_error("3 2 0 0\n1 0 0\n2 1 0", 4, "ended"); // no final newline: still 3 lines
}

TEST(PolyRead, MalformedSegments) {
  const std::string v = "3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n"; // lines 1-4
  expect_error(v, 5, "segment header");
  expect_error(v + "# comment\n", 6, "segment header");
  expect_error(v + "3\n", 5, "fields");
  expect_error(v + "3 2\n", 5, "0 or 1");
  expect_error(v + "-1 0\n", 5, "non-negative");
  expect_error(v + "3000000000 0\n", 5, "2^31");
  expect_error(v + "500 0\n1 1 2\n0\n", 5, "cannot fit");
  expect_error(v + "2 0\n1 1 2\n2 2 4\n0\n", 7, "out of range");
  expect_error(v + "2 0\n1 1 2\n2 2 -3\n0\n", 7, "negative");
  expect_error(v + "2 0\n1 1 2\n2 2 3 1\n0\n", 7, "fields");
  expect_error(v + "2 1\n1 1 2 1\n2 2 3\n0\n", 7, "fields");
  expect_error(v + "2 1\n1 1 2 1\n2 2 3 x\n0\n", 7, "integer");
  expect_error(v + "2 0\n1 1 2\n2 2 3.0\n0\n", 7, "integer");
  expect_error(v + "2 0\n1 1 2\n-2 2 3\n0\n", 7, "non-negative segment id");
  expect_error(v + "2 0\n1 1 2\n", 7, "segment 2 of 2");
}

TEST(PolyRead, MalformedHolesAndRegions) {
  const std::string s = square_vertices + "4 1\n1 1 2 5\n2 2 3 5\n3 3 4 5\n4 4 1 5\n"; // 1-10
  expect_error(s, 11, "hole header");
  expect_error(s + "1 2\n", 11, "fields");
  expect_error(s + "-1\n", 11, "non-negative");
  expect_error(s + "100\n", 11, "cannot fit");
  expect_error(s + "1\n#\n", 13, "hole 1 of 1");
  expect_error(s + "1\n1 0.5\n", 12, "fields");
  expect_error(s + "1\n1 0.5 0.5z\n", 12, "number");
  expect_error(s + "1\n1 0.5 nan\n", 12, "finite");
  expect_error(s + "1\n-1 0.5 0.5\n", 12, "non-negative hole id");
  const std::string h = s + "0\n"; // line 11
  expect_error(h + "2 3\n", 12, "regional attribute header");
  expect_error(h + "1\n#\n", 14, "region 1 of 1");
  expect_error(h + "1\n", 12, "cannot fit");
  expect_error(h + "1\n1 0.5 0.5\n", 13, "fields");
  expect_error(h + "1\n1 0.5 0.5 1 2 3\n", 13, "fields");
  expect_error(h + "1\n1 0.5 0.5 1 inf\n", 13, "finite");
  expect_error(h + "1\n1 0.5 0.5 1 0.1\n7\n", 14, "end of the file");
  expect_error(h + "1\n1 0.5 0.5 1 0.1\n\n# fine\n1 2 3\n", 16, "end of the file");
  expect_error(h + "-1\n", 12, "non-negative");
}

TEST(PolyRead, NodeSibling) {
  const auto dir = pdd::test::fresh_dir("node");
  pdd::test::write_text(dir / "sq.node", "# vertices\n4 2 1 1\n0 0 0 9 3\n1 2 0 9 3\n"
                                         "2 2 2 9 3\n3 0 2 9 3\n# the rest is ignored\n2 0\n");
  pdd::test::write_text(dir / "sq.poly", "# refers to sq.node\n0 2 0 1\n"
                                         "4 1\n0 0 1 1\n1 1 2 1\n2 2 3 2\n3 3 0 2\n1\n1 1 1\n");
  const auto g = pdd::read_poly(dir / "sq.poly");
  ASSERT_EQ(g.vertices.size(), 4u);
  EXPECT_EQ(g.vertices[2], (pdd::point{2, 2}));
  EXPECT_EQ(g.vertex_markers, (std::vector<int>{3, 3, 3, 3}));
  ASSERT_EQ(g.segments.size(), 4u); // the .node is 0-based: ids 0..3 are valid
  EXPECT_EQ(g.segments[3].a, 3u);
  EXPECT_EQ(g.segments[3].b, 0u);
  EXPECT_EQ(g.segments[2].marker, 2);
  EXPECT_EQ(g.holes.size(), 1u);

  // parse_poly looks the .node up in dir_for_node_file, by the stem of the message name.
  std::istringstream in(pdd::test::read_text(dir / "sq.poly"));
  const auto g2 = pdd::parse_poly(in, "sq.poly", dir);
  EXPECT_EQ(g2.vertices, g.vertices);

  // Missing sibling: the error points at the header line of the .poly.
  expect_error("# no node\n\n0 2 0 1\n0 0\n0\n", 3, "cannot be found", dir);
  // Ids in the .poly are checked against the .node's range.
  std::istringstream bad("0 2 0 1\n1 0\n1 1 4\n0\n");
  try {
    (void)pdd::parse_poly(bad, "sq.poly", dir);
    ADD_FAILURE() << "no exception";
  } catch (const pdd::input_error& e) {
    EXPECT_NE(std::string(e.what()).find("sq.poly:3:"), std::string::npos) << e.what();
  }
  // Errors inside the .node name the .node file and its line.
  pdd::test::write_text(dir / "broken.node", "2 2 0 0\n1 0 0\n2 0 oops\n");
  pdd::test::write_text(dir / "broken.poly", "0 2 0 0\n0 0\n0\n");
  try {
    (void)pdd::read_poly(dir / "broken.poly");
    ADD_FAILURE() << "no exception";
  } catch (const pdd::input_error& e) {
    EXPECT_EQ(e.line(), 3u);
    EXPECT_NE(std::string(e.what()).find("broken.node:3:"), std::string::npos) << e.what();
  }
  pdd::test::write_text(dir / "empty.node", "0 2 0 0\n");
  pdd::test::write_text(dir / "empty.poly", "0 2 0 0\n0 0\n0\n");
  EXPECT_THROW((void)pdd::read_poly(dir / "empty.poly"), pdd::input_error);
}

TEST(PolyRead, ReadPolyMessagesNameThePathAndMissingFileThrows) {
  const auto dir = pdd::test::fresh_dir("named");
  pdd::test::write_text(dir / "file.poly", "3 2 0 0\n1 0 0\n2 1 0\n3 0 q\n");
  try {
    (void)pdd::read_poly(dir / "file.poly");
    ADD_FAILURE() << "no exception";
  } catch (const pdd::input_error& e) {
    EXPECT_EQ(e.file(), (dir / "file.poly").string());
    EXPECT_NE(std::string(e.what()).find("file.poly:4:"), std::string::npos) << e.what();
  }
  EXPECT_THROW((void)pdd::read_poly(dir / "absent.poly"), pdd::error);
}

TEST(PolyRead, GarbageNeverCrashes) {
  // Random byte soup built from .poly-like tokens: every outcome is a result or input_error.
  std::mt19937 rng(12345);
  const char* pieces[] = {"0",  "1", "2", "3",  "-1", "1e9", "nan", "#",      "\n",
                          "\n", " ", " ", "\t", "x",  "0.5", "4",   "2 0 1\n"};
  int parsed = 0, errors = 0;
  for (int round = 0; round < 3000; ++round) {
    std::string text;
    const int len = static_cast<int>(rng() % 60);
    for (int i = 0; i < len; ++i)
      text += pieces[rng() % std::size(pieces)];
    try {
      (void)parse(text);
      ++parsed;
    } catch (const pdd::input_error&) {
      ++errors;
    }
  }
  // Valid prefixes followed by random bytes (NUL, high bytes, '#', newlines).
  const std::string valid = square_vertices + square_rest;
  for (int round = 0; round < 2000; ++round) {
    std::string text = valid.substr(0, rng() % valid.size());
    for (int i = static_cast<int>(rng() % 12); i > 0; --i)
      text += static_cast<char>(rng() % 256);
    try {
      (void)parse(text);
      ++parsed;
    } catch (const pdd::input_error&) {
      ++errors;
    }
  }
  EXPECT_GT(errors, 0);
  EXPECT_EQ(parsed + errors, 5000);
}

TEST(PolyRead, SharedGeometriesMatchTheReadme) {
  const auto dir = pdd::test::shared_data_dir();
  if (dir.empty()) GTEST_SKIP() << "shared/data is absent";
  const std::string readme = pdd::test::read_text(dir / "README.md");
  // Table rows: | `name.poly` | source | licence | V | S | H | ...
  const std::regex row(
      R"(\|\s*`([^`]+\.poly)`\s*\|[^|]*\|[^|]*\|\s*\**(\d+)\**\s*\|\s*\**(\d+)\**\s*\|\s*\**(\d+)\**\s*\|)");
  std::map<std::string, std::array<std::size_t, 3>> expected;
  for (std::sregex_iterator it(readme.begin(), readme.end(), row), end; it != end; ++it)
    expected[(*it)[1]] = {std::stoul((*it)[2]), std::stoul((*it)[3]), std::stoul((*it)[4])};
  const auto files = pdd::test::shared_poly_files();
  ASSERT_FALSE(files.empty());
  for (const auto& f : files) {
    SCOPED_TRACE(f.string());
    const auto it = expected.find(f.filename().string());
    ASSERT_NE(it, expected.end()) << "no README row for " << f.filename();
    const auto g = pdd::read_poly(f);
    EXPECT_EQ(g.vertices.size(), it->second[0]);
    EXPECT_EQ(g.segments.size(), it->second[1]);
    EXPECT_EQ(g.holes.size(), it->second[2]);
    EXPECT_EQ(g.vertex_markers.size(), g.vertices.size());
  }
}

} // namespace poly_read_test
