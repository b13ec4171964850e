// What each installer's sheet shows, listed once for the set: the same elements, pieces and
// labels as asking every sheet's view of every one of them.
#include "export/drawing/installer_drawing.h"

#include <gtest/gtest.h>

#include "export/drawing/sheet_drawing.h"
#include "layout/builder.h"
#include "pattern_support.h"

namespace curdle {
namespace {

using test::pattern_layout;

TEST(InstallerDrawing, EachSheetListsWhatItsViewShows) {
  for (const char* name :
       {"plaza-three-colours.toml", "paper/fig5a-park.toml", "brick-facade-five-storeys.toml"}) {
    const Layout layout = pattern_layout(name);
    const InstallerPlan plan = plan_installer_sheets(layout);
    const InstallerDrawing set = installer_set(layout, plan);
    ASSERT_GT(plan.sheets.size(), 1u) << name;
    ASSERT_EQ(set.elements_on.size(), plan.sheets.size());
    size_t listed = 0;
    for (size_t s = 0; s < plan.sheets.size(); ++s) {
      sheet_drawing::View view;
      view.window = plan.sheets[s].window;
      std::vector<uint32_t> elements, pieces, labels;
      for (uint32_t i = 0; i < layout.elements.size(); ++i)
        if (view.shows(laid_bounds(layout.elements[i]))) elements.push_back(i);
      for (uint32_t i = 0; i < plan.pieces.size(); ++i)
        if (view.shows(plan.pieces[i].bounds)) pieces.push_back(i);
      for (uint32_t i = 0; i < plan.labels.size(); ++i)
        if (plan.labels[i].sheet == s) labels.push_back(i);
      EXPECT_EQ(set.elements_on[s], elements) << name << " sheet " << s;
      EXPECT_EQ(set.pieces_on[s], pieces) << name << " sheet " << s;
      EXPECT_EQ(set.labels_on[s], labels) << name << " sheet " << s;
      listed += elements.size();
    }
    EXPECT_GE(listed, layout.elements.size()) << "every element is on a sheet";
  }
}

}  // namespace
}  // namespace curdle
