// Tests of install.h: install.svg is well-formed XML that labels every piece once, numbers the
// rows and shows where laying starts.
#include "export/install.h"

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
}

}  // namespace
}  // namespace curdle
