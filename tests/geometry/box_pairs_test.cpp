// Tests of pdd::for_each_box_pair: the same pairs as the quadratic test of every two boxes, on
// seeded random boxes with shared edges and corners (closed boxes: touching counts), each pair
// once with i < j.
#include <pdd/geometry/box_pairs.hpp>

#include <gtest/gtest.h>

#include <random>
#include <set>
#include <utility>
#include <vector>

namespace box_pairs_test {

bool intersect(const pdd::bbox& a, const pdd::bbox& b) {
  return a.xmin <= b.xmax && b.xmin <= a.xmax && a.ymin <= b.ymax && b.ymin <= a.ymax;
}

TEST(BoxPairs, SameAsTestingEveryTwoBoxes) {
  for (unsigned seed = 0; seed < 40; ++seed) {
    std::mt19937 rng(seed);
    const auto coordinate = [&rng] { return static_cast<double>(rng() % 40); }; // ties: touching
    std::vector<pdd::bbox> boxes(5 + seed * 10);
    for (auto& b : boxes) {
      const double x = coordinate(), y = coordinate();
      b = {x, y, x + static_cast<double>(rng() % 6), y + static_cast<double>(rng() % 6)};
    }
    std::set<std::pair<std::size_t, std::size_t>> expected, found;
    for (std::size_t i = 0; i < boxes.size(); ++i)
      for (std::size_t j = i + 1; j < boxes.size(); ++j)
        if (intersect(boxes[i], boxes[j])) expected.emplace(i, j);
    std::size_t calls = 0;
    pdd::for_each_box_pair(boxes, [&](std::size_t i, std::size_t j) {
      EXPECT_LT(i, j);
      found.emplace(i, j);
      ++calls;
    });
    EXPECT_EQ(found, expected) << "seed " << seed;
    EXPECT_EQ(calls, expected.size()) << "seed " << seed; // each pair once
  }
}

} // namespace box_pairs_test
