// Random polygons with holes (and islands inside holes) for the geometry tests.
#pragma once

#include <pdd/core/pslg.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <numbers>
#include <random>
#include <vector>

namespace pdd::test {

/// One loop of a generated domain, as built (before vertex renumbering).
struct generated_loop {
  std::vector<point> pts; ///< in construction order
  int depth = 0;
  int parent = -1; ///< index into generated_domain::loops
};

struct generated_domain {
  pslg g;
  std::vector<generated_loop> loops;
  std::vector<index_t> loop_of_vertex; ///< by pslg vertex id
};

inline double uniform(std::mt19937_64& rng, double a, double b) {
  return a + (b - a) * static_cast<double>(rng() >> 11) * 0x1.0p-53;
}

/// A star-shaped polygon around c with n vertices at sorted random angles and radii in
/// [rmin, rmax]; reversed when !ccw.
inline std::vector<point> random_star(std::mt19937_64& rng, point c, double rmin, double rmax,
                                      int n, bool ccw) {
  std::vector<double> ang(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i)
    ang[static_cast<std::size_t>(i)] = (i + uniform(rng, 0.05, 0.95)) * 2.0 * std::numbers::pi / n;
  std::vector<point> pts;
  for (double a : ang) {
    const double r = uniform(rng, rmin, rmax);
    pts.push_back({c.x + r * std::cos(a), c.y + r * std::sin(a)});
  }
  if (!ccw) std::reverse(pts.begin(), pts.end());
  return pts;
}

/// A random domain: a star-shaped outer loop (radius 10..14), star-shaped holes in some cells
/// of a 3x3 grid, some with an island (and sometimes a hole in the island). Vertex ids and
/// segment order are shuffled, loop orientations random. Every hole gets a hole point.
/// Each loop has its minimum vertex count (that keeps it star-shaped around its centre and
/// clear of its neighbours) plus up to `extra` more vertices.
inline generated_domain random_domain(std::uint64_t seed, int extra = 4, double hole_prob = 0.6) {
  std::mt19937_64 rng(seed);
  generated_domain d;
  auto nv = [&](int lo) {
    return lo + static_cast<int>(rng() % static_cast<std::uint64_t>(extra + 1));
  };
  auto coin = [&](double p) { return uniform(rng, 0, 1) < p; };
  d.loops.push_back({random_star(rng, {0, 0}, 10, 14, nv(10), coin(0.5)), 0, -1});
  std::vector<point> holes;
  for (int cell = 0; cell < 9; ++cell) {
    if (!coin(hole_prob)) continue;
    const point c{-4.0 + 4.0 * (cell % 3) + uniform(rng, -0.1, 0.1),
                  -4.0 + 4.0 * (cell / 3) + uniform(rng, -0.1, 0.1)};
    const int h = static_cast<int>(d.loops.size());
    d.loops.push_back({random_star(rng, c, 1.5, 1.8, nv(8), coin(0.5)), 1, 0});
    if (coin(0.4)) {
      const int island = static_cast<int>(d.loops.size());
      d.loops.push_back({random_star(rng, c, 0.45, 0.6, nv(8), coin(0.5)), 2, h});
      if (coin(0.4)) {
        d.loops.push_back({random_star(rng, c, 0.1, 0.2, nv(4), coin(0.5)), 3, island});
        holes.push_back(c);
      }
      // between the island (radius <= 0.6) and the hole loop (edges beyond radius 1.1)
      holes.push_back({c.x + 0.85, c.y});
    } else {
      holes.push_back(c);
    }
  }
  // Shuffle vertex ids.
  std::size_t total = 0;
  for (const auto& l : d.loops)
    total += l.pts.size();
  std::vector<index_t> perm(total);
  for (std::size_t i = 0; i < total; ++i)
    perm[i] = static_cast<index_t>(i);
  std::shuffle(perm.begin(), perm.end(), rng);
  d.g.vertices.resize(total);
  d.g.vertex_markers.assign(total, 0);
  d.loop_of_vertex.resize(total);
  std::vector<segment> segs;
  std::size_t k = 0;
  for (std::size_t l = 0; l < d.loops.size(); ++l) {
    const std::size_t n = d.loops[l].pts.size();
    for (std::size_t i = 0; i < n; ++i) {
      d.g.vertices[perm[k + i]] = d.loops[l].pts[i];
      d.loop_of_vertex[perm[k + i]] = static_cast<index_t>(l);
      index_t a = perm[k + i], b = perm[k + (i + 1) % n];
      if (coin(0.5)) std::swap(a, b);
      segs.push_back({a, b, static_cast<int>(l) + 1});
    }
    k += n;
  }
  std::shuffle(segs.begin(), segs.end(), rng);
  d.g.segments = segs;
  d.g.holes = holes;
  return d;
}

/// Shoelace area of a point sequence (reference, independent of the library).
inline double reference_area(const std::vector<point>& p) {
  double a = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const point& u = p[i];
    const point& v = p[(i + 1) % p.size()];
    a += u.x * v.y - u.y * v.x;
  }
  return 0.5 * a;
}

} // namespace pdd::test
