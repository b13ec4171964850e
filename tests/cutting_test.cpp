// Fabrication sheets: openings keep their margins within each sheet and their bridges across
// seams, and each sheet's DXF, read back with dxflib's reader, holds exactly its openings.
#include "export/dxf/cutting.h"

#include <dxflib/dl_creationadapter.h>
#include <dxflib/dl_dxf.h>
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <filesystem>
#include <map>
#include <set>

#include "curdle/curdling.h"
#include "export/dxf/layout_dxf.h"
#include "kinds/perforation.h"
#include "layout/builder.h"
#include "picture_support.h"
#include "test_support.h"

namespace curdle {
namespace {

// The SHEETS layer of a layout's DXF: each sheet's first corner and its ID.
struct SheetsLayer : DL_CreationAdapter {
  std::vector<std::array<double, 2>> corners;
  std::set<std::string> ids;
  bool first = false;
  void addPolyline(const DL_PolylineData&) override { first = attributes.getLayer() == "SHEETS"; }
  void addVertex(const DL_VertexData& v) override {
    if (first) corners.push_back({v.x, v.y});
    first = false;
  }
  void addText(const DL_TextData& t) override {
    if (attributes.getLayer() == "SHEETS") ids.insert(t.text);
  }
};

struct DxfContents : DL_CreationAdapter {
  std::vector<std::tuple<std::string, double, double, double>> circles;  // layer, x, y, r
  int polylines = 0;
  std::string text;
  std::set<std::string> ids;
  void addCircle(const DL_CircleData& c) override {
    circles.emplace_back(attributes.getLayer(), c.cx, c.cy, c.radius);
  }
  void addPolyline(const DL_PolylineData&) override { ++polylines; }
  void addText(const DL_TextData& t) override {
    if (attributes.getLayer() == "ID")
      ids.insert(t.text);
    else
      text = t.text;
  }
};

const Design kDesign = test::design(
    2, 2, {{"0.9", "0.9", "0.8", "0.8", "0.8", "0.7"}, {"0.8", "0.7", "0.8", "0.7", "0.7", "0.8"}});

// A 3.2 m square screen of 50 mm cells cut into 1250 x 2500 mm sheets.
Layout screen(const Design& d) {
  LayoutSpec spec = test::layout_spec();
  spec.set_kind(layout_kind("perforation"));
  spec.combine = Combine::mix;
  spec.module_w = spec.module_h = 50;
  spec.size = std::array<double, 2>{3200, 3200};
  spec.own<PerforationKeys>().thickness = 3;
  spec.own<PerforationKeys>().holes = {{12, -8, 8}, {20, 4, -4}};
  spec.own<PerforationKeys>().min_bridge = 4;
  spec.own<PerforationKeys>().edge_margin = 20;
  spec.own<PerforationKeys>().fix = HoleFix::drop;
  spec.own<PerforationKeys>().sheet_size = std::array<double, 2>{1250, 2500};
  return make_layout(d, curdle(d, 9, d.field), d.field, spec);
}

}  // namespace

TEST(Cutting, SheetsKeepMarginsAndBridgesAndTheirDxfHoldsTheirOpenings) {
  const Layout layout = screen(kDesign);
  ASSERT_EQ(layout.sheets().size(), 6u);  // 3 x 2 sheets, the last column and row narrower
  std::map<int, std::vector<const Element*>> by_sheet;
  for (const Element& e : layout.elements) {
    ASSERT_GE(e.sheet, 0) << e.id;
    const Rect& a = layout.sheets()[static_cast<size_t>(e.sheet)].area;
    const Circle& c = *e.circle;
    EXPECT_GE(c.cx - c.d / 2 - a.x, 20 - 1e-9) << e.id;
    EXPECT_GE(a.right() - c.cx - c.d / 2, 20 - 1e-9) << e.id;
    EXPECT_GE(c.cy - c.d / 2 - a.y, 20 - 1e-9) << e.id;
    EXPECT_GE(a.top() - c.cy - c.d / 2, 20 - 1e-9) << e.id;
    by_sheet[e.sheet].push_back(&e);
  }
  for (size_t i = 0; i < layout.elements.size(); ++i)  // every pair, across seams too
    for (size_t j = i + 1; j < layout.elements.size(); ++j)
      EXPECT_GE(bridge({*layout.elements[i].circle}, {*layout.elements[j].circle}), 4 - 1e-9);

  const auto dir =
      std::filesystem::temp_directory_path() / ("curdle-dxf-" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  for (size_t s = 0; s < layout.sheets().size(); ++s) {
    const auto path = dir / (layout.sheets()[s].id + ".dxf");
    write_sheet_dxf(path, layout, static_cast<int>(s));
    DxfContents read;
    DL_Dxf dxf;
    ASSERT_TRUE(dxf.in(path.string(), &read)) << path;
    EXPECT_EQ(read.text, layout.sheets()[s].id);
    EXPECT_EQ(read.polylines, 1);  // the sheet's outline
    std::set<std::string> expected_ids;
    for (const Element* e : by_sheet[static_cast<int>(s)]) expected_ids.insert(e->id);
    EXPECT_EQ(read.ids, expected_ids);  // the same IDs as the schedule, SVG and glTF
    ASSERT_EQ(read.circles.size(), by_sheet[static_cast<int>(s)].size());
    const Rect& a = layout.sheets()[s].area;
    for (size_t k = 0; k < read.circles.size(); ++k) {
      const Circle& c = *by_sheet[static_cast<int>(s)][k]->circle;
      const auto& [layer, x, y, r] = read.circles[k];
      EXPECT_NEAR(x, c.cx - a.x, 1e-6);
      EXPECT_NEAR(y, c.cy - a.y, 1e-6);
      EXPECT_NEAR(2 * r, c.d, 1e-6);
      // One layer per diameter, without a dot: HOLE_D20, HOLE_D22_6.
      std::string expected = "HOLE_D" + std::to_string(static_cast<int>(c.d));
      if (std::fabs(c.d - std::round(c.d)) > 1e-9) continue;
      EXPECT_EQ(layer, expected);
    }
  }
  std::filesystem::remove_all(dir);
}

// A screen laid on a surface read from a site drawing: each cutting file keeps the sheet's own
// origin for the cutter and says where that origin lies in the drawing; layout-site.dxf shows
// every sheet by its ID at the drawing's coordinates.
TEST(Cutting, SheetsOfASiteSurfaceSayWhereTheyLieInTheDrawing) {
  Layout layout = screen(kDesign);
  layout.site_frame = SiteFrame{.file = "site.dxf",
                                .unit_mm = 1000,
                                .unit_name = "m",
                                .insunits = 6,
                                .datum = {530000, 180000},
                                .precision = 3};
  const auto dir = test::scratch("cutting-site");
  const auto& second = layout.sheets()[1];
  write_sheet_dxf(dir / "sheet.dxf", layout, 1);
  DxfContents sheet;
  DL_Dxf reader;
  ASSERT_TRUE(reader.in((dir / "sheet.dxf").string(), &sheet));
  ASSERT_EQ(second.area.x, 1250);
  ASSERT_EQ(second.area.y, 0);
  EXPECT_TRUE(sheet.ids.count("(0, 0) = E 530,001.250 N 180,000.000 m in site.dxf"));
  ASSERT_FALSE(sheet.circles.empty());  // still from the sheet's own corner
  EXPECT_LT(std::get<1>(sheet.circles[0]), second.area.w);

  write_layout_dxf(dir / "layout-site.dxf", layout, true);
  SheetsLayer sheets;
  ASSERT_TRUE(reader.in((dir / "layout-site.dxf").string(), &sheets));
  ASSERT_EQ(sheets.ids.size(), layout.sheets().size());
  ASSERT_EQ(sheets.corners.size(), layout.sheets().size());
  for (size_t i = 0; i < layout.sheets().size(); ++i) {
    const Rect& a = layout.sheets()[i].area;
    EXPECT_TRUE(sheets.ids.count(layout.sheets()[i].id)) << layout.sheets()[i].id;
    EXPECT_NEAR(sheets.corners[i][0], 530000 + a.x / 1000, 1e-9) << i;
    EXPECT_NEAR(sheets.corners[i][1], 180000 + a.y / 1000, 1e-9) << i;
  }
  std::filesystem::remove_all(dir);
}

}  // namespace curdle
