// write_poly round trips and the atomic file writer.
#include "test_files.hpp"

#include <pdd/errors.hpp>
#include <pdd/io/atomic_file.hpp>
#include <pdd/io/poly.hpp>

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace poly_write_test {
namespace {

std::uint64_t bits(double d) {
  return std::bit_cast<std::uint64_t>(d);
}

/// Field-by-field, bit-for-bit equality of two PSLGs.
void expect_bitwise_equal(const pdd::pslg& a, const pdd::pslg& b) {
  ASSERT_EQ(a.vertices.size(), b.vertices.size());
  for (std::size_t i = 0; i < a.vertices.size(); ++i) {
    EXPECT_EQ(bits(a.vertices[i].x), bits(b.vertices[i].x)) << "vertex " << i;
    EXPECT_EQ(bits(a.vertices[i].y), bits(b.vertices[i].y)) << "vertex " << i;
  }
  EXPECT_EQ(a.vertex_markers, b.vertex_markers);
  ASSERT_EQ(a.segments.size(), b.segments.size());
  for (std::size_t i = 0; i < a.segments.size(); ++i) {
    EXPECT_EQ(a.segments[i].a, b.segments[i].a);
    EXPECT_EQ(a.segments[i].b, b.segments[i].b);
    EXPECT_EQ(a.segments[i].marker, b.segments[i].marker);
  }
  ASSERT_EQ(a.holes.size(), b.holes.size());
  for (std::size_t i = 0; i < a.holes.size(); ++i) {
    EXPECT_EQ(bits(a.holes[i].x), bits(b.holes[i].x));
    EXPECT_EQ(bits(a.holes[i].y), bits(b.holes[i].y));
  }
  ASSERT_EQ(a.regions.size(), b.regions.size());
  for (std::size_t i = 0; i < a.regions.size(); ++i) {
    EXPECT_EQ(bits(a.regions[i].p.x), bits(b.regions[i].p.x));
    EXPECT_EQ(bits(a.regions[i].p.y), bits(b.regions[i].p.y));
    EXPECT_EQ(bits(a.regions[i].attribute), bits(b.regions[i].attribute));
    EXPECT_EQ(bits(a.regions[i].max_area), bits(b.regions[i].max_area));
  }
}

/// A finite double drawn from awkward places: specials, subnormals, random bit patterns.
double awkward(std::mt19937_64& rng) {
  static const double specials[] = {0.0,
                                    -0.0,
                                    0.1,
                                    1.0 / 3.0,
                                    -2.0 / 3.0,
                                    1e-300,
                                    -1e300,
                                    5e-324,
                                    std::numeric_limits<double>::min(),
                                    std::numeric_limits<double>::max(),
                                    std::numeric_limits<double>::lowest(),
                                    std::numeric_limits<double>::epsilon(),
                                    123456789.123456789,
                                    0.30000000000000004,
                                    9007199254740993.0};
  switch (rng() % 4) {
  case 0:
    return specials[rng() % std::size(specials)];
  case 1:
    return std::uniform_real_distribution<double>(-1e3, 1e3)(rng);
  default:
    for (;;) {
      const double d = std::bit_cast<double>(rng());
      if (std::isfinite(d)) return d;
    }
  }
}

pdd::pslg random_pslg(std::mt19937_64& rng) {
  pdd::pslg g;
  const std::size_t n = 1 + rng() % 40;
  for (std::size_t i = 0; i < n; ++i)
    g.add_vertex({awkward(rng), awkward(rng)}, static_cast<int>(rng() % 7) - 3);
  const std::size_t m = rng() % 50;
  for (std::size_t i = 0; i < m; ++i)
    g.add_segment(static_cast<pdd::index_t>(rng() % n), static_cast<pdd::index_t>(rng() % n),
                  static_cast<int>(rng() % 2000) - 1000);
  for (std::size_t i = rng() % 4; i > 0; --i)
    g.holes.push_back({awkward(rng), awkward(rng)});
  for (std::size_t i = rng() % 4; i > 0; --i)
    g.regions.push_back(
        {{awkward(rng), awkward(rng)}, awkward(rng), rng() % 2 ? -1.0 : awkward(rng)});
  return g;
}

} // namespace

TEST(PolyWrite, RoundTripAwkwardDoubles) {
  pdd::pslg g;
  g.add_loop(std::vector<pdd::point>{{1e-300, -0.0}, {0.1, 1.0 / 3.0}, {-0.0, 5e-324}}, 2);
  g.add_vertex({std::numeric_limits<double>::max(), std::numeric_limits<double>::lowest()}, -7);
  g.holes.push_back({0.1 + 0.2, -1.0 / 3.0});
  g.regions.push_back({{0.5, 0.25}, 1.0 / 3.0, -1.0});
  g.regions.push_back({{-0.0, 1e-300}, -0.0, 2.5e-7});
  const auto p = pdd::test::temp_path("awkward.poly");
  pdd::write_poly(p, g);
  expect_bitwise_equal(pdd::read_poly(p), g);
  // The text itself is the shortest round-trip form.
  const std::string text = pdd::test::read_text(p);
  EXPECT_NE(text.find(" 1e-300 -0 2\n"), std::string::npos) << text;
  EXPECT_NE(text.find(" 0.1 0.3333333333333333 2\n"), std::string::npos) << text;
}

TEST(PolyWrite, RoundTripRandomPslgs) {
  std::mt19937_64 rng(20240601);
  const auto p = pdd::test::temp_path("random.poly");
  for (int round = 0; round < 300; ++round) {
    SCOPED_TRACE("round " + std::to_string(round));
    const pdd::pslg g = random_pslg(rng);
    pdd::write_poly(p, g);
    expect_bitwise_equal(pdd::read_poly(p), g);
    if (HasFailure()) break;
  }
}

TEST(PolyWrite, RoundTripSharedGeometries) {
  const auto files = pdd::test::shared_poly_files();
  if (files.empty()) GTEST_SKIP() << "shared/data is absent";
  const auto p = pdd::test::temp_path("shared.poly");
  for (const auto& f : files) {
    SCOPED_TRACE(f.string());
    const auto g = pdd::read_poly(f);
    pdd::write_poly(p, g);
    expect_bitwise_equal(pdd::read_poly(p), g);
  }
}

TEST(PolyWrite, RefusesWhatCannotRoundTrip) {
  const auto dir = pdd::test::fresh_dir("refuse");
  EXPECT_THROW(pdd::write_poly(dir / "empty.poly", pdd::pslg{}), pdd::error);
  pdd::pslg g;
  g.add_vertex({std::nan(""), 0});
  EXPECT_THROW(pdd::write_poly(dir / "nan.poly", g), pdd::error);
  g.vertices[0] = {0, 0};
  g.add_segment(0, 5);
  EXPECT_THROW(pdd::write_poly(dir / "seg.poly", g), pdd::error);
  g.segments.clear();
  g.holes.push_back({std::numeric_limits<double>::infinity(), 0});
  EXPECT_THROW(pdd::write_poly(dir / "hole.poly", g), pdd::error);
  EXPECT_TRUE(pdd::test::dir_entries(dir).empty());
}

TEST(AtomicFile, WritesAndReplaces) {
  const auto dir = pdd::test::fresh_dir("atomic");
  const auto p = dir / "out.txt";
  pdd::write_file_atomically(p, [](std::ostream& os) { os << "first"; });
  EXPECT_EQ(pdd::test::read_text(p), "first");
  pdd::write_file_atomically(p, [](std::ostream& os) { os << "second"; });
  EXPECT_EQ(pdd::test::read_text(p), "second");
  EXPECT_EQ(pdd::test::dir_entries(dir), std::vector<std::string>{"out.txt"});
}

TEST(AtomicFile, MissingDirectoryThrowsAndLeavesNothing) {
  const auto dir = pdd::test::fresh_dir("nodir");
  const auto p = dir / "does" / "not" / "exist" / "out.poly";
  pdd::pslg g;
  g.add_vertex({0, 0});
  try {
    pdd::write_poly(p, g);
    ADD_FAILURE() << "no exception";
  } catch (const pdd::error& e) {
    EXPECT_NE(std::string(e.what()).find(p.string()), std::string::npos) << e.what();
  }
  EXPECT_FALSE(std::filesystem::exists(dir / "does"));
  EXPECT_TRUE(pdd::test::dir_entries(dir).empty());
}

TEST(AtomicFile, FailedWritesLeaveNoTemporaryAndKeepTheOldFile) {
  const auto dir = pdd::test::fresh_dir("fail");
  const auto p = dir / "keep.txt";
  pdd::test::write_text(p, "old content");
  const std::vector<std::string> only_p{"keep.txt"};

  // The writer throws a pdd::error half-way: rethrown unchanged.
  try {
    pdd::write_file_atomically(p, [](std::ostream& os) {
      os << "half";
      throw pdd::geometry_error("bad geometry");
    });
    ADD_FAILURE() << "no exception";
  } catch (const pdd::geometry_error& e) {
    EXPECT_STREQ(e.what(), "bad geometry");
  }
  EXPECT_EQ(pdd::test::read_text(p), "old content");
  EXPECT_EQ(pdd::test::dir_entries(dir), only_p);

  // Another std::exception becomes a pdd::error naming the path.
  try {
    pdd::write_file_atomically(p, [](std::ostream&) { throw std::runtime_error("boom"); });
    ADD_FAILURE() << "no exception";
  } catch (const pdd::error& e) {
    EXPECT_NE(std::string(e.what()).find("keep.txt"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("boom"), std::string::npos) << e.what();
  }
  EXPECT_EQ(pdd::test::dir_entries(dir), only_p);

  // The stream goes bad (as on a full disk): detected, reported, cleaned up.
  try {
    pdd::write_file_atomically(p, [](std::ostream& os) {
      os << "partial";
      os.setstate(std::ios::badbit);
    });
    ADD_FAILURE() << "no exception";
  } catch (const pdd::error& e) {
    EXPECT_NE(std::string(e.what()).find("write failed"), std::string::npos) << e.what();
  }
  EXPECT_EQ(pdd::test::read_text(p), "old content");
  EXPECT_EQ(pdd::test::dir_entries(dir), only_p);

  // The target is a non-empty directory: the rename fails, the temporary is removed.
  std::filesystem::create_directory(dir / "sub");
  pdd::test::write_text(dir / "sub" / "x", "x");
  EXPECT_THROW(pdd::write_file_atomically(dir / "sub", [](std::ostream& os) { os << "y"; }),
               pdd::error);
  EXPECT_EQ(pdd::test::dir_entries(dir), (std::vector<std::string>{"keep.txt", "sub"}));

  // A path without a file name.
  EXPECT_THROW(pdd::write_file_atomically(dir / "", [](std::ostream&) {}), pdd::error);
}

/// What the FIFO at `fifo` holds after `write` ran with a reader open on it (non-blocking, so
/// that the writer's open does not wait; the content fits in the pipe's buffer).
template <class Write>
std::string through_fifo(const std::filesystem::path& fifo, Write write) {
  const int fd = ::open(fifo.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
  EXPECT_GE(fd, 0);
  EXPECT_NO_THROW(write());
  std::string got(4096, '\0');
  const ::ssize_t n = fd >= 0 ? ::read(fd, got.data(), got.size()) : -1;
  if (fd >= 0) ::close(fd);
  got.resize(n > 0 ? static_cast<std::size_t>(n) : 0);
  return got;
}

// A FIFO (as /dev/null, /dev/stdout or a pipe a user names) is written in place: its reader
// gets the content, and afterwards it is still a FIFO, with no temporary file beside it. A
// rename onto it would have replaced it with a regular file (as it once replaced /dev/null
// for the whole machine when `pdd-mesh --stats /dev/null` ran as root).
TEST(AtomicFile, SpecialFilesAreWrittenInPlace) {
  const auto dir = pdd::test::fresh_dir("fifo");
  const auto fifo = dir / "pipe";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  EXPECT_EQ(through_fifo(fifo,
                         [&] {
                           pdd::write_file_atomically(
                               fifo, [](std::ostream& os) { os << "through the pipe"; });
                         }),
            "through the pipe");
  EXPECT_TRUE(std::filesystem::is_fifo(fifo));
  EXPECT_EQ(pdd::test::dir_entries(dir), std::vector<std::string>{"pipe"});
  // a symbolic link to it: the link is followed, not replaced
  std::filesystem::create_symlink(fifo, dir / "link");
  pdd::pslg g;
  g.add_vertex({0.5, 0.25});
  const std::string poly = through_fifo(fifo, [&] { pdd::write_poly(dir / "link", g); });
  EXPECT_NE(poly.find("0.5 0.25"), std::string::npos) << poly;
  EXPECT_TRUE(std::filesystem::is_symlink(dir / "link"));
  EXPECT_TRUE(std::filesystem::is_fifo(fifo));
}

} // namespace poly_write_test
