// Tests of picture_cells.h: a preview is read back as its cells, curds told apart by colour.
#include "app/picture_cells.h"

#include <gtest/gtest.h>

#include "curdle/curdling.h"
#include "curdle/error.h"
#include "curdle/overlay.h"
#include "export/report/preview_png.h"
#include "picture_support.h"

namespace curdle::app {
namespace {

// Two curds whose colours (red, blue) and their purple blend share a luminance band.
Design two_curds() {
  Design d;
  d.lattice = Lattice{4, 2, 2, Mode::canonical};
  for (const char* name : {"red", "blue"}) {
    CurdSpec c;
    c.name = name;
    c.probabilities = {*Probability::parse("3/4"), *Probability::parse("2/3")};
    d.curds.push_back(c);
  }
  d.curds[0].colour = Rgb{192, 57, 43};
  d.curds[1].colour = Rgb{46, 94, 170};
  d.field = Box{{0, 0, 0}, {32, 16, 1}};
  return d;
}

TEST(PictureCells, APreviewIsReadBackAsItsCellsAndItsCurdsByColour) {
  const Design d = two_curds();
  const CurdField field = curdle(d, 9, d.field);
  const auto dir = test::scratch("picture-cells");
  const auto path =
      test::write_file(dir / "preview.png", encode_png(render_preview(d, field, d.field)));
  const PictureCells cells = picture_cells(read_luminance(path, "png"), 2, 0);
  EXPECT_GT(cells.pixels_per_cell, 1);
  EXPECT_EQ(cells.width, 32);
  EXPECT_EQ(cells.height, 16);
  EXPECT_TRUE(cells.by_colour);
  // Values match the engine's, up to which curd is called first (the picture cannot say).
  const std::vector<uint16_t> truth = values_in(field, d.field);  // rows from the bottom
  int same = 0, swapped = 0;
  for (int64_t y = 0; y < 16; ++y)
    for (int64_t x = 0; x < 32; ++x) {
      const uint16_t got = cells.values[static_cast<size_t>((15 - y) * 32 + x)];
      const uint16_t want = truth[static_cast<size_t>(y * 32 + x)];
      same += got == want;
      swapped += got == ((want & 1) << 1 | (want >> 1));
    }
  EXPECT_TRUE(same == 512 || swapped == 512) << same << " " << swapped;
  // Told apart by luminance, red, blue and purple would merge: they are within 30 greys.
  std::filesystem::remove_all(dir);
}

TEST(PictureCells, APixelACellUnlessNamedAndNamedSizesMustDivide) {
  LuminanceImage image;
  image.width = 6, image.height = 4;
  for (int i = 0; i < 24; ++i) image.luminance.push_back(i % 5 == 0 ? 0.f : 1.f);
  EXPECT_EQ(picture_cells(image, 1, 0).pixels_per_cell, 1);
  EXPECT_EQ(picture_cells(image, 1, 2).width, 3);
  EXPECT_THROW(picture_cells(image, 1, 4), InputError);  // 6 is not whole cells of 4
}

}  // namespace
}  // namespace curdle::app
