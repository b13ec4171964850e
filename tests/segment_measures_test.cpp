// Tests of segment_measures.h.
#include "curdle/segment_measures.h"

#include <gtest/gtest.h>

#include "search_support.h"

namespace curdle {
TEST(SegmentMeasures, CountsAndBoxCountsMatchTheReportOfTheWindow) {
  const Design d = two_curds_128();
  const CurdField field = curdle(d, 5, d.field);
  SegmentMeasures m;
  m.reset(d, d.field, values_in(field, d.field));
  for (const Box& w :
       {box(0, 0, 200, 150), box(37, 11, 67, 67), box(120, 100, 80, 50), box(127, 127, 3, 2)}) {
    const Report r = make_report(d, 5, field, w);
    for (uint32_t v = 0; v < 4; ++v) EXPECT_EQ(m.value_count(v, w), r.values[v].count);
    for (size_t c = 0; c < 2; ++c) {
      EXPECT_EQ(m.curd_count(c, w), r.curds[c].stages.back().survivors);
      EXPECT_EQ(m.box_counts(c, w), r.curds[c].box_counts) << "curd " << c;
    }
  }
}

TEST(SegmentMeasures, ClustersRunsAndLacunarityAgreeWithBruteForce) {
  Design d = test::design(2, 2, {test::repeat("0.5", 5)[0], test::repeat("0.5", 5)[0]});
  d.field.size = {32, 32, 1};
  std::mt19937 rng(3);
  std::vector<uint16_t> grid(32 * 32);
  for (auto& v : grid) v = rng() % 3 == 0;
  SegmentMeasures m;
  m.reset(d, d.field, grid);
  const Box s = box(3, 5, 20, 17);
  auto at = [&](int64_t x, int64_t y) { return grid[static_cast<size_t>(y * 32 + x)]; };
  // Largest cluster by repeated flood fill with a plain recursive walk.
  std::vector<int> label(32 * 32, 0);
  std::function<int(int64_t, int64_t, int)> fill = [&](int64_t x, int64_t y, int id) -> int {
    if (x < 3 || x >= 23 || y < 5 || y >= 22 || at(x, y) != 1 || label[y * 32 + x]) return 0;
    label[y * 32 + x] = id;
    return 1 + fill(x + 1, y, id) + fill(x - 1, y, id) + fill(x, y + 1, id) + fill(x, y - 1, id);
  };
  uint64_t largest = 0, longest = 0;
  int id = 0;
  for (int64_t y = 5; y < 22; ++y)
    for (int64_t x = 3; x < 23; ++x) largest = std::max<uint64_t>(largest, fill(x, y, ++id));
  for (int64_t y = 5; y < 22; ++y)
    for (int64_t x = 3; x < 23; ++x) {
      uint64_t h = 0, v = 0;
      while (x + h < 23 && at(x + h, y) == 1) ++h;
      while (y + v < 22 && at(x, y + v) == 1) ++v;
      longest = std::max({longest, h, v});
    }
  EXPECT_EQ(m.largest_cluster(1, s), largest);
  EXPECT_EQ(m.longest_run(1, s), longest);
  double s1 = 0, s2 = 0, n = 0;
  for (int64_t y = 5; y + 4 <= 22; ++y)
    for (int64_t x = 3; x + 4 <= 23; ++x) {
      double mass = 0;
      for (int64_t j = 0; j < 4; ++j)
        for (int64_t i = 0; i < 4; ++i) mass += at(x + i, y + j) == 1;
      s1 += mass, s2 += mass * mass, n += 1;
    }
  EXPECT_NEAR(*m.lacunarity(1, s, 4), (s2 / n) / ((s1 / n) * (s1 / n)), 1e-12);
  EXPECT_FALSE(m.lacunarity(2, s, 4));  // no cell has value 2
}

}  // namespace curdle
