// The DelaunayMesher models every kernel test runs on (typed tests, CONTRIBUTING.md checklist).
#pragma once

#include <pdd/kernels/cgal/mesher.hpp>
#include <pdd/kernels/native/mesher.hpp>

#include <gtest/gtest.h>

#include <string>
#include <type_traits>

namespace pdd::test {

using kernel_types = ::testing::Types<pdd::cgal::mesher, pdd::native::mesher>;

/// Names the typed instances "cgal" and "native" instead of 0 and 1.
struct kernel_names {
  template <class M>
  static std::string GetName(int) {
    return std::is_same_v<M, pdd::cgal::mesher> ? "cgal" : "native";
  }
};

} // namespace pdd::test
