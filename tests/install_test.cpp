// Tests of install.h: install.svg is well-formed XML that labels every piece once, numbers the
// rows and shows where laying starts.
#include "export/drawing/install.h"

#include <expat.h>
#include <gtest/gtest.h>

#include <sstream>

#include "layout/installer_sheets.h"
#include "layout_support.h"

namespace curdle {
namespace {

TEST(Install, EveryPieceLabelledOnceInWellFormedSvg) {
  const Design d = test::design(2, 2, {{"3/4", "2/3"}});
  LayoutSpec spec = test::layout_spec("paving");
  spec.size = std::array<double, 2>{2400, 1500};
  spec.module_w = spec.module_h = 600;
  const Layout layout = lay_floor(d, spec, 2);
  std::ostringstream out;
  write_install_svg(out, layout, plan_installer_sheets(layout));
  const std::string svg = out.str();
  // A key beside the map: every value laid, its name and how many of it.
  ASSERT_NE(svg.find("<g id=\"key\""), std::string::npos);
  for (const LegendEntry& e : layout.legend) {
    if (e.count == 0) continue;
    EXPECT_NE(svg.find(">" + e.label + ": " + std::to_string(e.count) + "</text>"),
              std::string::npos)
        << e.label;
  }
  XML_Parser parser = XML_ParserCreate(nullptr);
  EXPECT_EQ(XML_Parse(parser, svg.data(), static_cast<int>(svg.size()), 1), XML_STATUS_OK)
      << XML_ErrorString(XML_GetErrorCode(parser));
  XML_ParserFree(parser);
  for (const Element& e : layout.elements) {
    size_t labels = 0;
    for (size_t at = svg.find(">" + e.id + "<"); at != std::string::npos;
         at = svg.find(">" + e.id + "<", at + 1))
      ++labels;
    EXPECT_EQ(labels, 1u) << e.id;
  }
  EXPECT_NE(svg.find("id=\"rows\""), std::string::npos);
  EXPECT_NE(svg.find(">R0<"), std::string::npos);
  EXPECT_NE(svg.find("id=\"laying-order\""), std::string::npos);
  EXPECT_NE(svg.find(", IDs "), std::string::npos);  // the heading gives the IDs' height
}

// A coursed map (bricks) numbers courses and columns and draws no IDs: its heading says so,
// and gives no height of IDs it does not have.
TEST(Install, ACoursedMapsHeadingNamesNoIds) {
  const Design d = test::design(2, 2, {{"3/4", "2/3"}, {"1/2", "1/2"}});
  LayoutSpec spec = test::layout_spec("facade");
  spec.size = std::array<double, 2>{2400, 1500};
  const Layout layout = lay_floor(d, spec, 2);
  const InstallerPlan plan = plan_installer_sheets(layout);
  ASSERT_TRUE(plan.coursed);
  std::ostringstream out;
  write_install_svg(out, layout, plan);
  EXPECT_EQ(out.str().find(", IDs "), std::string::npos);
  EXPECT_NE(out.str().find("courses and columns numbered"), std::string::npos);
}

// The key shows each product as the map draws it: the pieces' faint fill (once full colour,
// so that "dark" slabs printed near the key's "mid"), the same hatch for black-and-white
// prints, and room for its longest line ("Dark brown ...: 3105" once read "310").
TEST(Install, TheKeyShowsEachProductAsDrawnHatchedAndWhole) {
  const Design d = test::design(2, 2, {{"3/4", "2/3"}, {"3/4", "1/2"}});
  LayoutSpec spec = test::layout_spec("paving");
  spec.size = std::array<double, 2>{2400, 1500};
  spec.module_w = spec.module_h = 100;
  spec.materials = {"Buff concrete paving slab", "Dark brown clay paver, 100 x 100 mm, tumbled",
                    "Mid grey granite sett", "Mid grey granite sett"};
  spec.value_colours = {Rgb{220, 214, 200}, Rgb{94, 58, 40}, Rgb{140, 140, 136},
                        Rgb{140, 140, 136}};
  const Layout layout = lay_floor(d, spec, 2);
  std::ostringstream out;
  write_install_svg(out, layout, plan_installer_sheets(layout));
  const std::string svg = out.str();
  const size_t key = svg.find("<g id=\"key\"");
  ASSERT_NE(key, std::string::npos);
  const std::string faint = "fill-opacity=\"0.35\"";
  EXPECT_NE(svg.find("<g id=\"elements\" " + faint), std::string::npos);
  EXPECT_NE(svg.find(faint, key), std::string::npos);  // the key's swatches as drawn
  // Values 2 and 3 lay one product: one pattern, one hatch, one key line.
  EXPECT_NE(svg.find("<pattern id=\"hatch-2\""), std::string::npos);
  EXPECT_EQ(svg.find("<pattern id=\"hatch-3\""), std::string::npos);
  EXPECT_NE(svg.find("fill=\"url(#hatch-2)\"", key), std::string::npos);
  EXPECT_NE(svg.find("<g id=\"hatches\">"), std::string::npos);
  size_t lines = 0;
  for (size_t at = svg.find("Mid grey granite sett: ", key); at != std::string::npos;
       at = svg.find("Mid grey granite sett: ", at + 1))
    ++lines;
  EXPECT_EQ(lines, 1u);
  // The drawing is wide enough for the key's longest line at 0.62 em a character.
  auto number = [&](const std::string& attribute, size_t from) {
    const size_t at = svg.find(attribute + "=\"", from) + attribute.size() + 2;
    return std::stod(svg.substr(at));
  };
  const double width = std::stod(svg.substr(svg.find("viewBox=\"0 0 ") + 13));
  const double key_x = number("x", svg.find("<text", key));
  const double font = number("font-size", key);
  const std::string longest = "Dark brown clay paver, 100 x 100 mm, tumbled: ";
  EXPECT_GE(width, key_x + 10 * plan_installer_sheets(layout).scale +
                       0.62 * font * static_cast<double>(longest.size() + 3));
}

}  // namespace
}  // namespace curdle
