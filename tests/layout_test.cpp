// Tests of layout.h: a kind's own keys, held and copied with the spec, and each kind's own
// record on the layouts it lays.
#include "layout/layout.h"

#include <gtest/gtest.h>

#include "app/run.h"
#include "layout/builder.h"
#include "test_support.h"

namespace curdle {
namespace {
struct PierKeys : KindKeysOf<PierKeys> {
  double pitch = 600;
};
struct QuayKeys : KindKeysOf<QuayKeys> {};

Layout shipped_layout(const std::string& name) {
  const std::string path = std::string(CURDLE_SOURCE_DIR) + "/patterns/" + name;
  const app::Run run = test::run_recipe(path, app::read_recipe_file(path), {});
  return make_layout(run.recipe.design, app::run_engine(run, 0), run.view, *run.recipe.layout);
}
}  // namespace

TEST(OwnKeys, AKindsKeysAreFoundAsThemselvesAndCopiedWithTheirOwner) {
  OwnKeys keys(std::make_unique<PierKeys>());
  keys.as<PierKeys>().pitch = 450;
  EXPECT_EQ(keys.find<QuayKeys>(), nullptr);  // another kind's record is not there
  const OwnKeys copy = keys;
  keys.as<PierKeys>().pitch = 300;
  EXPECT_EQ(copy.as<PierKeys>().pitch, 450);  // a copy of its own, not the same record
  EXPECT_EQ(OwnKeys().find<PierKeys>(), nullptr);
}

// Which records a layout holds says what it is: blocks' views, a park's planting, a screen's
// sheets, a wall's frames (a one-brick wall's backing with them); a plain floor holds none.
TEST(Layout, EachKindsOwnRecordIsOnTheLayoutsItLaysAlone) {
  struct Expected {
    std::string pattern;
    bool views, planting, fabrication, envelope, backing;
  };
  for (const Expected& x :
       std::vector<Expected>{{"courtyard-l-shaped.toml", false, false, false, false, false},
                             {"stacked-blocks.toml", true, false, false, false, false},
                             {"paper/fig5a-park.toml", false, true, false, false, false},
                             {"perforated-aluminium-screen.toml", false, false, true, false, false},
                             {"perforated-screen-curved.toml", false, false, true, true, false},
                             {"fins-round-building.toml", false, false, false, true, false},
                             {"kiosk-from-dxf.toml", false, false, false, true, true}}) {
    const Layout l = shipped_layout(x.pattern);
    SCOPED_TRACE(x.pattern);
    EXPECT_EQ(l.block_views.has_value(), x.views);
    EXPECT_EQ(l.planting.has_value(), x.planting);
    EXPECT_EQ(l.fabrication.has_value(), x.fabrication);
    EXPECT_EQ(l.envelope.has_value(), x.envelope);
    EXPECT_EQ(l.backing() != nullptr, x.backing);
    EXPECT_EQ(l.sheets().empty(), !x.fabrication);
    EXPECT_EQ(l.frames().empty(), !x.envelope);
  }
}

}  // namespace curdle
