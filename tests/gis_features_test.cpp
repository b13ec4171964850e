// The layout as GIS features: a feature per schedule row with its attributes, a layer per kind
// of element, shapes in metres, and layout.georef placing them in the project's CRS.
#include "export/gis/gis_features.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>

#include "app/run.h"
#include "layout/builder.h"
#include "layout/piece.h"
#include "test_support.h"

namespace curdle {
namespace {

Layout pattern_layout(const std::string& name) {
  const std::string path = std::string(CURDLE_SOURCE_DIR) + "/patterns/" + name;
  const app::Run run = test::run_recipe(path, app::read_recipe_file(path), {});
  const CurdField field = app::run_engine(run, 0);
  return make_layout(run.recipe.design, field, run.view, *run.recipe.layout);
}

size_t of_type(GisField::Type t) {
  switch (t) {
    case GisField::Type::integer:
      return GisValue(std::int64_t{0}).index();
    case GisField::Type::real:
      return GisValue(0.0).index();
    case GisField::Type::text:
      break;
  }
  return GisValue(std::string()).index();
}

// A text value as the schedules give it: null as empty.
std::string text_of(const GisValue& v) {
  return std::holds_alternative<std::monostate>(v) ? std::string() : std::get<std::string>(v);
}

TEST(GisFeatures, AFeaturePerPieceInALayerPerKindWithTheScheduleAttributes) {
  const Layout layout = pattern_layout("paper/fig5a-park.toml");
  const GisDataset data = gis_features(layout);
  EXPECT_EQ(data.epsg, 0);
  size_t features = 0;
  std::vector<std::string> names;
  for (const GisLayer& l : data.layers) {
    names.push_back(l.name);
    features += l.features.size();
    for (const GisFeature& f : l.features) {
      ASSERT_EQ(f.values.size(), data.fields.size());
      ASSERT_FALSE(f.polygons.empty());
      // Each value of its field's type, or null: GDAL is handed it by its type.
      for (size_t i = 0; i < f.values.size(); ++i)
        ASSERT_TRUE(std::holds_alternative<std::monostate>(f.values[i]) ||
                    f.values[i].index() == of_type(data.fields[i].type))
            << data.fields[i].name;
    }
  }
  EXPECT_EQ(features, layout.elements.size());
  EXPECT_EQ(names, (std::vector<std::string>{"white_paving", "tree", "bench"}));
  EXPECT_EQ(data.fields.front().name, "element_id");
  // The tree's attributes as schedule.csv has them: its ID first, its species as material.
  const GisFeature& tree = data.layers[1].features.front();
  const std::string& id = std::get<std::string>(tree.values.front());
  EXPECT_TRUE(id.ends_with("-tree")) << id;
  // planting.csv's columns on the layers too, as it gives them: a tree's species and sizes, a
  // paving piece's left null; and every piece's zone.
  std::map<std::string, size_t> field;
  for (size_t i = 0; i < data.fields.size(); ++i) field[data.fields[i].name] = i;
  for (const char* name : {"species", "girth_cm", "root_ball_mm", "pit_width_mm", "zone"})
    ASSERT_TRUE(field.contains(name)) << name;
  const Element* first_tree = nullptr;
  for (const Element& e : layout.elements)
    if (e.stands && e.circle && !first_tree) first_tree = &e;
  ASSERT_NE(first_tree, nullptr);
  const PlantingSpec& p = planting_of(layout, *first_tree);
  EXPECT_EQ(text_of(tree.values[field["species"]]), p.species);
  EXPECT_EQ(text_of(tree.values[field["girth_cm"]]), p.girth_text());
  const GisValue& ball = tree.values[field["root_ball_mm"]];
  if (p.root_ball > 0)
    EXPECT_EQ(std::get<double>(ball), p.root_ball);
  else
    EXPECT_TRUE(std::holds_alternative<std::monostate>(ball));
  EXPECT_TRUE(std::holds_alternative<std::monostate>(
      data.layers[0].features.front().values[field["species"]]));
}

TEST(GisFeatures, GeorefPlacesTheDatumAndTurnsTheAxes) {
  Layout layout = pattern_layout("courtyard-l-shaped.toml");
  EXPECT_EQ(map_point(layout, 1500, 2000), (std::array<double, 2>{1.5, 2.0}));
  layout.georef = Georef{25832, 500000, 5700000, 90};
  const auto p = map_point(layout, 1000, 0);  // one metre along x: north, turned 90°
  EXPECT_NEAR(p[0], 500000, 1e-9);
  EXPECT_NEAR(p[1], 5700001, 1e-9);
  const GisDataset data = gis_features(layout);
  EXPECT_EQ(data.epsg, 25832);
  const Ring& ring = data.layers[0].features[0].polygons[0][0];
  for (const auto& [e, n] : ring) {
    EXPECT_GT(e, 499000);
    EXPECT_GT(n, 5699990);
  }
}

}  // namespace
}  // namespace curdle
