#include "curdle/cell_shapes.h"

#include <gtest/gtest.h>

namespace curdle {

TEST(CellShapes, ACropCutsCellsAtItsEndsOnly) {
  // Cells of 4 meeting [2, 15): one cut at each end and two whole ones.
  const auto spans = spans_meeting(2, 15, 4);
  EXPECT_EQ(spans.size(), 3u);
  EXPECT_EQ(spans.at({2, 4}), 1u);
  EXPECT_EQ(spans.at({0, 4}), 2u);
  EXPECT_EQ(spans.at({0, 3}), 1u);
}

TEST(CellShapes, ChildrenAndTheirProductOverAxes) {
  const auto children = child_spans({1, 4}, 4, 2);  // halves: [1, 2) cut, [0, 2) whole
  EXPECT_EQ(children.at({1, 2}), 1u);
  EXPECT_EQ(children.at({0, 2}), 1u);
  std::array<std::map<CellSpan, uint64_t>, 3> axes{children, children, {}};
  const auto both = shapes(axes, 2);
  uint64_t total = 0;
  for (const auto& [shape, n] : both) total += n;
  EXPECT_EQ(both.size(), 4u);
  EXPECT_EQ(total, 4u);
}

}  // namespace curdle
