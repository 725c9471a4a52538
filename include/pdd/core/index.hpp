/// \file index.hpp
/// pdd::index_t and pdd::no_index: the index type of vertices, segments, triangles and
/// subdomains in pdd's value types, and its "none" value.
#pragma once

#include <cstdint>
#include <limits>

namespace pdd {

/// Index type of vertices and triangles in pdd's value types.
using index_t = std::uint32_t;

/// The index that refers to nothing (no vertex, no path edge, no neighbour).
inline constexpr index_t no_index = std::numeric_limits<index_t>::max();

} // namespace pdd
