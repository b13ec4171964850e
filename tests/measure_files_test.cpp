// Tests of measure_files.h: measure.json says what was measured, and the plot is a picture.
#include "export/report/measure_files.h"

#include <gtest/gtest.h>

#include "curdle/measure.h"

namespace curdle {
namespace {

TEST(MeasureFiles, TheJsonAndThePlotOfAMeasuredPicture) {
  EXPECT_EQ(level_colour(0), "#000000");
  EXPECT_EQ(level_colour(1), "#ffffff");
  EXPECT_NE(series_colour(0), series_colour(1));
  ValueGrid grid{16, 16, std::vector<uint16_t>(256, 0)};
  for (int64_t y = 0; y < 16; ++y)
    for (int64_t x = 0; x < 16; ++x)
      grid.values[static_cast<size_t>(y * 16 + x)] = (x + y) % 3 == 0;
  MeasuredPicture picture{"diagonals.png", measure(grid, 2, 2), {1.0, 0.0}};
  const auto j = measure_to_json(picture);
  EXPECT_EQ(j["source"], "diagonals.png");
  ASSERT_TRUE(j.contains("values"));
  EXPECT_EQ(j["values"].size(), 2u);
  const PreviewImage plot = plot_box_counts(picture);
  EXPECT_GT(plot.width, 100);
  EXPECT_EQ(plot.rgb.size(), static_cast<size_t>(plot.width) * plot.height * 3);
}

}  // namespace
}  // namespace curdle
