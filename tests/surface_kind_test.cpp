// Tests of surface_kind.h: the surface kinds laid on a grid share their keys and their laying,
// and each tells the writers its own facts.
#include "kinds/surface_kind.h"

#include <gtest/gtest.h>

#include <algorithm>

#include "layout_support.h"

namespace curdle {
namespace {

TEST(SurfaceKind, TilePavingAndFacadeShareTheGridsKeysAndSayTheirOwnFacts) {
  for (const char* name : {"tile", "paving", "facade"}) {
    const LayoutKind& kind = layout_kind(name);
    ASSERT_NE(dynamic_cast<const SurfaceKind*>(&kind), nullptr) << name;
    const std::vector<std::string> keys = kind.keys();
    for (const char* key : {"joint", "origin", "bond", "shift", "min_cut", "zones", "outline"})
      EXPECT_NE(std::find(keys.begin(), keys.end(), key), keys.end()) << name << " " << key;
    EXPECT_TRUE(kind.takes_zones());
    EXPECT_EQ(kind.ground(), Ground::joints);
    EXPECT_EQ(kind.depiction(), Depiction::grid);
  }
  const LayoutSpec spec = test::layout_spec("paving");
  EXPECT_EQ(layout_kind("paving").thickness(spec), 30);
  EXPECT_EQ(layout_kind("tile").thickness(spec), 10);
  EXPECT_TRUE(layout_kind("paving").bedded());
  EXPECT_FALSE(layout_kind("facade").bedded());
  EXPECT_TRUE(layout_kind("facade").upright());
}

TEST(SurfaceKind, SliversAreCheckedAndTheLayoutCarriesWhatWasBuilt) {
  Design d = test::design(2, 2, {{"3/4", "2/3"}});
  d.description = "a floor";
  LayoutSpec spec = test::layout_spec("tile");
  spec.module_w = spec.module_h = 300;
  spec.size = std::array<double, 2>{1230, 900};  // the last column is 30 mm: a sliver
  spec.drawing.dpi = 200;
  spec.ordering.pack = 12;
  const Layout layout = lay_floor(d, spec, 5);
  EXPECT_EQ(layout.kind, &layout_kind("tile"));
  EXPECT_EQ(layout.element_type, "tile");
  EXPECT_EQ(layout.thickness, 10);
  EXPECT_EQ(layout.drawing.dpi, 200);
  EXPECT_EQ(layout.ordering.pack, 12);
  EXPECT_EQ(layout.source.seed, 5u);  // the field's seed, without the application's help
  EXPECT_EQ(layout.source.description, "a floor");
  size_t slivers = 0;
  for (const std::string& v : layout.violations)
    slivers += v.find("below 100.0 mm (a third of the element)") != v.npos;
  EXPECT_EQ(slivers, 3u) << "one 30 mm piece per row";
}

}  // namespace
}  // namespace curdle
