// Tests of geometry.h: rectangles, their subtraction and the pieces left.
#include "layout/geometry.h"

#include <gtest/gtest.h>

#include "layout_support.h"

namespace curdle {
using test::design;

TEST(Geometry, SubtractKeepsExactlyWhatNoHoleCovers) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(0, 100);
  for (int trial = 0; trial < 300; ++trial) {
    const Rect a{u(rng), u(rng), 1 + u(rng), 1 + u(rng)};
    // Disjoint holes: cells of a coarse grid, so their areas simply add.
    std::vector<Rect> holes;
    std::set<std::pair<int, int>> used;
    for (int i = 0; i < 4; ++i) {
      const int gx = static_cast<int>(u(rng) / 25), gy = static_cast<int>(u(rng) / 25);
      if (used.insert({gx, gy}).second)
        holes.push_back(Rect{gx * 50.0, gy * 50.0, 10 + u(rng) / 4, 10 + u(rng) / 4});
    }
    const auto pieces = subtract(a, holes);
    double kept = 0, covered = 0;
    for (const Rect& p : pieces) {
      kept += p.area();
      EXPECT_NEAR(intersection(p, a), p.area(), 1e-9);
      for (const Rect& h : holes) EXPECT_NEAR(intersection(p, h), 0, 1e-9);
    }
    for (size_t i = 0; i < pieces.size(); ++i)
      for (size_t j = i + 1; j < pieces.size(); ++j)
        EXPECT_NEAR(intersection(pieces[i], pieces[j]), 0, 1e-9);
    for (const Rect& h : holes) covered += intersection(a, h);
    EXPECT_NEAR(kept + covered, a.area(), 1e-6);
  }
}

}  // namespace curdle
