// Piece rows: every piece's row names it as the layout does and holds its box, area and shape.
#include "layout/piece_rows.h"

#include <gtest/gtest.h>

#include "curdle/curdling.h"
#include "layout/builder.h"
#include "layout/piece.h"
#include "test_support.h"

namespace curdle {
namespace {

Layout paving_with_cut_edges() {
  Design d = test::design(4, 2, {{"3/4", "1/2", "1/2"}, {"1/2", "1/2", "1/2"}});
  LayoutSpec spec = test::layout_spec();
  spec.set_kind(layout_kind("paving"));
  spec.module_w = spec.module_h = 400, spec.joint = 5;
  spec.size = std::array<double, 2>{12000, 8100};  // the last row is cut
  spec.ordering.lot_rows = 5;
  const auto cells = elements_to_cover(spec);
  d.field.size = {cells[0], cells[1], 1};
  const CurdField f = curdle(d, 4, d.field);
  return make_layout(d, f, d.field, spec);
}

TEST(PieceRows, EveryRowIsItsPieceAsLaid) {
  const Layout layout = paving_with_cut_edges();
  ASSERT_FALSE(layout.elements.empty());
  size_t cut = 0;
  for (size_t i = 0; i < layout.elements.size(); ++i) {
    const Element& e = layout.elements[i];
    const ScheduleRow r = schedule_row(layout, i);
    EXPECT_EQ(r.id, e.id);
    EXPECT_EQ(r.value, e.value);
    EXPECT_EQ(r.cut, e.cut);
    EXPECT_DOUBLE_EQ(r.area, e.area());
    const Rect b = laid_bounds(e);
    EXPECT_DOUBLE_EQ(r.width, b.w);
    EXPECT_DOUBLE_EQ(r.height, b.h);
    ASSERT_FALSE(r.outlines.empty()) << "every piece has a shape";
    EXPECT_NEAR(r.outlines.front().area, e.area(), 1e-6 * e.area());
    EXPECT_EQ(r.lot, lot_text(layout, e, i));
    EXPECT_EQ(r.element_type, element_type_of(layout, e));
    EXPECT_EQ(r.colour.size(), 7u);
    cut += r.cut;
  }
  EXPECT_GT(cut, 0u) << "the last row is cut to the edge";
}

TEST(PieceRows, LotsCountFromOneInLayingOrder) {
  OrderingKeys by_rows;
  by_rows.lot_rows = 5;
  Element e;
  e.row = 0;
  EXPECT_EQ(lot_of(e, 0, by_rows), 1);
  e.row = 4;
  EXPECT_EQ(lot_of(e, 0, by_rows), 1);
  e.row = 5;
  EXPECT_EQ(lot_of(e, 0, by_rows), 2);
  OrderingKeys by_count;
  by_count.lot_size = 100;
  EXPECT_EQ(lot_of(e, 99, by_count), 1);
  EXPECT_EQ(lot_of(e, 100, by_count), 2);
  EXPECT_EQ(lot_of(e, 100, OrderingKeys{}), 1) << "one lot when none is asked for";
}

TEST(PieceRows, AreaInSquareMetresIsToTheSquareMillimetre) {
  EXPECT_DOUBLE_EQ(area_m2(160000.4), 0.16);
  EXPECT_DOUBLE_EQ(area_m2(160000.6), 0.160001);
}

}  // namespace
}  // namespace curdle
