// General PSLGs (Triangle's rule, issue 13) whose features fill the middle of a face, where
// the medial axis of the face runs: a spiral of dangling segments from a corner (the fuzz
// input that found the gap), a field of wells, a comb of cracks. Every separator along the
// medial axis passes near a feature, so MADD splits them with straight chords beside the
// features (madd/detail/chord_split.hpp).
#pragma once

#include <pdd/core/pslg.hpp>
#include <pdd/geometry/validate.hpp>

#include <algorithm>
#include <cstdint>
#include <random>
#include <vector>

namespace pdd::test {

/// A 4 x 4 square with a dangling square spiral (1, 1) -> (3, 1) -> (3, 3) -> (1, 3) joined to
/// the corner (0, 4) by a segment at 18.4 deg to the left side (a cap there).
inline pslg spiral_from_a_corner() {
  pslg g;
  g.add_loop(std::vector<point>{{0, 0}, {4, 0}, {4, 4}, {0, 4}}, 1);
  const index_t a = g.add_vertex({1, 1}, 2), b = g.add_vertex({3, 1}, 2);
  const index_t c = g.add_vertex({3, 3}, 2), d = g.add_vertex({1, 3}, 2);
  g.add_segment(3, a, 2);
  g.add_segment(a, b, 2);
  g.add_segment(b, c, 2);
  g.add_segment(c, d, 2);
  g.rule = domain_rule::triangle;
  return g;
}

/// A 4 x 4 square with a cross of dangling segments from its centre to 0.05 from the middle
/// of each side: every chord between opposite sides crosses an arm or passes within 0.05 of
/// one, and no chord between two neighbouring sides meets both at >= 60 deg.
inline pslg cross_to_the_sides() {
  pslg g;
  g.add_loop(std::vector<point>{{0, 0}, {4, 0}, {4, 4}, {0, 4}}, 1);
  const index_t centre = g.add_vertex({2, 2}, 2);
  for (const point p : {point{0.05, 2}, point{3.95, 2}, point{2, 0.05}, point{2, 3.95}})
    g.add_segment(centre, g.add_vertex(p, 2), 2);
  g.rule = domain_rule::triangle;
  return g;
}

/// The features of random_dense_features: a square spiral (inward, 90 deg turns) from
/// `start`, of `turns` sides, the first `side` long, each next one 0.8 times the one before.
inline void add_spiral(pslg& g, point start, double side, int turns) {
  const point dirs[] = {{1, 0}, {0, 1}, {-1, 0}, {0, -1}};
  index_t prev = g.add_vertex(start, 2);
  point p = start;
  for (int t = 0; t < turns; ++t, side *= t % 2 == 0 ? 0.8 : 1.0) {
    p = {p.x + side * dirs[t % 4].x, p.y + side * dirs[t % 4].y};
    const index_t v = g.add_vertex(p, 2);
    g.add_segment(prev, v, 2);
    prev = v;
  }
}

/// An m x m field of wells (isolated vertices) spaced `step` from `corner`.
inline void add_well_field(pslg& g, point corner, double step, int m) {
  for (int i = 0; i < m; ++i)
    for (int j = 0; j < m; ++j)
      g.add_vertex({corner.x + i * step, corner.y + j * step});
}

/// A comb of cracks: a spine from `left` of length `width`, with `m` teeth up and down of
/// random lengths up to `reach`.
inline void add_comb(pslg& g, point left, double width, double reach, int m, std::mt19937& rng) {
  std::uniform_real_distribution<double> len(0.3 * reach, reach);
  index_t prev = g.add_vertex(left, 2);
  for (int i = 1; i <= m; ++i) {
    const point p{left.x + width * i / (m + 1), left.y};
    const index_t v = g.add_vertex(p, 2);
    g.add_segment(prev, v, 2);
    g.add_segment(v, g.add_vertex({p.x, p.y + (i % 2 == 0 ? 1 : -1) * len(rng)}, 2), 2);
    prev = v;
  }
  g.add_segment(prev, g.add_vertex({left.x + width, left.y}, 2), 2);
}

/// A random W x H rectangle (3 to 6 each) whose middle, a square of 0.4 to 0.6 times the
/// shorter side around a jittered centre, holds a spiral of 4 to 6 sides (seed % 3 == 0; for
/// even seeds joined to the rectangle's corner (0, 0), at below 60 deg to a side: a cap), a
/// field of 4 x 4 to 7 x 7 wells (seed % 3 == 1) or a comb of 3 to 6 cracks (seed % 3 == 2).
/// Deterministic for a seed; valid (checked).
inline pslg random_dense_features(std::uint32_t seed) {
  std::mt19937 rng(seed * 2654435761u + 7u);
  std::uniform_real_distribution<double> side(3.0, 6.0), share(0.4, 0.6), jitter(-0.3, 0.3);
  const double w = side(rng), h = side(rng), s = share(rng) * std::min(w, h);
  const point c{w / 2 + jitter(rng), h / 2 + jitter(rng)};
  pslg g;
  g.add_loop(std::vector<point>{{0, 0}, {w, 0}, {w, h}, {0, h}}, 1);
  const point lower_left{c.x - s / 2, c.y - s / 2};
  std::uniform_int_distribution<int> count(3, 6);
  if (seed % 3 == 0) {
    const index_t first = static_cast<index_t>(g.vertices.size());
    add_spiral(g, lower_left, s, 4 + count(rng) % 3);
    if (seed % 2 == 0) g.add_segment(0, first, 2);
  } else if (seed % 3 == 1) {
    const int m = 1 + count(rng);
    add_well_field(g, lower_left, s / (m - 1), m);
  } else {
    add_comb(g, {lower_left.x, c.y}, s, 0.45 * s, count(rng), rng);
  }
  g.rule = domain_rule::triangle;
  validate(g);
  return g;
}

} // namespace pdd::test
