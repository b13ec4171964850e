#include "site/layer_shapes.h"

#include <gtest/gtest.h>

namespace curdle::site {
namespace {

Shape shape(const std::string& handle, Contour path, bool closed) {
  Shape s;
  s.layer = "PIT";
  s.handle = handle;
  s.entity = closed ? "CIRCLE" : "LINE";
  s.path = std::move(path);
  s.closed = closed;
  return s;
}

TEST(LayerShapesTest, TheOuterShapesAreTheLayersAndTheRestIsCounted) {
  Drawing d;
  d.shapes.push_back(shape("1", {{-750, 0, 1}, {750, 0, 1}}, true));       // the pit
  d.shapes.push_back(shape("2", {{-200, 0, 1}, {200, 0, 1}}, true));       // its trunk
  d.shapes.push_back(shape("3", {{-500, 300, 0}, {500, 300, 0}}, false));  // a grille bar
  d.shapes.push_back(shape("4", {{-750, 0, 1}, {750, 0, 1}}, true));       // the pit again
  PassedOver passed;
  const std::vector<Closed> found = closed_on(d, "PIT", 0.5, "site.dxf", "zone", 1, passed);
  ASSERT_EQ(found.size(), 1u);
  EXPECT_EQ(found[0].handles, "CIRCLE 1");
  EXPECT_EQ(passed.inside, 1u);
  EXPECT_EQ(passed.pieces, 1u);
  EXPECT_EQ(passed.repeats, 1u);
}

TEST(LayerShapesTest, ShapesAndPlacesAreNamedAsCadShowsThem) {
  Shape s = shape("9D", {{0, 0, 0}, {1, 0, 0}}, false);
  s.block = "PIT";
  s.insert_handle = "2F";
  EXPECT_EQ(handle_of(s), "LINE 9D in block \"PIT\" (INSERT 2F)");
  EXPECT_EQ(point_text({530012.34560, -0.5, 0}, 4), "(530012.3456, -0.5)");
  EXPECT_EQ(number_text(2.0, 3), "2");
  EXPECT_EQ(grouped(14000), "14,000");
}

}  // namespace
}  // namespace curdle::site
