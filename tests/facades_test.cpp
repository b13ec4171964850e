// A building's plan unrolled into façades: the L-shaped pavilion of the whole-buildings issue
// (20 x 12 m with an 8 x 6 m bite), a curved wall, a clockwise plan, and plans refused.
#include "building/facades.h"

#include <gtest/gtest.h>

#include <cmath>

#include "curdle/error.h"
#include "layout/contour.h"

namespace curdle {
namespace {

Contour pavilion() {
  return contour_of({{0, 0}, {20000, 0}, {20000, 6000}, {12000, 6000}, {12000, 12000}, {0, 12000}});
}

TEST(Facades, TheLShapedPavilionUnrollsAnticlockwiseFromItsStart) {
  const std::vector<Facade> f = unroll_plan(pavilion(), 0, 215);
  ASSERT_EQ(f.size(), 6u);
  const std::vector<std::string> names{"S", "E", "N", "E2", "N2", "W"};
  const std::vector<double> lengths{20000, 6000, 8000, 6000, 12000, 12000};
  for (size_t k = 0; k < 6; ++k) {
    EXPECT_EQ(f[k].index, k);
    EXPECT_EQ(f[k].name, names[k]);
    EXPECT_DOUBLE_EQ(f[k].length, lengths[k]);
  }
  EXPECT_DOUBLE_EQ(f[3].start, 20000 + 6000 + 8000);
  EXPECT_DOUBLE_EQ(strip_length(f), 64000);  // the 64 m the unrolled wall measured
  EXPECT_NEAR(f[0].facing, 180, 1e-9);
  EXPECT_NEAR(f[1].facing, 90, 1e-9);
  // The bite: the N face at 6 m turns into the building at its end (an inner corner).
  EXPECT_NEAR(f[0].turn_at_end, 90, 1e-9);
  EXPECT_NEAR(f[2].turn_at_end, -90, 1e-9);
  EXPECT_NEAR(f[3].turn_at_end, 90, 1e-9);
  EXPECT_NEAR(f[5].turn_at_end, 90, 1e-9);  // the closing corner, back into the first
}

TEST(Facades, AStartElsewhereAndAClockwisePlanGiveTheSameFacades) {
  const std::vector<Facade> from2 = unroll_plan(pavilion(), 2, 215);
  EXPECT_EQ(from2.front().index, 2u);
  EXPECT_EQ(from2.front().start, 0);
  Contour clockwise = pavilion();
  std::reverse(clockwise.begin(), clockwise.end());
  const std::vector<Facade> f = unroll_plan(clockwise, 5, 215);  // the (0, 0) corner
  EXPECT_DOUBLE_EQ(f.front().length, 20000);
  EXPECT_NEAR(f.front().facing, 180, 1e-9);
  EXPECT_DOUBLE_EQ(strip_length(f), 64000);
}

TEST(Facades, AnArcEdgeIsMeasuredAlongTheWallAndFacesOut) {
  // A 10 x 10 m plan whose east side bows out in a 90° arc of radius 7071 mm.
  Contour plan = contour_of({{0, 0}, {10000, 0}, {10000, 10000}, {0, 10000}});
  plan[1].bulge = std::tan(3.14159265358979323846 / 8);  // 90° anticlockwise: bows east
  const std::vector<Facade> f = unroll_plan(plan, 0, 215);
  EXPECT_NEAR(f[1].length, 7071.0678 * 3.14159265358979323846 / 2, 0.01);
  EXPECT_NEAR(f[1].facing, 90, 1e-6);
  EXPECT_EQ(f[1].name, "E");
  EXPECT_NEAR(strip_length(f), 30000 + f[1].length, 1e-6);
}

TEST(Facades, PlansThatCannotBeBuiltAreRefusedByName) {
  auto message = [](const Contour& plan, size_t start) {
    try {
      unroll_plan(plan, start, 215);
    } catch (const InputError& e) {
      return e.where().key + ": " + e.message();
    }
    return std::string("taken");
  };
  EXPECT_NE(message(contour_of({{0, 0}, {1000, 0}}), 0).find("three vertices"), std::string::npos);
  EXPECT_NE(
      message(contour_of({{0, 0}, {1000, 1000}, {1000, 0}, {0, 1000}}), 0).find("crosses itself"),
      std::string::npos);
  EXPECT_NE(message(contour_of({{0, 0}, {100, 0}, {100, 5000}, {0, 5000}}), 0)
                .find("edge 0 is 100 mm long, shorter than one unit"),
            std::string::npos);
  EXPECT_NE(message(pavilion(), 6).find("start must be a vertex"), std::string::npos);
  EXPECT_EQ(message(pavilion(), 0), "taken");
}

TEST(Facades, CompassPoints) {
  EXPECT_EQ(compass_point(0), "N");
  EXPECT_EQ(compass_point(22.4), "N");
  EXPECT_EQ(compass_point(22.6), "NE");
  EXPECT_EQ(compass_point(359), "N");
  EXPECT_EQ(compass_point(225), "SW");
}

}  // namespace
}  // namespace curdle
