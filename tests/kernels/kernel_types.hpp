// The DelaunayMesher models every kernel test runs on (typed tests, CONTRIBUTING.md checklist).
#pragma once

#ifndef PDD_PERMISSIVE
#include <pdd/kernels/cgal/mesher.hpp>
#endif
#include <pdd/kernels/native/mesher.hpp>

#include <gtest/gtest.h>

#include <string>
#include <type_traits>

namespace pdd::test {

#ifdef PDD_PERMISSIVE // no CGAL Mesh_2 (GPL) in this build
using kernel_types = ::testing::Types<pdd::native::mesher>;
#else
using kernel_types = ::testing::Types<pdd::cgal::mesher, pdd::native::mesher>;
#endif

/// Names the typed instances "cgal" and "native" instead of 0 and 1.
struct kernel_names {
  template <class M>
  static std::string GetName(int) {
    return std::is_same_v<M, pdd::native::mesher> ? "native" : "cgal";
  }
};

} // namespace pdd::test
