// Tests of piece.h: one reading of a piece's geometry — its bounds, whether it is a rectangle,
// its outline when it is not, its material and colour, and where rows and columns lie.
#include "layout/piece.h"

#include <gtest/gtest.h>

#include "layout_support.h"

namespace curdle {
namespace {

TEST(Piece, BoundsOutlinesMaterialsAndExtentsOfPiecesAsLaid) {
  Element whole;
  whole.shape = {Rect{0, 0, 300, 200}};
  EXPECT_EQ(laid_bounds(whole), (Rect{0, 0, 300, 200}));
  EXPECT_TRUE(is_rectangle(whole));
  EXPECT_TRUE(piece_outlines(whole).empty());
  Element l_shape;  // a panel cut at a window's corner
  l_shape.shape = {Rect{0, 0, 300, 100}, Rect{0, 100, 100, 100}};
  EXPECT_EQ(laid_bounds(l_shape), (Rect{0, 0, 300, 200}));
  EXPECT_FALSE(is_rectangle(l_shape));
  const std::vector<Outline> outline = piece_outlines(l_shape);
  ASSERT_EQ(outline.size(), 1u);
  EXPECT_NEAR(outline[0].area, 300 * 100 + 100 * 100, 1e-9);
  Element round;
  round.circle = Circle{50, 60, 20};
  EXPECT_EQ(laid_bounds(round), (Rect{40, 50, 20, 20}));
  EXPECT_FALSE(is_rectangle(round));

  Design d = test::design(2, 2, {{"3/4", "2/3"}});
  LayoutSpec spec = test::layout_spec("paving");
  spec.size = std::array<double, 2>{1500, 900};
  spec.materials = {"Limestone", "Basalt"};
  const Layout layout = lay_floor(d, spec, 3);
  for (const Element& e : layout.elements) {
    EXPECT_EQ(piece_material(layout, e), e.value ? "Basalt" : "Limestone");
    EXPECT_EQ(piece_colour(layout, e), layout.legend[e.value].colour);
    ASSERT_EQ(keep_stripes(layout, e).size(), 1u);  // mix: the piece in its value's colour
  }
  const LayingExtents extents = laying_extents(layout);
  ASSERT_EQ(extents.rows.size(), 3u);
  EXPECT_NEAR(extents.rows.at(0).first, 0, 1e-9);
  EXPECT_NEAR(extents.rows.at(2).second, 900, 1e-9);
  ASSERT_EQ(extents.columns.size(), 5u);
  EXPECT_NEAR(extents.columns.at(4).second, 1500, 1e-9);
}

// Two curds' trees of one type are ordered by their species (quantities.csv, the keys and the
// DXF layers read piece_material), and a tree's pit is centred on it.
TEST(Piece, ATreeIsOrderedByItsSpeciesAndItsPitIsCentredOnIt) {
  const Design d = test::design(4, 2, {{"3/4", "1/2"}, {"1/2", "1/2"}, {"3/4", "2/3"}});
  LayoutSpec spec = test::trees_and_benches();
  spec.own<ParkKeys>().elements[1] = spec.own<ParkKeys>().elements[0];  // a second tree
  spec.own<ParkKeys>().elements[0].order = {"Acer campestre", {}, 0, {900, 900}};
  spec.own<ParkKeys>().elements[1].order = {"Tilia cordata", {}, 0, {0, 0}};
  spec.own<ParkKeys>().elements[1].type = "tree";
  const Layout layout = make_layout(d, curdle(d, 4, d.field), d.field, spec);
  std::map<std::string, size_t> by_species;
  for (const Element& e : layout.elements) {
    if (!e.stands) continue;
    ++by_species[piece_material(layout, e)];
    const std::optional<Rect> pit = tree_pit(layout, e);
    EXPECT_EQ(pit.has_value(), piece_material(layout, e) == "Acer campestre");
    if (pit) {
      EXPECT_EQ(*pit, centred_on(e.circle->cx, e.circle->cy, 900, 900));
    }
  }
  EXPECT_EQ(by_species.size(), 2u);
  EXPECT_GT(by_species["Acer campestre"], 0u);
  EXPECT_GT(by_species["Tilia cordata"], 0u);
}

}  // namespace
}  // namespace curdle
