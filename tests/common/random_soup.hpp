// A random triangle soup with markers, for the file-format tests (the writers and readers do not
// care about geometry): nv vertices in [-1e3, 1e3]^2, every seventh with a marker in -2..2, nt
// triangles of random vertices with runs of ten equal triangle markers of both signs.
#pragma once

#include <pdd/core/triangle_mesh.hpp>

#include <cstddef>
#include <random>

namespace pdd::test {

inline triangle_mesh random_triangle_soup(unsigned seed, std::size_t nv, std::size_t nt) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> coord(-1e3, 1e3);
  std::uniform_int_distribution<index_t> vertex(0, static_cast<index_t>(nv - 1));
  triangle_mesh m;
  for (std::size_t i = 0; i < nv; ++i) {
    m.vertices.push_back({coord(rng), coord(rng)});
    m.vertex_markers.push_back(i % 7 == 0 ? static_cast<int>(i % 5) - 2 : 0);
  }
  for (std::size_t t = 0; t < nt; ++t) {
    m.triangles.push_back({vertex(rng), vertex(rng), vertex(rng)});
    m.triangle_markers.push_back(static_cast<int>(seed) - static_cast<int>(t / 10));
  }
  return m;
}

} // namespace pdd::test
