// Tests of building.h: the envelope's heights in whole courses, openings placed on the strip by
// façade name or index and by a window rule, and every kind of bad building refused with a
// message that says what is allowed.
#include "building/building.h"

#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "building_support.h"
#include "curdle/error.h"
#include "kinds/registry.h"
#include "layout/contour.h"

namespace curdle {
namespace {

BuildingKeys pavilion_keys() {
  BuildingKeys keys;
  keys.plan =
      contour_of({{0, 0}, {20000, 0}, {20000, 6000}, {12000, 6000}, {12000, 12000}, {0, 12000}});
  keys.height = 7050;
  return keys;
}

std::string refusal(const BuildingKeys& keys, const LayoutSpec& spec = test::bricks()) {
  try {
    (void)envelope_of(keys, spec);
  } catch (const InputError& e) {
    return e.where().key + ": " + e.message();
  }
  return "";
}

TEST(Building, OpeningsArePlacedOnTheStripByFacadeNameOrIndex) {
  BuildingKeys keys = pavilion_keys();
  keys.openings = {{"E", Rect{900, 900, 1200, 1500}, "window"},
                   {"3", Rect{600, 0, 1000, 2100}, "door"}};
  const Envelope env = envelope_of(keys, test::bricks());
  EXPECT_DOUBLE_EQ(env.length, 64000);
  EXPECT_EQ(env.courses, 94);
  EXPECT_DOUBLE_EQ(env.depth, 102.5);
  ASSERT_EQ(env.openings.size(), 2u);
  EXPECT_DOUBLE_EQ(env.openings[0].x, 20000 + 900);
  EXPECT_DOUBLE_EQ(env.openings[1].x, 34000 + 600);  // E2, the edge from vertex 3
  EXPECT_EQ(env.opening_type[1], "door");
  // Sills and heads on course lines: 2100 is 28 courses of 75 mm exactly; 900 and 2400 too.
  EXPECT_DOUBLE_EQ(env.openings[0].y, 900);
  EXPECT_DOUBLE_EQ(env.openings[1].top(), 2100);
}

TEST(Building, ARuleSetsWindowsOnEveryFacadeAndStoreyClearOfTheCorners) {
  BuildingKeys keys = pavilion_keys();
  keys.storey = 3525;
  keys.windows = WindowRule{{1200, 1500}, 3000, 900, 900};
  const Envelope env = envelope_of(keys, test::bricks());
  // Per storey: 6 on the 20 m front, 2 on each 6 and 8 m side, 4 on each 12 m side.
  EXPECT_EQ(env.openings.size(), 2u * (6 + 2 + 2 + 2 + 4 + 4));
  for (size_t i = 0; i < env.openings.size(); ++i) {
    const SurfaceFrame& f = env.facades[env.opening_facade[i]];
    EXPECT_GE(env.openings[i].x - f.start, 900 - 1e-9);
    EXPECT_LE(env.openings[i].right() - f.start, f.length - 900 + 1e-9);
  }
}

// Doors and windows are counted apart, the listed openings first and then the rule's: the names
// the IFC and every message give them. A rule's window is left out or replaced by its name, and
// the others keep theirs, so that a name means the same window before and after.
TEST(Building, OpeningsKeepTheirNamesWhenARulesWindowIsOmittedOrReplaced) {
  BuildingKeys keys = pavilion_keys();
  keys.storey = 3525;
  keys.openings = {{"S", Rect{9400, 0, 1200, 2400}, "door"}};
  keys.windows = WindowRule{{1200, 1500}, 3000, 900, 900};
  const Envelope all = envelope_of(keys, test::bricks());
  ASSERT_EQ(all.opening_names.size(), 41u);
  EXPECT_EQ(all.opening_names[0], "D-1");
  EXPECT_EQ(all.opening_names[1], "W-1");
  EXPECT_EQ(all.opening_names[40], "W-40");

  keys.windows->omit = {"W-3"};
  keys.openings.push_back({"", Rect{6900, 0, 1200, 2400}, "door", "W-2"});
  keys.openings.push_back({"", Rect{900, 600, 1200, 1800}, "window", "W-1"});
  const Envelope changed = envelope_of(keys, test::bricks());
  ASSERT_EQ(changed.opening_names.size(), 40u);
  EXPECT_EQ(changed.opening_names[0], "D-1");
  EXPECT_EQ(changed.opening_names[1], "W-1");  // taller, in W-1's place and name
  EXPECT_DOUBLE_EQ(changed.openings[1].h, 1800);
  EXPECT_EQ(changed.opening_names[2], "D-2");  // a door where W-2 was, on its façade
  EXPECT_EQ(changed.opening_type[2], "door");
  EXPECT_EQ(changed.opening_facade[2], 0u);
  EXPECT_EQ(changed.opening_names[3], "W-4");  // W-3 left out; W-4 is still W-4
  EXPECT_DOUBLE_EQ(changed.openings[3].x, all.openings[4].x);
  EXPECT_EQ(changed.opening_names[39], "W-40");

  BuildingKeys twice = keys;
  twice.windows->omit = {"W-2"};
  EXPECT_NE(refusal(twice).find("names W-2 twice"), std::string::npos) << refusal(twice);
  BuildingKeys unknown = keys;
  unknown.windows->omit = {"W-41"};
  EXPECT_NE(refusal(unknown).find("W-41, which is not a window of the rule: it sets W-1 to W-40"),
            std::string::npos)
      << refusal(unknown);
}

TEST(Building, StoreysOfDifferentHeightsSetEachStoreysWindowsFromItsOwnFloor) {
  BuildingKeys keys = pavilion_keys();
  keys.storeys = {4200, 2850};  // a tall ground floor
  keys.windows = WindowRule{{1200, 1500}, 3000, 900, 900};
  const Envelope env = envelope_of(keys, test::bricks());
  std::set<double> sills;
  for (const Rect& o : env.openings) sills.insert(o.y);
  EXPECT_EQ(sills, (std::set<double>{900, 5100}));
  EXPECT_EQ(storey_levels(0, keys.storeys, 7050), (std::vector<double>{0, 4200, 7050}));
  EXPECT_EQ(storey_levels(3525, {}, 7050), (std::vector<double>{0, 3525, 7050}));
  EXPECT_EQ(storey_levels(0, {}, 7050), (std::vector<double>{0}));
}

TEST(Building, BadBuildingsAreRefusedSayingWhatIsAllowed) {
  BuildingKeys keys = pavilion_keys();
  keys.height = 7000;
  EXPECT_EQ(refusal(keys),
            "height: 7000 mm is not whole courses of 75 mm (a unit and its bed joint): 6975 mm "
            "(93 courses) or 7050 mm (94 courses) are");
  keys = pavilion_keys();
  keys.openings = {{"S", Rect{19500, 900, 1200, 1500}, "window"}};
  EXPECT_NE(refusal(keys).find("past its corner at 20000 mm"), std::string::npos);
  keys.openings = {{"S", Rect{900, 6000, 1200, 1500}, "window"}};
  EXPECT_NE(refusal(keys).find("above the wall's top"), std::string::npos);
  // Named as the IFC and the sheets name them: doors and windows counted apart.
  keys.openings = {{"S", Rect{900, 0, 1200, 2400}, "door"},
                   {"S", Rect{3900, 900, 1200, 1500}, "window"},
                   {"S", Rect{1500, 1200, 1200, 1500}, "window"}};
  EXPECT_NE(refusal(keys).find(
                "openings: W-2 on façade S at x 1500, sill 1200 overlaps D-1 on façade S at x 900, "
                "sill 0: openings must stand apart"),
            std::string::npos)
      << refusal(keys);
  keys.openings = {{"SE", Rect{900, 900, 1200, 1500}, "window"}};
  EXPECT_NE(refusal(keys).find("S, E, N, E2, N2, W"), std::string::npos);
  keys = pavilion_keys();
  keys.plan = contour_of({{0, 0}, {10000, 0}, {0, 10000}, {10000, 10000}});
  EXPECT_NE(refusal(keys).find("plan: crosses itself"), std::string::npos);
  keys.plan = contour_of({{0, 0}, {10000, 0}, {10000, 100}, {0, 100}});
  EXPECT_NE(refusal(keys).find("shorter than one unit"), std::string::npos);
  keys = pavilion_keys();
  keys.height = 750000;
  EXPECT_THROW((void)envelope_of(keys, test::bricks()), ResourceLimitError);
  keys = pavilion_keys();
  keys.heights = {7050, 7050, 3525};
  EXPECT_NE(refusal(keys).find("heights: gives 3 heights for 6 edges"), std::string::npos);
  keys.heights = {7050, 7050, 3500, 3525, 7050, 7050};
  EXPECT_NE(refusal(keys).find("heights: 3500 mm is not whole courses"), std::string::npos);
  keys.heights = {7050, 7125, 3525, 3525, 7050, 7050};
  EXPECT_NE(refusal(keys).find("above the wall's height of 7050 mm"), std::string::npos);
  keys = pavilion_keys();
  keys.depth = 300;
  EXPECT_NE(refusal(keys).find("depth"), std::string::npos);
}

// A curved one-brick wall's joints taper to its back, a unit's length in: a radius a leaf
// takes (its joints 5.4 mm at its back, 102.5 mm in) closes them behind a one-brick wall.
TEST(Building, AOneBrickWallsJointsAreCheckedAtItsBack) {
  BuildingKeys keys;
  keys.path = {{0, 0, std::tan(1.0 / 4)}, {2 * 5000 * std::sin(0.5), 0, 0}};  // R 5 m, 1 rad
  keys.height = 750;
  EXPECT_EQ(refusal(keys), "");
  keys.wall = "one-brick";
  EXPECT_NE(refusal(keys).find("the joints would close to 0.3 mm at the back"), std::string::npos)
      << refusal(keys);
}

TEST(Building, AFacadeIsFoundByNameOrIndex) {
  const Envelope env = envelope_of(pavilion_keys(), test::bricks());
  EXPECT_EQ(facade_named(env.facades, "N2")->index, 4u);
  EXPECT_EQ(facade_named(env.facades, "4")->name, "N2");
  EXPECT_EQ(facade_named(env.facades, "Q"), nullptr);
}

}  // namespace
}  // namespace curdle
