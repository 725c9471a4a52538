// N-way MADD on generated and shared domains: exact subdomain counts, valid polygons with
// holes, conforming interfaces, separator angles >= Phi0, areas adding up to the domain's,
// determinism across thread counts, and the failure mode.
#include <pdd/geometry/model_domains.hpp>
#include <pdd/io/poly.hpp>
#include <pdd/madd/decompose.hpp>
#include <pdd/madd/validate_decomposition.hpp>

#include <test_support.hpp>

#include <gtest/gtest.h>
#include <tbb/task_arena.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <random>
#include <string>
#include <vector>

namespace madd_decompose_test {
namespace {

using pdd::point;

pdd::pslg square(double s = 1.0) {
  pdd::pslg g;
  g.add_loop(std::vector<point>{{0, 0}, {s, 0}, {s, s}, {0, s}}, 1);
  return g;
}

/// A 4 x 1 rectangle with three square holes.
pdd::pslg rectangle_with_holes() {
  pdd::pslg g;
  g.add_loop(std::vector<point>{{0, 0}, {4, 0}, {4, 1}, {0, 1}}, 1);
  for (int i = 0; i < 3; ++i) {
    const double x = 0.8 + 1.2 * i;
    g.add_loop(std::vector<point>{{x, 0.3}, {x, 0.7}, {x + 0.4, 0.7}, {x + 0.4, 0.3}}, 2 + i);
    g.holes.push_back({x + 0.2, 0.5});
  }
  return g;
}

/// A random star-shaped polygon (n vertices at sorted random angles and radii in [0.55, 1])
/// with up to `holes` random polygonal holes in its inner disc of radius 0.5, not overlapping.
pdd::pslg random_polygon(std::uint32_t seed, int holes) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<double> ang(5 + static_cast<std::size_t>(u(rng) * 40));
  for (auto& a : ang)
    a = u(rng) * 2.0 * std::numbers::pi;
  std::sort(ang.begin(), ang.end());
  // No angular gap over 40 degrees: every outer edge stays outside the disc of radius 0.5
  // (0.55 cos 20 > 0.5) where the holes are.
  for (std::size_t i = 0; i < ang.size(); ++i) {
    const double next = i + 1 < ang.size() ? ang[i + 1] : ang[0] + 2.0 * std::numbers::pi;
    if (next - ang[i] > 40.0 * std::numbers::pi / 180.0) {
      ang.insert(ang.begin() + static_cast<long>(i) + 1,
                 std::fmod(ang[i] + 35.0 * std::numbers::pi / 180.0, 2.0 * std::numbers::pi));
      std::sort(ang.begin(), ang.end());
      i = static_cast<std::size_t>(-1);
    }
  }
  const int n = static_cast<int>(ang.size());
  std::vector<point> outer;
  for (int i = 0; i < n; ++i) {
    if (i > 0 && ang[i] - ang[i - 1] < 1e-3) continue;
    const double r = 0.55 + 0.45 * u(rng);
    outer.push_back({r * std::cos(ang[i]), r * std::sin(ang[i])});
  }
  pdd::pslg g;
  g.add_loop(outer, 1);
  std::vector<std::pair<point, double>> placed;
  for (int h = 0, tries = 0; h < holes && tries < 100; ++tries) {
    const double rad = 0.04 + 0.08 * u(rng);
    const double cr = (0.5 - rad) * std::sqrt(u(rng)), ca = u(rng) * 2.0 * std::numbers::pi;
    const point c{cr * std::cos(ca), cr * std::sin(ca)};
    bool ok = true;
    for (const auto& [q, qr] : placed)
      ok = ok && std::hypot(q.x - c.x, q.y - c.y) > rad + qr + 0.02;
    if (!ok) continue;
    placed.emplace_back(c, rad);
    const int m = 3 + static_cast<int>(u(rng) * 8);
    auto pts = pdd::detail::circle_points(c, rad, static_cast<std::size_t>(m), u(rng));
    std::reverse(pts.begin(), pts.end());
    g.add_loop(pts, 2 + h);
    g.holes.push_back(c);
    ++h;
  }
  return g;
}

void expect_valid(const pdd::decomposition& d, const pdd::pslg& g, std::size_t n,
                  double phi0 = 60.0, const std::string& what = "") {
  EXPECT_EQ(d.subdomains.size(), n) << what;
  const auto rep = pdd::validate_decomposition(d, g, {.min_angle_deg = phi0});
  EXPECT_TRUE(rep.ok()) << what << "\n" << rep.summary();
  EXPECT_GE(rep.min_separator_angle_deg, phi0 - 1e-9) << what;
}

bool bitwise_equal(double a, double b) {
  return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b);
}

/// Bitwise equality of two decompositions (coordinates, ids, tags, interfaces, areas).
bool identical(const pdd::decomposition& x, const pdd::decomposition& y) {
  if (x.vertices.size() != y.vertices.size() || x.vertex_markers != y.vertex_markers ||
      x.subdomains.size() != y.subdomains.size() || x.interfaces.size() != y.interfaces.size())
    return false;
  for (std::size_t i = 0; i < x.vertices.size(); ++i)
    if (!bitwise_equal(x.vertices[i].x, y.vertices[i].x) ||
        !bitwise_equal(x.vertices[i].y, y.vertices[i].y))
      return false;
  for (std::size_t s = 0; s < x.subdomains.size(); ++s) {
    const auto& a = x.subdomains[s];
    const auto& b = y.subdomains[s];
    if (a.loops != b.loops || !bitwise_equal(a.area, b.area) || a.tags.size() != b.tags.size())
      return false;
    for (std::size_t l = 0; l < a.tags.size(); ++l)
      for (std::size_t i = 0; i < a.tags[l].size(); ++i) {
        const auto& p = a.tags[l][i];
        const auto& q = b.tags[l][i];
        if (p.type != q.type || p.id != q.id || p.marker != q.marker || p.neighbour != q.neighbour)
          return false;
      }
  }
  for (std::size_t c = 0; c < x.interfaces.size(); ++c)
    if (x.interfaces[c].a != y.interfaces[c].a || x.interfaces[c].b != y.interfaces[c].b ||
        x.interfaces[c].vertices != y.interfaces[c].vertices)
      return false;
  return true;
}

TEST(MaddDecompose, SquareAllCounts) {
  const auto g = square();
  for (const std::size_t n : {2u, 7u, 64u, 256u})
    for (const int alg : {1, 2}) {
      pdd::decomposition_statistics st;
      const auto d =
          pdd::decompose(g, {.subdomains = n, .algorithm = alg}, pdd::default_partitioner{}, &st);
      expect_valid(d, g, n, 60.0, "square n=" + std::to_string(n) + " alg " + std::to_string(alg));
      EXPECT_EQ(st.subdomains, n);
      EXPECT_EQ(st.splits, n - 1);
      EXPECT_LT(st.max_area_over_mean, 2.5);
    }
}

TEST(MaddDecompose, RectangleWithHoles) {
  const auto g = rectangle_with_holes();
  for (const std::size_t n : {2u, 7u, 64u, 256u})
    for (const int alg : {1, 2}) {
      const auto d = pdd::decompose(g, {.subdomains = n, .algorithm = alg});
      expect_valid(d, g, n, 60.0,
                   "rectangle n=" + std::to_string(n) + " alg " + std::to_string(alg));
    }
}

TEST(MaddDecompose, PipeCrossSection) {
  const auto g = pdd::pipe_domain(512, 32);
  for (const std::size_t n : {2u, 7u, 64u, 256u})
    for (const int alg : {1, 2}) {
      pdd::decomposition_statistics st;
      const auto d =
          pdd::decompose(g, {.subdomains = n, .algorithm = alg}, pdd::default_partitioner{}, &st);
      expect_valid(d, g, n, 60.0, "pipe n=" + std::to_string(n) + " alg " + std::to_string(alg));
      EXPECT_GT(st.separator_length_total, 0.0);
    }
}

// Issue 36 item 4: separator smoothing (4.2) used to trade balance for length up to L_b = 0.75
// of a split, and pdd-decompose (smoothing on by default) gave largest/mean area 1.59 on Lake
// Superior at N = 64 (1.69 on a 3-element airfoil); bounded by the partitioner's fraction it
// keeps MADD's balance: 1.41.
TEST(MaddDecompose, SmoothingKeepsThePartitionersBalance) {
  const auto dir = pdd::test::shared_data_dir();
  if (dir.empty()) GTEST_SKIP() << "../shared/data is absent";
  const pdd::pslg g = pdd::read_poly((dir / "lake_superior.poly").string());
  for (const std::size_t n : {16u, 64u, 256u}) {
    pdd::decomposition_statistics st;
    const auto d = pdd::decompose(g, {.subdomains = n, .smoothing = true, .threads = 1}, {}, &st);
    expect_valid(d, g, n, 60.0, "lake smoothing N=" + std::to_string(n));
    EXPECT_LE(st.max_area_over_mean, 1.5) << n;
    EXPECT_LE(st.max_split_fraction, 0.75) << n;
  }
}

// Into N, every subdomain has a quota (madd/detail/quotas.hpp): N just below a power of two,
// where halving the largest first leaves one subdomain of twice the others' area (1.75 at
// N = 7 with perfect splits; 1.52-1.73 measured before quotas), is balanced too.
TEST(MaddDecompose, QuotasBalanceCountsThatAreNotPowersOfTwo) {
  const auto key = pdd::key_domain();
  const auto pipe = pdd::pipe_domain(512, 32);
  for (const std::size_t n : {3u, 5u, 7u, 11u, 13u, 23u, 47u, 95u}) {
    for (const auto* g : {&key, &pipe}) {
      pdd::decomposition_statistics st;
      const auto d = pdd::decompose(*g, {.subdomains = n, .threads = 2}, {}, &st);
      expect_valid(d, *g, n, 60.0, "quotas N=" + std::to_string(n));
      EXPECT_LE(st.max_area_over_mean, 1.5) << n;
      if (n <= 13) {
        EXPECT_LE(st.max_area_over_mean, 1.3) << n;
      }
    }
  }
  const auto one = pdd::decompose(pipe, {.subdomains = 95, .threads = 1});
  EXPECT_TRUE(identical(one, pdd::decompose(pipe, {.subdomains = 95, .threads = 2})));
  const auto dir = pdd::test::shared_data_dir();
  if (dir.empty()) GTEST_SKIP() << "../shared/data is absent";
  const pdd::pslg lake = pdd::read_poly((dir / "lake_superior.poly").string());
  int above = 0;
  for (std::size_t n = 2; n < 40; ++n) {
    pdd::decomposition_statistics st;
    const auto d = pdd::decompose(lake, {.subdomains = n, .threads = 2}, {}, &st);
    expect_valid(d, lake, n, 60.0, "lake N=" + std::to_string(n));
    EXPECT_LE(st.max_area_over_mean, 1.6) << n;
    if (n == 7) {
      EXPECT_LE(st.max_area_over_mean, 1.25);
    }
    above += st.max_area_over_mean > 1.5;
  }
  EXPECT_LE(above, 2); // 1 measured (N = 25, 1.54)
}

TEST(MaddDecompose, OtherAnglesAndOptions) {
  const auto g = pdd::key_domain();
  for (const double phi0 : {30.0, 45.0, 70.0}) {
    const auto d = pdd::decompose(g, {.subdomains = 24, .min_separator_angle_deg = phi0});
    expect_valid(d, g, 24, phi0, "key phi0=" + std::to_string(phi0));
  }
  for (const bool smoothing : {false, true}) {
    const auto d = pdd::decompose(g, {.subdomains = 24, .smoothing = smoothing});
    expect_valid(d, g, 24, 60.0, "key smoothing");
  }
  const auto d =
      pdd::decompose(g, {.subdomains = 24, .refinement_scale = pdd::madd_refinement_scale::global});
  expect_valid(d, g, 24, 60.0, "key global refinement");
}

TEST(MaddDecompose, RandomPolygonsWithHoles) {
  const std::size_t counts[] = {2, 3, 5, 8, 13, 21};
  int cases = 0;
  for (std::uint32_t seed = 0; seed < 210; ++seed) {
    const auto g = random_polygon(seed, static_cast<int>(seed % 4));
    const std::size_t n = counts[seed % 6];
    const int alg = 1 + static_cast<int>(seed / 6 % 2);
    const bool smoothing = seed / 12 % 2 == 0;
    const std::string what =
        "seed " + std::to_string(seed) + " n=" + std::to_string(n) + " alg " + std::to_string(alg);
    try {
      const auto d = pdd::decompose(g, {.subdomains = n, .algorithm = alg, .smoothing = smoothing});
      expect_valid(d, g, n, 60.0, what);
      ++cases;
    } catch (const pdd::error& e) {
      ADD_FAILURE() << what << ": " << e.what();
    }
  }
  EXPECT_EQ(cases, 210);
}

TEST(MaddDecompose, MaxSubdomainArea) {
  const auto g = pdd::pipe_domain(256, 32);
  const double area = pdd::domain_area(g);
  const auto d = pdd::decompose(g, {.max_subdomain_area = area / 40.0});
  EXPECT_GE(d.subdomains.size(), 40u);
  for (const auto& s : d.subdomains)
    EXPECT_LE(s.area, area / 40.0);
  expect_valid(d, g, d.subdomains.size());
}

TEST(MaddDecompose, IdenticalForEveryThreadCount) {
  const auto g = pdd::pipe_domain(512, 32);
  for (const int alg : {1, 2}) {
    const pdd::madd_options o{.subdomains = 100, .algorithm = alg, .threads = 1};
    const auto one = pdd::decompose(g, o);
    pdd::madd_options o2 = o;
    o2.threads = 2;
    const auto two = pdd::decompose(g, o2);
    EXPECT_TRUE(identical(one, two));
    tbb::task_arena arena(2);
    pdd::decomposition three;
    pdd::madd_options o0 = o;
    o0.threads = 0;
    arena.execute([&] { three = pdd::decompose(g, o0); });
    EXPECT_TRUE(identical(one, three));
    tbb::task_arena single(1);
    pdd::decomposition four;
    single.execute([&] { four = pdd::decompose(g, o0); });
    EXPECT_TRUE(identical(one, four));
  }
}

TEST(MaddDecompose, ComponentsAndErrors) {
  // Two separate squares: two components, so N = 1 is impossible and N = 2 needs no split.
  pdd::pslg g = square();
  g.add_loop(std::vector<point>{{2, 0}, {3, 0}, {3, 1}, {2, 1}}, 3);
  EXPECT_THROW(pdd::decompose(g, {.subdomains = 1}), pdd::decomposition_error);
  const auto d2 = pdd::decompose(g, {.subdomains = 2});
  expect_valid(d2, g, 2);
  const auto d5 = pdd::decompose(g, {.subdomains = 5});
  expect_valid(d5, g, 5);
  // Bad options.
  EXPECT_THROW(pdd::decompose(square(), {.min_separator_angle_deg = 95}), pdd::decomposition_error);
  EXPECT_THROW(pdd::decompose(square(), {.algorithm = 3}), pdd::decomposition_error);
  EXPECT_THROW(pdd::decompose(square(), {.max_refinement_levels = 0}), pdd::decomposition_error);
}

TEST(MaddDecompose, UnsplittableGivesError) {
  // No refinement at all and one level: the square's two right triangles are no junction
  // triangles and its diagonal forms 45 degree angles, so there is no separator.
  try {
    pdd::decompose(square(), {.subdomains = 2,
                              .refinement_factor = 1e-6,
                              .max_refinement_levels = 1,
                              .max_encroachment_depth = 0});
    ADD_FAILURE() << "expected decomposition_error";
  } catch (const pdd::decomposition_error& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("subdomain 0"), std::string::npos) << msg;
    EXPECT_NE(msg.find("no acceptable separator"), std::string::npos) << msg;
  }
  // With dynamic refinement the same square splits.
  const auto d = pdd::decompose(square(), {.subdomains = 2, .refinement_factor = 0.1});
  expect_valid(d, square(), 2);
}

TEST(MaddDecompose, SliverRegionIsRefusedNotExhaustingMemory) {
  // A triangle of area ~1e-17 with sides of length ~1 (a fuzz input): the boundary spacing
  // 4 A / (P r) is ~1e-18, so Z would need 2^30 points per edge; the split is refused, naming
  // the subdomain and why (before: std::bad_alloc)
  pdd::pslg g;
  g.add_loop(std::vector<point>{{0, 0}, {1, 1}, {0.7071067811865476, 0.7071067811865475}}, 1);
  try {
    pdd::decompose(g, {.subdomains = 2});
    ADD_FAILURE() << "expected decomposition_error";
  } catch (const pdd::decomposition_error& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("subdomain 0"), std::string::npos) << msg;
    EXPECT_NE(msg.find("points at spacing"), std::string::npos) << msg;
  }
}

TEST(MaddDecompose, SharedDataFiles) {
  const auto files = pdd::test::shared_poly_files();
  if (files.empty()) GTEST_SKIP() << "no shared data";
  int used = 0;
  for (const auto& f : files) {
    const pdd::pslg g = pdd::read_poly(f);
    try {
      (void)pdd::find_loops(g);
    } catch (const pdd::geometry_error&) {
      continue; // not made of closed loops (dangling segments on purpose)
    }
    ++used;
    for (const std::size_t n : {2u, 64u}) {
      const auto d = pdd::decompose(g, {.subdomains = n});
      expect_valid(d, g, n, 60.0, f.filename().string() + " n=" + std::to_string(n));
    }
  }
  EXPECT_GT(used, 0);
}

} // namespace

namespace {

TEST(MaddDecompose, PipeThousandWaysOnOneCore) {
  // Performance goal: N = 1024 on the pipe cross-section in under a second on one core
  // (Release). The bound asserted here is loose so that busy or instrumented builds pass;
  // the measured time is recorded.
  const auto g = pdd::pipe_domain();
  pdd::decomposition_statistics st;
  const auto d =
      pdd::decompose(g, {.subdomains = 1024, .threads = 1}, pdd::default_partitioner{}, &st);
  expect_valid(d, g, 1024);
  RecordProperty("time_s", std::to_string(st.time_s));
  std::printf("pipe N=1024, one thread: %.3f s, %zu boundary points, max/mean area %.3f\n",
              st.time_s, st.boundary_points, st.max_area_over_mean);
  EXPECT_LT(st.time_s, 20.0);
  EXPECT_LT(st.max_area_over_mean, 2.5);
  EXPECT_GE(st.min_separator_angle_deg, 60.0 - 1e-9);
}

} // namespace

} // namespace madd_decompose_test
