// pdd::madd_start (the regions MADD starts from, found once) and the one-triangulation helpers
// behind it: domain_faces' validating constructor, its area, and inverse_area_integral on given
// triangles. Each must give bitwise what the separate calls gave, and the same errors.
#include <pdd/errors.hpp>
#include <pdd/geometry/domain_faces.hpp>
#include <pdd/geometry/loops.hpp>
#include <pdd/geometry/model_domains.hpp>
#include <pdd/madd/decompose.hpp>
#include <pdd/madd/face_decoupling.hpp>
#include <pdd/madd/madd_start.hpp>
#include <pdd/madd/validate_decomposition.hpp>
#include <pdd/sizing/analytic.hpp>
#include <pdd/sizing/inverse_area_integral.hpp>

#include "decomposition_compare.hpp"
#include "general_domains.hpp"
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

namespace madd_start_test {

using pdd::pslg;

std::vector<std::pair<std::string, pslg>> domains() {
  pslg triangle_rule_key = pdd::key_domain();
  triangle_rule_key.rule = pdd::domain_rule::triangle;
  return {{"key", pdd::key_domain()},
          {"key, Triangle's rule", triangle_rule_key},
          {"pipe", pdd::pipe_domain(96, 32)},
          {"layered", pdd::test::layered_domain()},
          {"pinched", pdd::test::pinched_rings()},
          {"tgrid", pdd::test::t_junction_grid()},
          {"combined", pdd::test::combined_domain()},
          {"random map 3", pdd::test::random_map(3)}};
}

TEST(MaddStart, ValidatingFacesAreTheFacesOfTrianglesRule) {
  for (auto [name, g] : domains()) {
    SCOPED_TRACE(name);
    const pdd::domain_faces validated(g, pdd::domain_faces::validate_first{});
    g.rule = pdd::domain_rule::triangle;
    const pdd::domain_faces by_rule(g);
    EXPECT_EQ(validated.closed_loops(), by_rule.closed_loops());
    EXPECT_EQ(validated.closed_loops(), pdd::has_closed_loops(g));
    EXPECT_EQ(validated.face_count(), by_rule.face_count());
    const auto a = validated.triangles(), b = by_rule.triangles();
    ASSERT_EQ(a.size(), b.size());
    for (std::size_t i = 0; i < a.size(); ++i) {
      EXPECT_EQ(a[i].vertices, b[i].vertices);
      EXPECT_EQ(a[i].face, b[i].face);
    }
    EXPECT_EQ(std::bit_cast<std::uint64_t>(validated.area()),
              std::bit_cast<std::uint64_t>(pdd::domain_area(g)));
    EXPECT_EQ(validated.loops() != nullptr, validated.closed_loops());
  }
}

TEST(MaddStart, ValidatingFacesRejectWhatValidateRejects) {
  pslg crossing; // two segments crossing inside a square
  crossing.add_loop(std::vector<pdd::point>{{0, 0}, {4, 0}, {4, 4}, {0, 4}});
  const auto a = crossing.add_vertex({1, 1}), b = crossing.add_vertex({3, 3});
  const auto c = crossing.add_vertex({1, 3}), d = crossing.add_vertex({3, 1});
  crossing.add_segment(a, b);
  crossing.add_segment(c, d);
  EXPECT_THROW(pdd::validate(crossing), pdd::geometry_error);
  EXPECT_THROW(pdd::domain_faces(crossing, pdd::domain_faces::validate_first{}),
               pdd::geometry_error);
  EXPECT_THROW(pdd::madd_start{crossing}, pdd::geometry_error);
  pslg hole_on_segment = pdd::key_domain();
  hole_on_segment.holes.push_back(hole_on_segment.vertices[0]);
  EXPECT_THROW(pdd::madd_start{hole_on_segment}, pdd::geometry_error);
}

TEST(MaddStart, InverseAreaIntegralOnGivenTrianglesIsTheDomainsOwn) {
  const pdd::analytic_sizing f{[](pdd::point p) { return 1e-3 * (1.0 + p.x * p.x + p.y * p.y); }};
  for (auto [name, g] : domains()) {
    SCOPED_TRACE(name);
    g.rule = pdd::domain_rule::triangle;
    const pdd::domain_faces faces(g);
    for (const std::size_t samples : {std::size_t{1}, std::size_t{1} << 12}) {
      const double whole = pdd::inverse_area_integral(g, 5e-3, f, samples);
      const double given =
          pdd::inverse_area_integral(g.vertices, faces.triangles(), 5e-3, f, samples);
      EXPECT_GT(whole, 0.0);
      EXPECT_EQ(std::bit_cast<std::uint64_t>(whole), std::bit_cast<std::uint64_t>(given));
    }
  }
}

TEST(MaddStart, FacesAndCapsAreThoseOfFaceDecoupling) {
  for (auto [name, g] : domains()) {
    SCOPED_TRACE(name);
    const pdd::madd_start start(g);
    EXPECT_EQ(start.general(), !pdd::has_closed_loops(g));
    if (!start.general()) {
      EXPECT_TRUE(start.cap_reason().empty());
      std::size_t components = 0; // one region per outer loop
      for (const pdd::polygon_loop& l : pdd::find_loops(g).loops)
        components += l.bounds_domain_inside ? 1 : 0;
      EXPECT_EQ(start.regions().size(), components);
      continue;
    }
    const pdd::face_decoupling_report r = pdd::face_decoupling(g);
    EXPECT_EQ(start.cap_reason(), r.cap_reason);
    EXPECT_EQ(start.regions().size(), r.regions);
    EXPECT_EQ(r.cap_reason.empty(), r.regions == r.faces);
  }
  // the pinched rings' face touches itself: its loops are weakly simple, visiting each pinch
  // vertex once per sector (the outer loop (5, 0) twice, the one hole loop (5, 5) twice)
  const pslg rings = pdd::test::pinched_rings();
  const pdd::madd_start pinched(rings);
  EXPECT_TRUE(pinched.cap_reason().empty()) << pinched.cap_reason();
  ASSERT_EQ(pinched.regions().size(), 1u);
  const auto& loops = pinched.regions()[0].loops;
  ASSERT_EQ(loops.size(), 2u);
  const auto visits = [](const pdd::detail::madd_loop& l, pdd::point p) {
    return std::count(l.points.begin(), l.points.end(), p);
  };
  EXPECT_EQ(visits(loops[0], {5, 0}), 2);
  EXPECT_EQ(visits(loops[1], {5, 5}), 2);
  EXPECT_EQ(loops[0].size() + loops[1].size(), rings.segments.size()); // each segment once
  EXPECT_DOUBLE_EQ(pinched.regions()[0].area, 100.0 - 2 * 4.5 - 2.0);
  const pdd::decomposition d = pdd::decompose(pinched, pdd::madd_options{.subdomains = 4});
  const pdd::decomposition_report rep = pdd::validate_decomposition(d, rings);
  EXPECT_TRUE(rep.ok()) << (rep.problems.empty() ? "" : rep.problems.front());
}

TEST(MaddStart, DecomposingFromOneStartIsDecomposingTheDomain) {
  for (auto [name, g] : domains()) {
    SCOPED_TRACE(name);
    const pdd::madd_start start(g);
    for (const std::size_t n : {std::size_t{8}, std::size_t{16}}) {
      pdd::madd_options o;
      o.subdomains = std::max(n, start.regions().size());
      const pdd::decomposition once = pdd::decompose(start, o);
      pdd::test::expect_same_decomposition(once, pdd::decompose(g, o));
      pdd::test::expect_same_decomposition(once,
                                           pdd::decompose(start, o)); // the start is not used up
    }
  }
}

/// A unit square with its diagonal (0, 0) - (1, 1): corners of 45 deg on the segment between
/// its two faces at both ends.
pslg square_with_diagonal() {
  pslg g;
  g.add_loop(std::vector<pdd::point>{{0, 0}, {1, 0}, {1, 1}, {0, 1}});
  g.add_segment(0, 2);
  g.rule = pdd::domain_rule::triangle;
  return g;
}

TEST(MaddStart, CapsAroundSmallAnglesBetweenFacesAreKeptWholeWithChordsAtWideAngles) {
  const pslg g = square_with_diagonal();
  const pdd::madd_start start(g);
  ASSERT_EQ(start.regions().size(), 4u); // the two faces less the caps, two caps
  const pdd::face_decoupling_report r = pdd::face_decoupling(g);
  ASSERT_EQ(r.caps.size(), 2u);
  EXPECT_EQ(r.faces, 2u);
  EXPECT_EQ(r.caps[0].first, (pdd::point{0, 0}));
  EXPECT_EQ(r.caps[1].first, (pdd::point{1, 1}));
  EXPECT_DOUBLE_EQ(r.caps[0].second, 0.25); // a quarter of the distance to (1, 0)
  double area = 0.0;
  std::size_t caps = 0;
  for (const pdd::detail::madd_region& region : start.regions()) {
    area += region.area;
    if (!region.keep_whole) continue;
    ++caps;
    ASSERT_EQ(region.loops.size(), 1u);
    const pdd::detail::madd_loop& l = region.loops[0];
    ASSERT_EQ(region.features.size(), 1u); // the diagonal's piece
    EXPECT_EQ(region.features[0].segment, 4u);
    std::size_t chords = 0;
    for (std::size_t i = 0; i < l.size(); ++i) {
      const pdd::point prev = l.points[(i + l.size() - 1) % l.size()], v = l.points[i],
                       next = l.points[(i + 1) % l.size()];
      chords += l.tags[i].external ? 0 : 1;
      const bool apex = v == r.caps[0].first || v == r.caps[1].first;
      if (!apex) {
        EXPECT_GE(pdd::detail::interior_angle_deg(prev, v, next), 65.0 - 1e-9);
      }
      if (!l.tags[i].external) { // a chord: at most 50 deg of arc, both ends on the circle
        EXPECT_LE(pdd::detail::distance(v, next),
                  2 * std::sin(25 * std::numbers::pi / 180) * r.caps[0].second * (1 + 1e-12));
      }
    }
    EXPECT_EQ(chords, 2u); // one per 45 deg sector
  }
  EXPECT_EQ(caps, 2u);
  EXPECT_NEAR(area, 1.0, 1e-12);
  for (const std::size_t n : {std::size_t{4}, std::size_t{16}}) {
    const pdd::decomposition d = pdd::decompose(start, pdd::madd_options{.subdomains = n});
    ASSERT_EQ(d.subdomains.size(), n);
    const pdd::decomposition_report rep = pdd::validate_decomposition(d, g);
    EXPECT_TRUE(rep.ok()) << (rep.problems.empty() ? "" : rep.problems.front());
    std::size_t whole_caps = 0; // subdomains with every vertex inside a cap's circle
    for (const pdd::subdomain& sd : d.subdomains) {
      bool inside = true;
      for (const auto& loop : sd.loops)
        for (const pdd::index_t v : loop) {
          const pdd::point p = d.vertices[v];
          inside = inside && std::min(pdd::detail::distance(p, r.caps[0].first),
                                      pdd::detail::distance(p, r.caps[1].first)) <=
                                 r.caps[0].second * (1 + 1e-12);
        }
      whole_caps += inside ? 1 : 0;
    }
    EXPECT_EQ(whole_caps, 2u) << n;
  }
}

TEST(MaddStart, ACapIsNeverSplitEvenWhenItsAreaIsAboveTheBound) {
  // A square cut by an oblique chord, with a dangling segment from the chord's lower end at
  // 20 deg beside it: a cap around that end (its pieces of the two segments inside).
  // Decomposed by area with a bound below the cap's area, the regions around it are split
  // while the cap stays one subdomain of its own area. (MADD by area leaves a region it cannot
  // split above the bound without an error; that is not what this checks.)
  pslg g;
  g.add_loop(std::vector<pdd::point>{{0, 0}, {1.5, 0}, {4, 0}, {4, 4}, {2.5, 4}, {0, 4}});
  g.add_segment(1, 4);
  const double turn = std::atan2(4.0, 1.0) + 20.0 * std::numbers::pi / 180.0;
  g.add_segment(1, g.add_vertex({1.5 + std::cos(turn), std::sin(turn)}));
  g.rule = pdd::domain_rule::triangle;
  const pdd::madd_start start(g);
  const auto caps = pdd::face_decoupling(g).caps;
  ASSERT_EQ(caps.size(), 1u);
  const auto [apex, radius] = caps[0];
  double cap_area = 0.0;
  for (const pdd::detail::madd_region& region : start.regions())
    if (region.keep_whole) cap_area = region.area;
  ASSERT_GT(cap_area, 0.0);
  const pdd::decomposition d =
      pdd::decompose(start, pdd::madd_options{.max_subdomain_area = 0.4 * cap_area});
  const pdd::decomposition_report rep = pdd::validate_decomposition(d, g);
  EXPECT_TRUE(rep.ok()) << (rep.problems.empty() ? "" : rep.problems.front());
  EXPECT_GT(d.subdomains.size(), 16u);
  std::vector<double> inside_circle; // the areas of the subdomains inside the cap's circle
  for (const pdd::subdomain& sd : d.subdomains) {
    bool inside = true;
    double area = 0.0;
    for (const auto& loop : sd.loops) {
      std::vector<pdd::point> pts;
      for (const pdd::index_t v : loop) {
        pts.push_back(d.vertices[v]);
        inside = inside && pdd::detail::distance(d.vertices[v], apex) <= radius * (1 + 1e-12);
      }
      area += pdd::detail::polygon_signed_area(pts);
    }
    if (inside) inside_circle.push_back(area);
  }
  ASSERT_EQ(inside_circle.size(), 1u);
  EXPECT_NEAR(inside_circle[0], cap_area, 1e-12 * cap_area);
}

} // namespace madd_start_test
