#include "recipe/recipe.h"

#include <gtest/gtest.h>

#include "recipe_support.h"

namespace curdle {
TEST(Recipe, ReadsEveryKey) {
  const Recipe r = parse_recipe(kGood, "r.toml");
  EXPECT_EQ(r.design.name, "t");
  EXPECT_EQ(r.seed, 9u);
  EXPECT_EQ(r.design.lattice.base, 4);
  EXPECT_EQ(r.design.lattice.stages, 2);
  EXPECT_EQ(r.design.field.size[0], 67);
  ASSERT_EQ(r.design.curds.size(), 2u);
  EXPECT_EQ(r.design.curds[1].probabilities[0].text(), "0.75");
  EXPECT_EQ((r.design.curds[0].colour), (Rgb{0xc0, 0x39, 0x2b}));
}

TEST(Recipe, Windows) {
  const Recipe r = parse_recipe(kGood, "r.toml");
  const Box w = parse_window("3,4,10,20", r.design);
  EXPECT_EQ(w.origin[0], 3);
  EXPECT_EQ(w.size[1], 20);
  EXPECT_THROW(parse_window("60,0,10,10", r.design), InputError);
  EXPECT_THROW(parse_window("1,2,3", r.design), InputError);
  EXPECT_THROW(parse_window("a,b,c,d", r.design), InputError);
}

}  // namespace curdle
