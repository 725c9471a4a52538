// Test fixture: two decompositions with the same vertices (coordinates) and the same subdomain
// loops (vertex ids), e.g. one made on 1 thread and one on 2.
#pragma once

#include <pdd/core/decomposition.hpp>

#include <gtest/gtest.h>

namespace pdd::test {

inline void expect_same_decomposition(const pdd::decomposition& a, const pdd::decomposition& b) {
  ASSERT_EQ(a.vertices.size(), b.vertices.size());
  ASSERT_EQ(a.subdomains.size(), b.subdomains.size());
  for (std::size_t i = 0; i < a.vertices.size(); ++i) {
    EXPECT_EQ(a.vertices[i].x, b.vertices[i].x);
    EXPECT_EQ(a.vertices[i].y, b.vertices[i].y);
  }
  for (std::size_t s = 0; s < a.subdomains.size(); ++s)
    EXPECT_EQ(a.subdomains[s].loops, b.subdomains[s].loops);
}

} // namespace pdd::test
