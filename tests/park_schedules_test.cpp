// Tests of park_schedules.h: every tree in planting.csv, every bench in furniture.csv, each at
// the centre schedule.csv and the drawing give it, and the surfaces' areas per material and zone
// adding up to the schedule's.
#include "export/park_schedules.h"

#include <gtest/gtest.h>

#include <map>
#include <sstream>

#include "export/schedule.h"
#include "export_support.h"
#include "kinds/park.h"
#include "layout/zone.h"
#include "layout_support.h"

namespace curdle {
namespace {

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
  std::ostringstream planting, furniture, surfaces;
  write_planting_csv(planting, layout);
  write_furniture_csv(furniture, layout);
  write_surfaces_csv(surfaces, layout);
  const auto plants = strict_csv(planting.str().substr(3));
  const auto items = strict_csv(furniture.str().substr(3));
  const auto areas = strict_csv(surfaces.str().substr(3));
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
  EXPECT_EQ(plants[0], (std::vector<std::string>{"element_id", "plant", "x_mm", "y_mm",
                                                 "canopy_diameter_mm", "value", "zone"}));
  std::map<std::string, const Element*> by_id;
  for (const Element& e : layout.elements) by_id[e.id] = &e;
  size_t in_lawn = 0;
  for (size_t r = 1; r < plants.size(); ++r) {
    const Element& e = *by_id.at(plants[r][0]);
    EXPECT_EQ(plants[r][1], "Tilia cordata");
    EXPECT_NEAR(std::stod(plants[r][2]), e.circle->cx, 1e-3);
    EXPECT_NEAR(std::stod(plants[r][3]), e.circle->cy, 1e-3);
    EXPECT_EQ(plants[r][4], "1000");
    in_lawn += plants[r][6] == "lawn";
    EXPECT_EQ(plants[r][6] == "lawn", e.circle->cx < 12000 && e.circle->cy < 6000) << e.id;
  }
  EXPECT_GT(in_lawn, 0u);
  for (size_t r = 1; r < items.size(); ++r) {
    const Element& e = *by_id.at(items[r][0]);
    EXPECT_EQ(items[r][1], "bench");
    EXPECT_EQ(std::stod(items[r][4]) * std::stod(items[r][5]), e.area());
  }
  double listed = 0;
  for (size_t r = 1; r < areas.size(); ++r) listed += std::stod(areas[r][2]) * 1e6;
  EXPECT_NEAR(listed, ground, 1e-3);  // to the mm², as schedule.csv's rows
}

}  // namespace
}  // namespace curdle
