// Tests of palette.h: value colours blend the curds present, colours read and write as
// #rrggbb.
#include "curdle/palette.h"

#include <gtest/gtest.h>

namespace curdle {
namespace {

TEST(Palette, ValuesBlendTheirCurdsAndColoursReadBack) {
  std::vector<CurdSpec> curds(2);
  curds[0].colour = Rgb{200, 0, 0};
  curds[1].colour = Rgb{0, 0, 200};
  const std::vector<Rgb> v = value_colours(curds);
  ASSERT_EQ(v.size(), 4u);
  EXPECT_EQ(v[1], (Rgb{200, 0, 0}));
  EXPECT_EQ(v[2], (Rgb{0, 0, 200}));
  EXPECT_EQ(v[3], (Rgb{100, 0, 100}));  // red and blue give purple
  EXPECT_EQ(curd_colour(curds, 1), (Rgb{0, 0, 200}));
  EXPECT_EQ(hex_colour(Rgb{255, 16, 1}), "#ff1001");
  EXPECT_EQ(parse_hex_colour("#FF1001"), (Rgb{255, 16, 1}));
  for (const char* bad : {"ff1001", "#ff100", "#ff10011", "#gg0000", ""})
    EXPECT_FALSE(parse_hex_colour(bad)) << bad;
  // Curds without a colour take distinct defaults.
  const std::vector<CurdSpec> plain(3);
  EXPECT_NE(curd_colour(plain, 0), curd_colour(plain, 1));
  EXPECT_NE(curd_colour(plain, 1), curd_colour(plain, 2));
}

}  // namespace
}  // namespace curdle
