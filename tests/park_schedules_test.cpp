// Tests of park_schedules.h: every tree in planting.csv, every bench in furniture.csv, each at
// the centre schedule.csv and the drawing give it, and the surfaces' areas per material and zone
// adding up to the schedule's.
#include "export/schedules/park_schedules.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>
#include <tuple>

#include "export_support.h"
#include "kinds/park.h"
#include "layout/piece.h"
#include "layout/piece_rows.h"
#include "layout/zone.h"
#include "layout_support.h"

namespace curdle {
namespace {

using Rows = std::vector<std::vector<std::string>>;

// planting.csv, furniture.csv and surfaces.csv of `layout`, each as strict CSV rows.
std::tuple<Rows, Rows, Rows> park_csvs(const Layout& layout) {
  std::ostringstream planting, furniture, surfaces;
  write_planting_csv(planting, layout);
  write_furniture_csv(furniture, layout);
  write_surfaces_csv(surfaces, layout);
  return {strict_csv(planting.str().substr(3)), strict_csv(furniture.str().substr(3)),
          strict_csv(surfaces.str().substr(3))};
}

TEST(ParkSchedules, PlantsFurnitureAndSurfacesInLandscapeTerms) {
  const Design d = test::design(4, 2, {{"3/4", "1/2"}, {"1/2", "1/2"}, {"3/4", "2/3"}});
  LayoutSpec spec = test::trees_and_benches("Tilia cordata");
  Zone lawn;
  lawn.name = "lawn";
  lawn.rule = ZoneRule::value;
  lawn.value = 1;  // trees only
  lawn.polygon = rect_polygon(Rect{0, 0, 12000, 6000});
  spec.zones = {lawn};
  spec.size = std::array<double, 2>{24000, 18000};
  const Layout layout = lay_floor(d, spec, 4);
  const auto [plants, items, areas] = park_csvs(layout);
  size_t trees = 0, benches = 0;
  double ground = 0;
  for (const Element& e : layout.elements) {
    trees += e.stands && e.circle;
    benches += e.stands && !e.circle;
    if (!e.stands) ground += std::round(e.area());
  }
  ASSERT_GT(trees, 0u);
  ASSERT_GT(benches, 0u);
  ASSERT_EQ(plants.size(), trees + 1);
  ASSERT_EQ(items.size(), benches + 1);
  EXPECT_EQ(plants[0], (std::vector<std::string>{"element_id", "plant", "species", "centre_x_mm",
                                                 "centre_y_mm", "canopy_diameter_mm", "girth_cm",
                                                 "root_ball_mm", "pit_width_mm", "pit_length_mm",
                                                 "value", "zone"}));
  std::map<std::string, const Element*> by_id;
  for (const Element& e : layout.elements) by_id[e.id] = &e;
  size_t in_lawn = 0;
  for (size_t r = 1; r < plants.size(); ++r) {
    const Element& e = *by_id.at(plants[r][0]);
    EXPECT_EQ(plants[r][1], "Tilia cordata");
    EXPECT_EQ(plants[r][2], "");  // no species given: the type says it
    EXPECT_NEAR(std::stod(plants[r][3]), e.circle->cx, 1e-3);
    EXPECT_NEAR(std::stod(plants[r][4]), e.circle->cy, 1e-3);
    EXPECT_EQ(plants[r][5], "1000");
    in_lawn += plants[r][11] == "lawn";
    EXPECT_EQ(plants[r][11] == "lawn", e.circle->cx < 12000 && e.circle->cy < 6000) << e.id;
  }
  EXPECT_GT(in_lawn, 0u);
  for (size_t r = 1; r < items.size(); ++r) {
    const Element& e = *by_id.at(items[r][0]);
    EXPECT_EQ(items[r][1], "bench");
    EXPECT_EQ(std::stod(items[r][5]) * std::stod(items[r][6]), e.area());
    // 1000 x 450, turned to face its path: the long side square to the way it faces.
    const int facing = std::stoi(items[r][8]);
    EXPECT_TRUE(facing % 90 == 0 && facing >= 0 && facing < 360) << items[r][8];
    EXPECT_EQ(items[r][7], facing % 180 == 0 ? "0" : "90") << e.id;
    EXPECT_EQ(facing, static_cast<int>(e.turn));
  }
  double listed = 0;
  for (size_t r = 1; r < areas.size(); ++r) listed += std::stod(areas[r][2]) * 1e6;
  EXPECT_NEAR(listed, ground, 1e-3);  // to the mm², as schedule.csv's rows
}

// surfaces.csv books a piece to the zone holding most of its area, or to none: pieces cut round
// an excluded pond lie in none of it, however the centre of their box falls.
TEST(ParkSchedules, SurfacesAreBookedToTheZoneTheyLieInByArea) {
  const Design d = test::design(4, 2, {{"3/4", "1/2"}, {"1/2", "1/2"}, {"3/4", "2/3"}});
  LayoutSpec spec = test::trees_and_benches();
  Zone play;
  play.name = "play";
  play.rule = ZoneRule::value;
  play.value = 4;  // grey paving only
  const Rect area{5000, 1000, 5000, 6000};
  play.polygon = rect_polygon(area);
  Zone pond;  // an octagon inside one module: its piece is laid round it, a hole in it
  pond.name = "pond";
  for (int i = 0; i < 8; ++i) {
    const double a = (i + 0.5) * 3.14159265358979323846 / 4;
    pond.polygon.push_back({10500 + 800 * std::cos(a), 10500 + 800 * std::sin(a)});
  }
  spec.zones = {play, pond};
  spec.size = std::array<double, 2>{24000, 18000};
  const Layout layout = lay_floor(d, spec, 4);
  const auto [plants, items, areas] = park_csvs(layout);
  double booked_play = 0, want_play = 0;
  size_t cut_round_pond = 0;
  for (size_t r = 1; r < areas.size(); ++r) {
    EXPECT_NE(areas[r][1], "pond") << areas[r][0] << " " << areas[r][2];
    if (areas[r][1] == "play") booked_play += std::stod(areas[r][2]) * 1e6;
  }
  for (const Element& e : layout.elements) {
    if (e.stands) continue;
    const Rect b = laid_bounds(e);
    if (!e.cut && intersection(b, area) > e.area() / 2) want_play += std::round(e.area());
    cut_round_pond += e.cut && contains(pond.polygon, b.x + b.w / 2, b.y + b.h / 2);
  }
  EXPECT_GT(cut_round_pond, 0u);  // the case the centre of a box got wrong
  EXPECT_GT(want_play, 0);
  EXPECT_NEAR(booked_play, want_play, 1e-3);
}

// The landscape contractor's columns: the species, girth, root ball and pit the recipe gives,
// each bench's bearing, and edging per material that adds up to the edges between materials
// and round the site.
TEST(ParkSchedules, SpeciesSizesPitsBearingsAndEdging) {
  const Design d = test::design(4, 2, {{"3/4", "1/2"}, {"1/2", "1/2"}, {"3/4", "2/3"}});
  LayoutSpec spec = test::trees_and_benches("tree");
  ParkKeys& park = spec.own<ParkKeys>();
  park.elements[0].order = {"Acer campestre 'Elsrijk'", {16, 18}, 500, {1200, 1400}};
  park.elements[1].w = 450, park.elements[1].h = 1000;  // a bench turned along y
  park.elements[1].order = {"Oak slats", {0, 0}, 0, {0, 0}};
  spec.size = std::array<double, 2>{24000, 18000};
  const Layout layout = lay_floor(d, spec, 4);
  const auto [plants, items, areas] = park_csvs(layout);
  ASSERT_GT(plants.size(), 1u);
  ASSERT_GT(items.size(), 1u);
  for (size_t r = 1; r < plants.size(); ++r)
    EXPECT_EQ((std::vector<std::string>(plants[r].begin() + 1, plants[r].begin() + 3)),
              (std::vector<std::string>{"tree", "Acer campestre 'Elsrijk'"}));
  for (size_t r = 1; r < plants.size(); ++r)
    EXPECT_EQ((std::vector<std::string>(plants[r].begin() + 6, plants[r].begin() + 10)),
              (std::vector<std::string>{"16-18", "500", "1200", "1400"}));
  for (size_t r = 1; r < items.size(); ++r) {
    EXPECT_EQ(items[r][2], "Oak slats");
    // Its front (the 450 mm side) faces its path: the 1000 mm side runs along the facing.
    EXPECT_EQ(items[r][7], std::stoi(items[r][8]) % 180 == 0 ? "90" : "0") << items[r][0];
  }
  // Every surface piece is a rectangle of the park's grid: each one's edge to another
  // material or the site's edge, summed by brute force, is what surfaces.csv lists.
  ASSERT_EQ(areas[0].back(), "edging_m");
  double listed = 0, brute = 0;
  for (size_t r = 1; r < areas.size(); ++r) listed += std::stod(areas[r][5]) * 1e3;
  std::vector<const Element*> ground;
  for (const Element& e : layout.elements)
    if (!e.stands) ground.push_back(&e);
  for (const Element* a : ground)
    for (const Rect& ra : a->shape) {
      double shared = 0;
      for (const Element* b : ground)
        if (piece_material(layout, *a) == piece_material(layout, *b))
          for (const Rect& rb : b->shape) {
            if (&ra == &rb) continue;
            const double along_x =
                std::max(0.0, std::min(ra.right(), rb.right()) - std::max(ra.x, rb.x));
            const double along_y =
                std::max(0.0, std::min(ra.top(), rb.top()) - std::max(ra.y, rb.y));
            if (std::abs(ra.top() - rb.y) < 1e-6 || std::abs(rb.top() - ra.y) < 1e-6)
              shared += along_x;
            if (std::abs(ra.right() - rb.x) < 1e-6 || std::abs(rb.right() - ra.x) < 1e-6)
              shared += along_y;
          }
      brute += 2 * (ra.w + ra.h) - shared;
    }
  EXPECT_GT(listed, 2 * (24000 + 18000) - 1e-3);  // at least round the site
  EXPECT_NEAR(listed, brute, 1.0);                // 3 decimals of a metre per line
}

}  // namespace
}  // namespace curdle
