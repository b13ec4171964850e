// A perforated sheet drawn as tiles: which openings become shared tiles, and the tile's shape.
#include "layout/sheet_tiles.h"

#include <gtest/gtest.h>

#include <cmath>

namespace curdle {
namespace {

double signed_area(const Ring& r) {
  double a = 0;
  for (size_t i = 0; i < r.size(); ++i) {
    const auto& p = r[i];
    const auto& q = r[(i + 1) % r.size()];
    a += p[0] * q[1] - q[0] * p[1];
  }
  return a / 2;
}

TEST(SheetTiles, ATileIsItsSquareLessItsHoleAndTouchesEachSideAtItsMiddle) {
  for (const double d : {6.0, 14.0, 32.0, 250.0}) {
    const double tolerance = 0.05;
    const OpeningTile tile = opening_tile(d, tolerance);
    ASSERT_EQ(tile.hole.size() % 4, 0u);
    EXPECT_LT(signed_area(tile.hole), 0) << "the hole runs clockwise";
    double face = 0;
    for (const auto& t : tile.triangles) {
      const double a = signed_area({t[0], t[1], t[2]});
      EXPECT_GT(a, 0) << "counter-clockwise";
      face += a;
    }
    EXPECT_NEAR(face - signed_area(tile.hole), d * d, 1e-9 * d * d) << "square = face + hole";
    const double r = d / 2;
    for (const auto& v : tile.hole) {
      const double from_centre = std::hypot(v[0], v[1]);
      EXPECT_NEAR(from_centre, r, 1e-9);
      EXPECT_LE(std::fabs(v[0]), r);
      EXPECT_LE(std::fabs(v[1]), r);
    }
    // Chords no further than the tolerance inside the circle.
    const double chord =
        std::hypot(tile.hole[0][0] - tile.hole[1][0], tile.hole[0][1] - tile.hole[1][1]);
    EXPECT_LE(r - std::sqrt(r * r - chord * chord / 4), tolerance + 1e-12) << d;
    size_t touching = 0;
    for (const auto& v : tile.hole)
      touching += (v[0] == r && v[1] == 0) || (v[0] == -r && v[1] == 0) ||
                  (v[0] == 0 && v[1] == r) || (v[0] == 0 && v[1] == -r);
    EXPECT_EQ(touching, 4u) << d;
  }
}

Element round_opening(double cx, double cy, double d) {
  Element e;
  e.circle = Circle{cx, cy, d};
  return e;
}

TEST(SheetTiles, OpeningsClearOfEachOtherAndOfEdgesAreTilesTheRestStayHoles) {
  Layout layout;
  layout.width = 1000;
  layout.height = 500;
  layout.elements.push_back(round_opening(100, 100, 20));  // 0: alone: a tile
  layout.elements.push_back(round_opening(300, 100, 20));  // 1, 2: squares overlap
  layout.elements.push_back(round_opening(318, 118, 20));  //       though the circles do not
  layout.elements.push_back(round_opening(995, 250, 20));  // 3: crosses the sheet's edge
  Element merged;
  merged.outline = Outline{{{{500, 200}, {560, 200}, {560, 260}, {500, 260}}}, 3600};
  layout.elements.push_back(merged);                       // 4: a merged opening
  layout.elements.push_back(round_opening(550, 270, 20));  // 5: its square meets the merged one
  layout.elements.push_back(round_opening(700, 400, 30));  // 6: alone: a tile
  const std::vector<Ring> sheet{{{0, 0}, {1000, 0}, {1000, 500}, {0, 500}}};
  const SheetTiles tiles = sheet_tiles(layout, sheet);
  EXPECT_EQ(tiles.tiled, (std::vector<size_t>{0, 6}));
  ASSERT_EQ(tiles.squares.size(), 2u);
  for (const Ring& s : tiles.squares) EXPECT_LT(signed_area(s), 0);
  EXPECT_NEAR(-signed_area(tiles.squares[0]) - signed_area(tiles.squares[1]), 400 + 900, 1e-9);
  // Holes: the merged outline and openings 1, 2, 3 and 5, each clockwise.
  ASSERT_EQ(tiles.holes.size(), 5u);
  for (const Ring& h : tiles.holes) EXPECT_LT(signed_area(h), 0);
}

TEST(SheetTiles, AMergedOpeningClearOfTheRestIsATileOfItsBoxLessItsRing) {
  Layout layout;
  layout.width = 1000;
  layout.height = 500;
  Element merged;  // a diamond with a notch: it meets its box at four points
  const Ring ring{{530, 200}, {560, 230}, {530, 260}, {500, 230}, {520, 230}};
  merged.outline = Outline{{ring}, 1500};
  layout.elements.push_back(merged);                       // 0: alone: a tile of its box
  layout.elements.push_back(round_opening(100, 100, 20));  // 1: alone: a round tile
  Element touching = merged;
  for (auto& [x, y] : touching.outline->rings[0]) x += 200;
  layout.elements.push_back(touching);                     // 2: its box meets 3's square
  layout.elements.push_back(round_opening(770, 270, 20));  // 3
  Element along;  // 4: an L along two sides of its least box: a tile of its grown box
  along.outline =
      Outline{{{{300, 300}, {360, 300}, {360, 330}, {330, 330}, {330, 360}, {300, 360}}}, 2700};
  layout.elements.push_back(along);
  const std::vector<Ring> sheet{{{0, 0}, {1000, 0}, {1000, 500}, {0, 500}}};
  const SheetTiles tiles = sheet_tiles(layout, sheet);
  EXPECT_EQ(tiles.tiled, (std::vector<size_t>{0, 1, 4}));
  ASSERT_EQ(tiles.holes.size(), 2u);  // the second merged opening and the round one by it
  for (const Ring& h : tiles.holes) EXPECT_LT(signed_area(h), 0);
  double squares = 0;
  for (const Ring& s : tiles.squares) squares -= signed_area(s);
  // The merged openings' boxes, each grown by kTileMargin a side, and the round one's square.
  const double grown = 60 + 2 * kTileMargin;
  EXPECT_NEAR(squares, 2 * grown * grown + 400, 1e-9);
  // The tile: from its box's corner, the box less the ring, and the ring clockwise.
  const std::array<double, 4> box = outline_box(ring);
  EXPECT_NEAR(box[0], 500 - kTileMargin, 1e-12);
  EXPECT_NEAR(box[1], 200 - kTileMargin, 1e-12);
  EXPECT_NEAR(box[2], 560 + kTileMargin, 1e-12);
  EXPECT_NEAR(box[3], 260 + kTileMargin, 1e-12);
  const OpeningTile tile = outline_tile(ring);
  double face = 0;
  for (const auto& t : tile.triangles) {
    const double a = signed_area(Ring{t[0], t[1], t[2]});
    EXPECT_GT(a, 0);
    face += a;
  }
  EXPECT_NEAR(face, grown * grown - 1500, 1e-9);
  EXPECT_NEAR(signed_area(tile.hole), -1500, 1e-9);
  // The ring alone, as the writers tell shapes apart by it, is the tile's, either way round.
  EXPECT_EQ(outline_tile_hole(ring), tile.hole);
  EXPECT_EQ(outline_tile_hole(Ring(ring.rbegin(), ring.rend())).size(), tile.hole.size());
  EXPECT_NEAR(signed_area(outline_tile_hole(Ring(ring.rbegin(), ring.rend()))), -1500, 1e-9);
}

}  // namespace
}  // namespace curdle
