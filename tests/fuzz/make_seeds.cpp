// Writes the generated part of the fuzzer's seed corpus: small domains made by pdd's own
// generators (model domains, the geometry tests' random domains) and a few hand-shaped ones that
// reach the interesting paths (small input angles that get shielded, holes, thin parts, a
// regions section), and small general domains (issue 13, by Triangle's rule, meshed whole or
// decoupled from their faces: an internal constraint, a dangling segment and isolated vertices,
// an internal boundary, loops touching at pinch vertices (random small sectors too), a T-junction
// grid, a fan of dangling segments at 15 deg, random arrangements and maps,
// tests/common/general_domains.hpp; features filling a face's middle, which MADD splits beside
// with chords, tests/common/dense_features.hpp; one with a 0.2 deg angle the kernel refuses).
// The bundled examples/data files are the other seeds.
//
//   pdd_fuzz_seeds DIR     writes DIR/<name>.poly (DIR is created)
#include <pdd/core/pslg.hpp>
#include <pdd/geometry/model_domains.hpp>
#include <pdd/io/poly.hpp>

#include "dense_features.hpp"
#include "general_domains.hpp"
#include "random_domains.hpp"

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

namespace {

pdd::pslg polygon(const std::vector<pdd::point>& outer) {
  pdd::pslg g;
  g.add_loop(outer, 1);
  return g;
}

/// A star with `spikes` tips at radius 1 and notches at radius `inner` (tip angles < 60 deg).
pdd::pslg star(int spikes, double inner) {
  std::vector<pdd::point> p;
  for (int i = 0; i < 2 * spikes; ++i) {
    const double r = i % 2 == 0 ? 1.0 : inner, a = i * std::numbers::pi / spikes;
    p.push_back({r * std::cos(a), r * std::sin(a)});
  }
  return polygon(p);
}

/// A triangle with an angle of `deg` degrees at the origin, legs of length 1.
pdd::pslg wedge(double deg) {
  const double a = deg * std::numbers::pi / 180.0;
  return polygon({{0, 0}, {1, 0}, {std::cos(a), std::sin(a)}});
}

pdd::pslg square_with_hole() {
  pdd::pslg g = polygon({{0, 0}, {1, 0}, {1, 1}, {0, 1}});
  g.add_loop(std::vector<pdd::point>{{0.4, 0.4}, {0.4, 0.6}, {0.6, 0.6}, {0.6, 0.4}}, 2);
  g.holes.push_back({0.5, 0.5});
  return g;
}

pdd::pslg square_with_region() {
  pdd::pslg g = polygon({{0, 0}, {2, 0}, {2, 1}, {0, 1}});
  g.regions.push_back({{0.5, 0.5}, 1.0, 0.01});
  return g;
}

/// A comb: `teeth` teeth of width 0.1 and length 0.5 on a base of height 0.2.
pdd::pslg comb(int teeth) {
  std::vector<pdd::point> p{{0, 0}, {0.2 * teeth, 0}, {0.2 * teeth, 0.2}};
  for (int t = teeth - 1; t >= 0; --t) {
    const double x = 0.2 * t;
    p.insert(p.end(), {{x + 0.15, 0.7}, {x + 0.05, 0.7}});
    if (t > 0) p.push_back({x, 0.2});
  }
  return polygon(p);
}

pdd::pslg square4() {
  return polygon({{0, 0}, {4, 0}, {4, 4}, {0, 4}});
}

/// A 4 x 4 square with a dangling segment and two isolated vertices.
pdd::pslg dangling_and_isolated() {
  pdd::pslg g = square4();
  g.add_segment(g.add_vertex({1, 1}), g.add_vertex({2.5, 3}));
  g.add_vertex({1.3, 2.7});
  g.add_vertex({3.1, 0.9});
  return g;
}

/// A 4 x 4 square with an inner square loop and no hole point (both sides are the domain).
pdd::pslg internal_boundary() {
  pdd::pslg g = square4();
  g.add_loop(std::vector<pdd::point>{{1, 1}, {3, 1}, {3, 3}, {1, 3}}, 2);
  return g;
}

/// A 4 x 4 square with four dangling segments of length 1.5 from its centre, 15 deg apart (a
/// cluster: cluster-exempt triangles).
pdd::pslg dangling_fan() {
  pdd::pslg g = square4();
  const pdd::index_t c = g.add_vertex({2, 2});
  for (int i = 0; i < 4; ++i) {
    const double a = (20.0 + 15.0 * i) * std::numbers::pi / 180.0;
    g.add_segment(c, g.add_vertex({2 + 1.5 * std::cos(a), 2 + 1.5 * std::sin(a)}));
  }
  return g;
}

std::vector<std::pair<std::string, pdd::pslg>> general_seeds() {
  pdd::pslg diagonal = square4();
  diagonal.add_segment(0, 2);
  return {{"general-internal-diagonal", diagonal},
          {"general-dangling-isolated", dangling_and_isolated()},
          {"general-internal-boundary", internal_boundary()},
          {"general-dangling-fan", dangling_fan()},
          {"general-layered", pdd::test::layered_domain(0.5)},
          {"general-pinched", pdd::test::pinched_rings()},
          {"general-pinched-sectors", pdd::test::pinched_sectors()},
          {"general-pinched-random", pdd::test::random_pinched(3)},
          {"general-pinched-cracks", pdd::test::random_pinched(4, 0.6)},
          {"general-faulted", pdd::test::faulted_layers()},
          {"general-dense-spiral", pdd::test::spiral_from_a_corner()},
          {"general-dense-wells", pdd::test::random_dense_features(4)},
          {"general-dense-comb", pdd::test::random_dense_features(5)},
          {"general-t-junctions", pdd::test::t_junction_grid()},
          {"general-combined", pdd::test::combined_domain(0.5)},
          {"general-random-1", pdd::test::random_arrangement(1)},
          {"general-random-2", pdd::test::random_arrangement(2)},
          {"general-map-1", pdd::test::random_map(1, 4)},
          {"general-map-2", pdd::test::random_map(2, 4)},
          {"general-sub-degree-angle", pdd::test::sub_degree_angle_domain()}};
}

std::vector<std::pair<std::string, pdd::pslg>> seeds() {
  std::vector<std::pair<std::string, pdd::pslg>> s{
      {"key", pdd::key_domain()},
      {"pipe-12-6", pdd::pipe_domain(12, 6)},
      {"square", polygon({{0, 0}, {1, 0}, {1, 1}, {0, 1}})},
      {"l-shape", polygon({{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}})},
      {"thin", polygon({{0, 0}, {1, 0}, {1, 0.02}, {0, 0.02}})},
      {"square-hole", square_with_hole()},
      {"square-region", square_with_region()},
      {"star-5", star(5, 0.4)},
      {"star-12", star(12, 0.6)},
      {"wedge-10", wedge(10.0)},
      {"wedge-45", wedge(45.0)},
      {"comb-4", comb(4)},
  };
  for (const std::uint64_t seed : {1u, 2u, 3u, 4u})
    s.emplace_back("random-" + std::to_string(seed), pdd::test::random_domain(seed, 1, 0.5).g);
  for (auto& general : general_seeds())
    s.push_back(std::move(general));
  return s;
}

} // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: pdd_fuzz_seeds DIR\n");
    return 2;
  }
  try {
    const std::filesystem::path dir = argv[1];
    std::filesystem::create_directories(dir);
    for (const auto& [name, g] : seeds())
      pdd::write_poly(dir / (name + ".poly"), g);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "pdd_fuzz_seeds: %s\n", e.what());
    return 1;
  }
  return 0;
}
