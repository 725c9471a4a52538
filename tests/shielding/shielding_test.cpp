// Shielding of small input angles (dissertation 8.1, Algorithms 8.1-8.2, Lemma 23, Theorem 24).
#include "test_support.hpp"
#include "verified.hpp"

#include <pdd/decoupling/decouple.hpp>
#include <pdd/generate.hpp>
#include <pdd/geometry/lfs.hpp>
#include <pdd/geometry/properties.hpp>
#include <pdd/io/poly.hpp>
#include <pdd/madd/decompose.hpp>
#include <pdd/mesh/verify.hpp>
#include <pdd/pipeline.hpp>
#include <pdd/shielding/shield.hpp>
#include <pdd/shielding/shield_statistics.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

namespace shielding_test {
namespace {

constexpr double deg = std::numbers::pi / 180.0;

/// A wedge: apex at the origin, angle theta (degrees) between the x axis and the other side,
/// closed by the segment between the two unit-length sides' ends.
pdd::pslg wedge(double theta) {
  pdd::pslg g;
  g.add_loop(
      std::vector<pdd::point>{{0, 0}, {1, 0}, {std::cos(theta * deg), std::sin(theta * deg)}}, 1);
  return g;
}

/// A trapezoid with base angles of 40 and 50 deg: two small angles sharing the base.
pdd::pslg zigzag() {
  pdd::pslg g;
  const double h = 0.3;
  g.add_loop(
      std::vector<pdd::point>{
          {0, 0}, {1, 0}, {1 - h / std::tan(50 * deg), h}, {h / std::tan(40 * deg), h}},
      1);
  return g;
}

/// A star with 16 spikes (outer radius 1, inner 0.6).
pdd::pslg star() {
  return pdd::test::star_polygon(16, 0.6);
}

double area_of(const pdd::pslg& g) {
  return pdd::domain_area(g);
}

/// Meshes g with N subdomains on `threads` threads and checks Theorem 24's claims.
pdd::triangle_mesh check_mesh(const pdd::pslg& g, double max_area, std::size_t n, unsigned threads,
                              const std::string& what) {
  pdd::generate_options o;
  o.criteria.max_area = max_area;
  o.subdomains = n;
  o.threads = threads;
  o.check_memory = false;
  const std::string at = what + " N=" + std::to_string(n) + " T=" + std::to_string(threads);
  pdd::generate_result r;
  try {
    r = pdd::generate(g, o);
  } catch (const std::exception& e) {
    ADD_FAILURE() << at << ": " << e.what();
    return {};
  }
  EXPECT_EQ(r.statistics.subdomains, n) << at;
  EXPECT_EQ(r.statistics.interface_splits, 0u) << at;
  EXPECT_EQ(r.statistics.shield_splits, 0u) << at;
  EXPECT_EQ(pdd::test::expect_verified(r.mesh, g, o.criteria, at), r.statistics.shielded_triangles)
      << at;
  return std::move(r.mesh);
}

void expect_same(const pdd::triangle_mesh& a, const pdd::triangle_mesh& b, const std::string& at) {
  ASSERT_EQ(a.vertices.size(), b.vertices.size()) << at;
  ASSERT_EQ(a.triangles, b.triangles) << at;
  for (std::size_t v = 0; v < a.vertices.size(); ++v)
    ASSERT_TRUE(a.vertices[v].x == b.vertices[v].x && a.vertices[v].y == b.vertices[v].y) << at;
}

} // namespace

TEST(Shield, WedgeGeometryMatchesLemma23) {
  for (const double theta : {1.0, 5.0, 10.0, 20.0, 30.0, 45.0, 59.0}) {
    const pdd::pslg g = wedge(theta);
    const pdd::shielded_domain sd = pdd::shield(g, std::numeric_limits<double>::infinity());
    ASSERT_EQ(sd.triangles.size(), 1u) << theta;
    ASSERT_EQ(sd.shield_segments.size(), 1u);
    EXPECT_EQ(sd.domain.segments[sd.shield_segments[0]].marker, pdd::shield_marker);
    const double l = pdd::lfs_min(g);
    EXPECT_DOUBLE_EQ(sd.l, l);
    const pdd::shield_triangle& t = sd.triangles[0];
    EXPECT_NEAR(t.angle_deg, theta, 1e-9);
    const double r = theta * deg;
    const double ab = std::hypot(t.b.x, t.b.y), ac = std::hypot(t.c.x, t.c.y);
    const double expect = l / (2 * std::sin(r / 2) * (std::cos(r / 2) + std::sin(r)));
    EXPECT_NEAR(ab, expect, 1e-12);
    EXPECT_NEAR(ac, expect, 1e-12);
    // (i): |b'c'| = l / (cos(theta/2) + sin theta); ccw orientation.
    EXPECT_NEAR(std::hypot(t.b.x - t.c.x, t.b.y - t.c.y), l / (std::cos(r / 2) + std::sin(r)),
                1e-12);
    EXPECT_GT((t.b.x - t.apex.x) * (t.c.y - t.apex.y) - (t.b.y - t.apex.y) * (t.c.x - t.apex.x),
              0.0);
    // Theorem 24 (1)-(3): D' has no angle < 60 deg and l / sqrt 3 < lfs_min(D') <= l.
    EXPECT_GE(pdd::min_domain_angle_deg(sd.domain), 60.0 - 1e-9) << theta;
    const double lp = pdd::lfs_min(sd.domain);
    // The bound of Lemma 23 fails for wide wedges whose domain is the triangle itself: the
    // shield points are then closer than l / sqrt 3 to the closing segment bc (45 deg:
    // 0.4005 < 0.4082 with l = 0.7071), a case the proof's (iii) does not cover. The pipeline
    // computes lfs_min(D') itself for k, so it needs only the weaker bound.
    EXPECT_GT(lp, l / (theta <= 30.0 ? std::sqrt(3.0) : 2.0) * (1 - 1e-12)) << theta;
    EXPECT_LE(lp, l * (1 + 1e-12)) << theta;
    EXPECT_NEAR(area_of(sd.domain) + pdd::detail::triangle_area(t.apex, t.b, t.c), area_of(g),
                1e-12);
  }
}

TEST(Shield, AreaBoundLimitsShieldedTriangles) {
  for (const double theta : {5.0, 20.0, 45.0}) {
    const double a = 1e-4;
    const pdd::shielded_domain sd = pdd::shield(wedge(theta), a);
    ASSERT_EQ(sd.triangles.size(), 1u);
    const pdd::shield_triangle& t = sd.triangles[0];
    EXPECT_LE(pdd::detail::triangle_area(t.apex, t.b, t.c), a * (1 + 1e-9)); // Theorem 24 (6)
    EXPECT_LT(std::hypot(t.b.x - t.c.x, t.b.y - t.c.y), std::sqrt(a / std::sqrt(2.0)) * 1.000001);
  }
}

TEST(Shield, NoSmallAngleLeavesDomainUnchanged) {
  pdd::pslg g;
  g.add_loop(std::vector<pdd::point>{{0, 0}, {1, 0}, {1, 1}, {0, 1}}, 3);
  const pdd::shielded_domain sd = pdd::shield(g, 0.01);
  EXPECT_TRUE(sd.triangles.empty());
  EXPECT_EQ(sd.domain.vertices, g.vertices);
}

TEST(Shield, TwoSmallAnglesOnOneShortSegment) {
  const pdd::pslg g = zigzag();
  const pdd::shielded_domain sd = pdd::shield(g, std::numeric_limits<double>::infinity());
  ASSERT_EQ(sd.triangles.size(), 2u);
  EXPECT_GE(pdd::min_domain_angle_deg(sd.domain), 60.0 - 1e-9);
  EXPECT_GT(pdd::lfs_min(sd.domain), sd.l / std::sqrt(3.0) * (1 - 1e-12)); // Lemma 23 (iv)
}

TEST(Shield, ReservedMarkerIsRejected) {
  pdd::pslg g = wedge(10);
  g.segments[0].marker = pdd::shield_marker;
  EXPECT_THROW(pdd::shield(g, 1.0), pdd::geometry_error);
}

TEST(ShieldMesh, HandMadeDomainsMonolithicAndDecoupled) {
  struct c {
    std::string name;
    pdd::pslg g;
    double area;
  };
  std::vector<c> cases;
  for (const double theta : {1.0, 5.0, 10.0, 20.0, 30.0, 45.0, 59.0})
    cases.push_back({"wedge " + std::to_string(theta), wedge(theta), 2e-3});
  cases.push_back({"zigzag", zigzag(), 2e-2});
  cases.push_back({"star", star(), 2e-3});
  for (const auto& k : cases) {
    const auto m1 = check_mesh(k.g, k.area, 1, 1, k.name);
    EXPECT_GT(pdd::compute_shielding_statistics(m1, k.g).shielded_triangles, 0u) << k.name;
    for (const std::size_t n : {2u, 16u, 64u}) {
      // N = 64 needs enough triangles per subdomain: about 100 each.
      const double area = std::min(k.area, area_of(k.g) / (100.0 * static_cast<double>(n)));
      const auto a = check_mesh(k.g, area, n, 1, k.name);
      const auto b = check_mesh(k.g, area, n, 2, k.name);
      expect_same(a, b, k.name);
    }
  }
}

TEST(ShieldDecouple, ShieldsKeepTheUnshieldedK) {
  // Shield lengths capped at sqrt 3 k0 (shield_length_cap), not k0: the shielded subdomains'
  // lfs_min(D') stays >= k0, so k stays the unshielded decomposition's k0 and the interface
  // pieces keep their length (with the cap k0, k fell to 0.58-0.85 k0 on these cases). Below
  // about 7 deg the area bound itself makes l_i short ((1 + 2 sin(theta/2)) sqrt(2 A sin theta)
  // < sqrt 3 k0) and k falls with it (5 deg: 0.994 k0, 1 deg: 0.44 k0): not asserted here.
  std::vector<std::pair<std::string, pdd::pslg>> cases{{"star", star()}};
  for (const double theta : {10.0, 15.0, 20.0, 30.0, 45.0, 59.0})
    cases.emplace_back("wedge " + std::to_string(theta), wedge(theta));
  for (const auto& [name, g] : cases) {
    pdd::generate_options o;
    o.criteria.max_area = area_of(g) / 20000.0;
    o.subdomains = 16;
    o.threads = 1;
    pdd::pipeline<> pl(g, o);
    const pdd::decomposition unshielded = pl.decompose(); // a copy: decouple() shields in place
    const double k0 = pdd::decouple(unshielded, {o.criteria}).k;
    const pdd::decoupled_decomposition& dd = pl.decouple();
    EXPECT_GT(dd.num_shielded_triangles(), 0u) << name;
    // the pipeline's graded path: its smallest k_i, from shields 1e-9 (relative) shorter than
    // Theorem 26's l_i (shielding/graded_shields.hpp)
    EXPECT_NEAR(dd.k, k0, 1e-8 * k0) << name;
    EXPECT_LE(dd.k, k0) << name;
  }
}

TEST(ShieldMadd, NoSeparatorEndsAtASmallAngle) {
  for (const pdd::pslg& g : {star(), zigzag()}) {
    const auto apex = pdd::detail::small_angle_apexes(g);
    pdd::madd_options mo;
    mo.subdomains = 16;
    mo.threads = 1;
    const pdd::decomposition d = pdd::decompose(g, mo);
    for (const auto& sd : d.subdomains)
      for (std::size_t l = 0; l < sd.loops.size(); ++l)
        for (std::size_t i = 0; i < sd.loops[l].size(); ++i) {
          const pdd::point p = d.vertices[sd.loops[l][i]];
          if (!apex.count({p.x, p.y})) continue;
          const std::size_t n = sd.loops[l].size();
          EXPECT_EQ(sd.tags[l][i].type, pdd::edge_tag::kind::external);
          EXPECT_EQ(sd.tags[l][(i + n - 1) % n].type, pdd::edge_tag::kind::external);
        }
  }
}

TEST(ShieldMesh, SharedGeometries) {
  const auto files = pdd::test::shared_poly_files();
  if (files.empty()) GTEST_SKIP() << "no shared data";
  // What was checked: files meshed monolithically, decoupled meshes compared across thread
  // counts, decouplings checked without meshing (too many split points for a quick test), and
  // files that pdd rejects (not made of closed loops; printed with the reason).
  std::size_t meshed = 0, decoupled = 0, decoupled_only = 0;
  std::vector<std::string> rejected;
  for (const auto& f : files) {
    const std::string name = f.filename().string();
    pdd::pslg g;
    try {
      g = pdd::read_poly(f.string());
      if (!pdd::has_closed_loops(g)) // validates
        throw pdd::geometry_error("not made of closed loops: meshed whole by the kernel "
                                  "(tests/pipeline/general_pslg_test.cpp)");
    } catch (const pdd::error& e) {
      rejected.push_back(name + ": " + e.what());
      continue;
    }
    const pdd::pslg_properties p = pdd::analyze(g);
    const double area = p.area / 3000.0; // coarse: a few thousand triangles
    std::printf("%s: min angle %.2f deg\n", name.c_str(), p.min_angle_deg);
    std::fflush(stdout);
    const auto m1 = check_mesh(g, area, 1, 1, name);
    std::printf("  monolithic %zu triangles\n", m1.triangles.size());
    std::fflush(stdout);
    ++meshed;
    for (const std::size_t n : {2u, 16u, 64u}) {
      // The uniform method refines every separator to k <= lfs_min: where a tiny feature makes
      // that too fine for a quick test, only the shielding and decoupling are checked.
      pdd::generate_options o;
      o.criteria.max_area = area;
      o.subdomains = n;
      o.threads = 1;
      pdd::pipeline<> pl(g, o);
      const pdd::decoupled_decomposition& dd = pl.decouple();
      std::printf("  N=%zu k %.3g split points %zu shielded %zu\n", n, dd.k, dd.num_split_points(),
                  dd.num_shielded_triangles());
      std::fflush(stdout);
      EXPECT_GT(dd.k, 0.0) << name << " N=" << n;
      if (dd.num_split_points() > 40000) {
        ++decoupled_only;
        continue;
      }
      const auto a = check_mesh(g, area, n, 1, name);
      std::printf("  N=%zu %zu triangles\n", n, a.triangles.size());
      std::fflush(stdout);
      const auto b = check_mesh(g, area, n, 2, name);
      expect_same(a, b, name);
      ++decoupled;
    }
  }
  for (const auto& r : rejected)
    std::printf("rejected (skipped): %s\n", r.c_str());
  std::printf("%zu files: %zu meshed (%zu decoupled meshes, %zu decouplings only), %zu rejected\n",
              files.size(), meshed, decoupled, decoupled_only, rejected.size());
  EXPECT_EQ(meshed + rejected.size(), files.size());
  EXPECT_GT(meshed, 0u) << "no shared geometry was meshed";
  EXPECT_GT(decoupled, 0u) << "no decoupled mesh was compared";
  EXPECT_EQ(decoupled + decoupled_only, 3 * meshed);
}

} // namespace shielding_test
