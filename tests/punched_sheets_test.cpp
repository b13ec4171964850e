// A flat screen's sheets as layout.ifc punches them: each opening's ring a hole in the part of
// the sheet that holds it, a merged opening's island of metal a part of its own, and nothing of
// another sheet's.
#include "export/ifc/punched_sheets.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "layout/zone.h"

namespace curdle {
namespace {

Ring square(double x, double y, double side, bool clockwise = false) {
  Ring r{{x, y}, {x + side, y}, {x + side, y + side}, {x, y + side}};
  if (clockwise) std::reverse(r.begin(), r.end());
  return r;
}

Element opening(int sheet) {
  Element e;
  e.form = ElementForm::opening;
  e.sheet = sheet;
  return e;
}

// Two sheets side by side: a round opening in the first, a merged one with an island in the
// second, a piece and an opening in no sheet that neither takes.
Layout two_sheets() {
  Layout l;
  l.chord_tolerance = 0.05;
  l.fabrication = SheetFabrication{};
  l.fabrication->sheets.resize(2);
  l.fabrication->sheets[0].area = Rect{0, 0, 500, 500};
  l.fabrication->sheets[1].area = Rect{500, 0, 500, 500};
  Element round = opening(0);
  round.circle = Circle{100, 100, 20};
  Element merged = opening(1);
  merged.outline = Outline{{square(600, 100, 60), square(620, 120, 20, true)}, 3200};
  Element stray = opening(-1);
  stray.circle = Circle{300, 300, 20};
  Element piece;
  piece.circle = Circle{200, 200, 20};
  l.elements = {round, merged, stray, piece};
  return l;
}

TEST(PunchedSheets, EachOpeningIsAHoleInItsSheetAndAnIslandAPartOfItsOwn) {
  const Layout l = two_sheets();
  const std::vector<std::vector<Outline>> punched = punched_sheets(l);
  ASSERT_EQ(punched.size(), 2u);
  ASSERT_EQ(punched[0].size(), 1u);
  ASSERT_EQ(punched[0][0].rings.size(), 2u);  // the sheet, and the round opening only
  EXPECT_EQ(punched[0][0].rings[0], rect_polygon(l.sheets()[0].area));
  EXPECT_EQ(punched[0][0].rings[1], opening_rings(l.elements[0], l.chord_tolerance)[0]);
  ASSERT_EQ(punched[1].size(), 2u);  // the sheet with the merged opening, and its island
  ASSERT_EQ(punched[1][0].rings.size(), 2u);
  EXPECT_EQ(punched[1][0].rings[1], square(600, 100, 60));
  EXPECT_EQ(punched[1][1].rings, std::vector<Ring>{square(620, 120, 20, true)});
}

TEST(PunchedSheets, ARoundOpeningIsItsPolygonAndAMergedOneItsOuterRings) {
  const Layout l = two_sheets();
  const std::vector<Ring> round = opening_rings(l.elements[0], 0.05);
  ASSERT_EQ(round.size(), 1u);
  EXPECT_GE(round[0].size(), 16u);
  for (const auto& [x, y] : round[0]) EXPECT_NEAR(std::hypot(x - 100, y - 100), 10, 0.05 + 1e-9);
  EXPECT_EQ(opening_rings(l.elements[1], 0.05), std::vector<Ring>{square(600, 100, 60)});
  EXPECT_TRUE(opening_rings(Element{}, 0.05).empty());
}

// A sheet cut by the surface's outline is punched part by part: a hole goes into the part that
// holds it.
TEST(PunchedSheets, ASheetInPartsTakesEachHoleInThePartThatHoldsIt) {
  Layout l = two_sheets();
  l.fabrication->sheets[0].outline = {square(0, 0, 200), square(300, 0, 200)};
  l.elements[0].circle = Circle{400, 100, 20};
  const std::vector<std::vector<Outline>> punched = punched_sheets(l);
  ASSERT_EQ(punched[0].size(), 2u);
  EXPECT_EQ(punched[0][0].rings.size(), 1u);
  EXPECT_EQ(punched[0][1].rings.size(), 2u);
}

}  // namespace
}  // namespace curdle
