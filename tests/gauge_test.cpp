// Tests of gauge.h: the gauge rod of a coursed sheet gives each course's bed at its height in
// mm and the storey levels, and the chain of dimensions stops at the openings' jambs; the
// coursed sheets had their setting-out as text alone.
#include "layout/gauge.h"

#include <gtest/gtest.h>

#include "curdle/curdling.h"
#include "layout/builder.h"
#include "recipe/recipe.h"

namespace curdle {
namespace {

Layout brick_wall(const std::string& extra) {
  const Recipe r = parse_recipe(R"(name = "wall"
seed = 3
[lattice]
base = 2
dimension = 2
[[curds]]
name = "red"
probabilities = ["1", "0.8", "0.8", "0.8", "0.8", "0.8"]
[layout]
kind = "facade"
panel = [215, 65]
joint = 10
wall = [4500, 3000]
bond = "half"
openings = [[900, 750, 1125, 1500]]
)" + extra,
                                "wall.toml");
  Design d = r.design;
  return make_layout(d, curdle(d, r.seed, d.field), d.field, *r.layout);
}

TEST(Gauge, EachCoursesBedAndTheStoreyLevels) {
  const Layout wall = brick_wall("storey = 1500\n");
  const LayingExtents extents = laying_extents(wall);
  const Rect window{0, 0, 4500, 3000};
  const std::vector<GaugeMark> marks = gauge_marks(wall, extents, window);
  std::vector<double> beds;
  std::vector<std::string> levels;
  for (const GaugeMark& m : marks) (m.level ? levels.push_back(m.label) : beds.push_back(m.at));
  // 40 courses of 75 mm from the datum, and the wall's top.
  ASSERT_EQ(beds.size(), 41u);
  for (size_t k = 0; k < beds.size(); ++k) EXPECT_NEAR(beds[k], 75.0 * k, 1e-6);
  EXPECT_EQ(marks[1].label, "0");  // a level comes first, then the course's bed
  EXPECT_EQ(levels, (std::vector<std::string>{"level 0 ±0", "level 1 +1500", "level 2 +3000"}));
  // A window of part of the wall marks only its own courses.
  const std::vector<GaugeMark> part = gauge_marks(wall, extents, Rect{0, 1000, 4500, 500});
  ASSERT_FALSE(part.empty());
  EXPECT_EQ(part.front().at, 1050);
  EXPECT_EQ(part.back().at, 1500);
  EXPECT_TRUE(part[part.size() - 2].level);  // level 1, before the bed at its height
}

TEST(Gauge, TheChainStopsAtTheJambsOfTheOpeningsOnTheSheet) {
  const Layout wall = brick_wall("");
  EXPECT_EQ(dimension_stops(wall, Rect{-300, -300, 5100, 3600}),
            (std::vector<double>{0, 900, 2025, 4500}));
  EXPECT_EQ(dimension_stops(wall, Rect{1000, 0, 2000, 3000}),
            (std::vector<double>{1000, 2025, 3000}));
  EXPECT_EQ(dimension_stops(wall, Rect{0, 2400, 4500, 600}),  // above the opening's head
            (std::vector<double>{0, 4500}));
  EXPECT_TRUE(dimension_stops(wall, Rect{5000, 0, 100, 100}).empty());
}

}  // namespace
}  // namespace curdle
