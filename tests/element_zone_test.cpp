// Tests of element_zone.h: a standing object's zone where it stands, a laid piece's where most of
// its area lies (a piece laid round an excluded pond is in none of it).
#include "layout/element_zone.h"

#include <gtest/gtest.h>

#include "layout/zone.h"

namespace curdle {

TEST(ElementZone, StandingObjectsByTheirCentrePiecesByTheirArea) {
  Layout layout;
  ZoneCount play;
  play.name = "play";
  play.polygon = rect_polygon(Rect{0, 0, 1000, 1000});
  ZoneCount pond;
  pond.name = "pond";
  pond.polygon = rect_polygon(Rect{2400, 2400, 200, 200});
  layout.zones = {play, pond};
  Element tree;
  tree.stands = true;
  tree.circle = Circle{500, 500, 3000};  // its canopy wider than the zone: it stands in it
  EXPECT_EQ(zone_of_element(layout, tree), "play");
  Element piece;  // 600 x 300 at (700, 0): 300 x 300 of it in play, the rest out of every zone
  piece.nominal = Rect{700, 0, 600, 300};
  piece.shape = {piece.nominal};
  EXPECT_EQ(zone_of_element(layout, piece), "");
  piece.nominal = Rect{500, 0, 600, 300};  // 500 of its 600 in play
  piece.shape = {piece.nominal};
  EXPECT_EQ(zone_of_element(layout, piece), "play");
  // A piece laid round the pond: a square with the pond as its hole, its box's centre in it.
  Element round;
  round.nominal = Rect{2000, 2000, 1000, 1000};
  round.cut = true;
  round.outline = Outline{{rect_polygon(Rect{2000, 2000, 1000, 1000}),
                           {{2400, 2400}, {2400, 2600}, {2600, 2600}, {2600, 2400}}},
                          1000.0 * 1000 - 200 * 200};
  EXPECT_EQ(zone_at(layout, 2500, 2500), "pond");
  EXPECT_EQ(zone_of_element(layout, round), "");
}

}  // namespace curdle
