// Tests of facade.h: a wall's windows and doors are cut out of its grid, and its open share is
// the openings' area over the wall's.
#include "kinds/facade.h"

#include <gtest/gtest.h>

#include "layout_support.h"

namespace curdle {
namespace {

TEST(Facade, OpeningsAreCutOutAndTheirShareOfTheWallReported) {
  const Design d = test::design(2, 2, {{"3/4", "2/3"}});
  LayoutSpec spec = test::layout_spec("facade");
  spec.module_w = 600, spec.module_h = 300, spec.joint = 0;
  spec.size = std::array<double, 2>{6000, 3000};
  spec.own<FacadeKeys>().openings = {{1200, 900, 1200, 1500}, {4200, 0, 900, 2100}};
  const Layout wall = lay_floor(d, spec, 4);
  double panels = 0;
  for (const Element& e : wall.elements) {
    panels += e.area();
    for (const Rect& o : wall.openings)
      for (const Rect& r : e.shape) EXPECT_FALSE(overlaps(r, o)) << e.id;
  }
  const double open = 1200 * 1500 + 900 * 2100;
  EXPECT_NEAR(panels, 6000.0 * 3000 - open, 1e-6);
  EXPECT_NEAR(wall.open_area, open / (6000.0 * 3000), 1e-12);
  bool noted = false;
  for (const std::string& n : wall.notes) noted |= n.find("% of the wall") != std::string::npos;
  EXPECT_TRUE(noted);
  EXPECT_EQ(wall.elements.front().id.rfind("F-", 0), 0u);
}

}  // namespace
}  // namespace curdle
