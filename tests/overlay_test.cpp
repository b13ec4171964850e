#include "curdle/overlay.h"

#include <gtest/gtest.h>

#include <algorithm>

#include "curdle/curdling.h"
#include "test_support.h"

namespace curdle {
using test::design;

TEST(Overlay, ValueCountsAgreeWithCellByCellValues) {
  for (size_t n : {1u, 3u, 6u}) {
    std::vector<std::vector<std::string>> curds(n, {"3/4", "1/2", "2/3"});
    Design d = design(4, 2, curds);
    d.field = Box{{0, 0, 0}, {70, 45, 1}};
    const CurdField f = curdle(d, 21, d.field);
    const auto counts = value_counts(f);
    std::vector<uint64_t> direct(counts.size(), 0);
    for (uint16_t v : values_in(f, d.field)) ++direct[v];
    EXPECT_EQ(counts, direct) << n << " curds";
    uint64_t total = 0;
    for (auto c : counts) total += c;
    EXPECT_EQ(total, 70u * 45u);
  }
}

TEST(Overlay, ValueIsTheSumOfCurdBits) {
  const Design d = design(4, 2, {{"1/2", "1/2"}, {"1/2", "1/2"}});
  const CurdField f = curdle(d, 2, d.field);
  const auto values = values_in(f, d.field);
  size_t i = 0;
  for (int64_t y = 0; y < 16; ++y)
    for (int64_t x = 0; x < 16; ++x, ++i) {
      const uint64_t bit = f.index.finest_index({x, y, 0});
      EXPECT_EQ(values[i], f.finest(0).test(bit) + 2 * f.finest(1).test(bit));
    }
}

TEST(Overlay, Labels) {
  const Design d = design(4, 2, {{"1/2"}, {"1/2"}, {"1/2"}});
  EXPECT_EQ(value_label(0, d.curds), "empty");
  EXPECT_EQ(value_label(5, d.curds), "c0+c2");
}

TEST(Overlay, RestrictingToAViewKeepsOnlyItsCells) {
  Design d = design(4, 2, {{"3/4", "3/4"}}, Mode::quota);
  const CurdField f = curdle(d, 4, d.field);
  const Box view{{3, 5, 0}, {7, 6, 1}};
  const CurdField r = restrict_to(f, view);
  const std::vector<uint16_t> inside = values_in(f, view);
  EXPECT_EQ(values_in(r, view), inside);
  // Counted from the whole field's values, not as a remainder: the survivors outside the view
  // must be gone from every stage, or value 1 is over-counted.
  const uint64_t dark = static_cast<uint64_t>(std::count(inside.begin(), inside.end(), 1));
  ASSERT_GT(dark, 0u);
  ASSERT_LT(dark, 42u);
  EXPECT_EQ(value_counts(r)[1], dark);
  EXPECT_EQ(value_counts(r)[0], 42u - dark);
  EXPECT_LT(r.curds[0].stages[d.lattice.stages].count(),
            f.curds[0].stages[d.lattice.stages].count());
}

}  // namespace curdle
