// Bitwise comparison of meshes for the determinism tests.
#pragma once

#include <pdd/core/triangle_mesh.hpp>

#include <cstring>

namespace pdd::test {

/// True when both meshes hold the same bytes in every array (coordinates, markers, triangles,
/// segments): the "bitwise identical output" the determinism guarantees promise.
inline bool bitwise_equal(const triangle_mesh& a, const triangle_mesh& b) {
  const auto same = [](const auto& x, const auto& y) {
    return x.size() == y.size() &&
           (x.empty() || std::memcmp(x.data(), y.data(), x.size() * sizeof(x[0])) == 0);
  };
  return same(a.vertices, b.vertices) && same(a.vertex_markers, b.vertex_markers) &&
         same(a.triangles, b.triangles) && same(a.triangle_markers, b.triangle_markers) &&
         same(a.segments, b.segments);
}

} // namespace pdd::test
