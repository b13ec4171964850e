// Tests of envelope_layout.h: the pavilion laid from a recipe as one curd round its envelope;
// courses level all round, each corner unit one piece counted once, the layout's frames its
// façades, the corners' places on the stage grid reported; and the continuity of tone across
// every corner (the closing one too) the same as across any line of the strip at the same
// place in the stage grid, over 1,000 seeds.
#include "building/envelope_layout.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>

#include "building_support.h"
#include "curdle/overlay.h"

namespace curdle {
namespace {

TEST(EnvelopeLayout, CoursesAreLevelAndEachCornerUnitIsOnePieceCountedOnce) {
  const Layout l = test::lay_recipe(test::pavilion_recipe());
  ASSERT_EQ(l.frames.size(), 6u);
  EXPECT_TRUE(l.closed_envelope);
  EXPECT_DOUBLE_EQ(l.width, 64000);
  EXPECT_DOUBLE_EQ(l.thickness, 102.5);
  std::map<int, int> corner_units;
  uint64_t counted = 0;
  for (const Element& e : l.elements) {
    EXPECT_DOUBLE_EQ(e.nominal.y, 75.0 * static_cast<double>(e.row)) << e.id;
    for (const Rect& r : e.shape) EXPECT_DOUBLE_EQ(r.y, e.nominal.y) << e.id;
    if (e.corner >= 0) ++corner_units[e.corner];
  }
  for (const LegendEntry& v : l.legend) counted += v.count;
  EXPECT_EQ(counted, l.elements.size());
  ASSERT_EQ(corner_units.size(), 6u);
  for (const auto& [corner, n] : corner_units) EXPECT_EQ(n, 94) << "corner " << corner;
  // The closing corner's unit lies in two parts on the strip: its end and its start.
  for (const Element& e : l.elements)
    if (e.corner == 5) {
      ASSERT_EQ(e.shape.size(), 2u);
      EXPECT_DOUBLE_EQ(e.shape[0].right(), 64000);
      EXPECT_DOUBLE_EQ(e.shape[1].x, 0);
    }
  size_t placed = 0;
  for (const std::string& n : l.notes) placed += n.rfind("corner at the end of", 0) == 0;
  EXPECT_EQ(placed, 6u);
}

TEST(EnvelopeLayout, EachUnitTakesTheValueOfTheCellUnderTheMiddleOfItsFace) {
  const Recipe r = parse_recipe(test::pavilion_recipe(), "pavilion.toml");
  const Design& d = r.design;
  const CurdField field = curdle(d, r.seed, d.field);
  const std::vector<uint16_t> values = values_in(field, d.field);
  const Layout l = make_layout(d, field, d.field, *r.layout);
  for (const Element& e : l.elements) {
    const double middle = wrap_along(e.nominal.x + e.nominal.w / 2, l.width);
    const int64_t column = static_cast<int64_t>(middle / 225);
    ASSERT_EQ(e.cell_x, column) << e.id;
    ASSERT_EQ(e.cell_y, e.row) << e.id;
    ASSERT_EQ(e.value, values[static_cast<size_t>(e.row * d.field.size[0] + column)]) << e.id;
  }
}

TEST(EnvelopeLayout, OpeningsCutTheUnitsAndNoUnitLiesInOne) {
  const Layout l = test::lay_recipe(test::pavilion_recipe(R"([[layout.building.openings]]
facade = "S"
rect = [9400, 0, 1200, 2400]
type = "door"
)"));
  ASSERT_EQ(l.openings.size(), 1u);
  double laid = 0;
  for (const Element& e : l.elements)
    for (const Rect& r : e.shape) {
      EXPECT_FALSE(overlaps(r, l.openings[0])) << e.id;
      laid += r.area();
    }
  // Units and their joints cover the strip but for the door: joints are 10 of every 75 mm up
  // and of every 225 mm along (one per unit, the corners' included).
  const double faces = 64000.0 * 7050 - 1200.0 * 2400;
  EXPECT_NEAR(laid / faces, 65.0 / 75 * 215 / 225, 0.01);
}

TEST(EnvelopeLayout, AFacadeLowerThanTheWallHasNoUnitsAboveItsOwnTop) {
  // The bite's two walls one storey high, the rest two.
  const Layout l =
      test::lay_recipe(test::pavilion_recipe("heights = [7050, 7050, 3525, 3525, 7050, 7050]\n"));
  ASSERT_EQ(l.frames[2].height, 3525);
  EXPECT_EQ(l.frames[1].height, 0);  // as tall as the wall
  size_t above = 0;
  for (const Element& e : l.elements)
    for (const Rect& r : e.shape) {
      const SurfaceFrame* f = frame_at(l.frames, r.x + r.w / 2);
      if (f->height > 0) {
        EXPECT_LE(r.top(), f->height + 1e-9) << e.id;
      }
      above += f == &l.frames[1] && r.y >= 3525;
    }
  EXPECT_GT(above, 0u);  // the east wall goes on up beside the bite's roof
}

// Tone continuity across a vertical line of the strip at `u` mm: the share of courses whose
// cells either side hold the same value. Cells either side of the closing seam are the strip's
// last and first.
double continuity(const std::vector<uint16_t>& values, int64_t columns, int64_t rows, int64_t left,
                  int64_t right) {
  int64_t same = 0;
  for (int64_t r = 0; r < rows; ++r)
    same += values[static_cast<size_t>(r * columns + left)] ==
            values[static_cast<size_t>(r * columns + right)];
  return static_cast<double>(same) / static_cast<double>(rows);
}

TEST(EnvelopeLayout, ToneContinuesRoundEveryCornerAsAcrossAnyLineOverAThousandSeeds) {
  const Recipe recipe = parse_recipe(test::pavilion_recipe(), "pavilion.toml");
  const Design& d = recipe.design;
  const Layout probe = test::lay_recipe(test::pavilion_recipe());
  const int64_t columns = d.field.size[0], rows = d.field.size[1];
  const double pitch = 225;
  // Each corner's cells either side, and a line elsewhere in the strip with the same place in
  // the stage grid (the root cell is 16 cells: 32 base-2 cells of 5 stages, halved once):
  // a whole number of root cells away. The closing seam pairs the strip's last cell with its
  // first; its reference is a root-cell boundary.
  const int64_t root = 32;
  struct Line {
    int64_t left, right, ref_left, ref_right;
  };
  std::vector<Line> lines;
  for (const SurfaceFrame& f : probe.frames) {
    const int64_t cell = static_cast<int64_t>(std::floor((f.start + f.length) / pitch));
    if (&f == &probe.frames.back()) {
      lines.push_back({columns - 1, 0, 2 * root - 1, 2 * root});
      continue;
    }
    const int64_t ref = cell + (cell >= columns / 2 ? -2 : 2) * root;
    lines.push_back({cell - 1, cell, ref - 1, ref});
  }
  std::vector<double> sum(lines.size() * 2), sq(lines.size() * 2);
  const int seeds = 1000;
  for (int s = 1; s <= seeds; ++s) {
    const CurdField field = curdle(d, static_cast<uint64_t>(s), d.field);
    const std::vector<uint16_t> values = values_in(field, d.field);
    for (size_t k = 0; k < lines.size(); ++k) {
      const double a = continuity(values, columns, rows, lines[k].left, lines[k].right);
      const double b = continuity(values, columns, rows, lines[k].ref_left, lines[k].ref_right);
      sum[2 * k] += a, sq[2 * k] += a * a;
      sum[2 * k + 1] += b, sq[2 * k + 1] += b * b;
    }
  }
  for (size_t k = 0; k < lines.size(); ++k) {
    const double ma = sum[2 * k] / seeds, mb = sum[2 * k + 1] / seeds;
    const double va = sq[2 * k] / seeds - ma * ma, vb = sq[2 * k + 1] / seeds - mb * mb;
    const double se = std::sqrt((va + vb) / seeds);
    EXPECT_LT(std::fabs(ma - mb), 4 * se)
        << "corner " << k << ": " << ma << " across it, " << mb << " across its reference";
  }
}

}  // namespace
}  // namespace curdle
