/// \file segment_markers.hpp
/// The two boundary markers pdd reserves for the segments it adds to a kernel's input: the
/// interface pieces of the decoupling path and the shield edges of small input angles. The
/// kernels tell them from input segments by these markers (pdd::segment_encroachment).
#pragma once

#include <limits>

namespace pdd {

/// The boundary marker of interface pieces in the subdomain inputs (and therefore in the
/// segments of each subdomain mesh). Reserved: input segments may not carry it.
inline constexpr int interface_marker = std::numeric_limits<int>::min();

/// The boundary marker of shield edges b'c' in shielded domains (and in the kernel's output
/// for them). Reserved: input segments may not carry it.
inline constexpr int shield_marker = std::numeric_limits<int>::min() + 1;

/// Whether a segment marker is one pdd reserves (interface_marker, shield_marker).
constexpr bool is_reserved_marker(int marker) noexcept {
  return marker == interface_marker || marker == shield_marker;
}

} // namespace pdd
