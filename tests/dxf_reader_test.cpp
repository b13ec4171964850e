#include "site/dxf_reader.h"

#include <gtest/gtest.h>

#include <cmath>

#include "dxf_text.h"

namespace curdle::site {
namespace {

using testing::DxfText;

const Shape& on(const Drawing& d, const std::string& layer, size_t k = 0) {
  for (const Shape& s : d.shapes)
    if (s.layer == layer && k-- == 0) return s;
  throw std::runtime_error("no shape on " + layer);
}

std::string refusal(const std::string& bytes, const DxfReading& r = {}) {
  try {
    read_dxf(bytes, "site.dxf", r);
  } catch (const SiteError& e) {
    return e.what();
  }
  return "(read)";
}

TEST(DxfReaderTest, ReadsPolylinesWithTheirBulgesAndUnits) {
  DxfText dxf(6);  // metres
  dxf.begin_entities_only().lwpolyline("A-OTLN", "2A",
                                       {{0, 0, 0}, {14, 0, 0}, {14, 9, -0.2}, {4, 9, 0}}, true);
  const Drawing d = read_dxf(dxf.text(), "site.dxf", {});
  EXPECT_EQ(d.format, "DXF");
  EXPECT_EQ(d.unit_mm, 1000);
  EXPECT_EQ(d.unit_name, "m");
  const Shape& s = on(d, "A-OTLN");
  EXPECT_TRUE(s.closed);
  EXPECT_EQ(s.handle, "2A");
  EXPECT_EQ(s.entity, "LWPOLYLINE");
  ASSERT_EQ(s.path.size(), 4u);
  EXPECT_EQ(s.path[2].bulge, -0.2);
  EXPECT_EQ(s.path[3].x, 4);
}

TEST(DxfReaderTest, ArcsAndCirclesBecomeBulges) {
  DxfText dxf;
  dxf.begin_entities_only().arc("EDGE", "10", 0, 0, 100, 0, 90).circle("PIT", "11", 50, 60, 7);
  const Drawing d = read_dxf(dxf.text(), "site.dxf", {});
  const Shape& arc = on(d, "EDGE");
  ASSERT_EQ(arc.path.size(), 2u);
  EXPECT_FALSE(arc.closed);
  EXPECT_NEAR(arc.path[0].x, 100, 1e-9);
  EXPECT_NEAR(arc.path[1].y, 100, 1e-9);
  EXPECT_NEAR(arc.path[0].bulge, std::tan(3.14159265358979323846 / 8), 1e-12);
  const Shape& pit = on(d, "PIT");
  EXPECT_TRUE(pit.closed);
  EXPECT_NEAR(contour_area(pit.path), 3.14159265358979323846 * 49, 1e-9);
}

TEST(DxfReaderTest, MirroredEntitiesTurnBackIntoThePlan) {
  DxfText dxf;
  // Drawn from below (extrusion 0, 0, -1): x is mirrored, and the turn with it.
  dxf.begin_entities_only().lwpolyline("M", "1", {{10, 0, 1}, {20, 0, 0}}, false, -1);
  const Drawing d = read_dxf(dxf.text(), "site.dxf", {});
  const Shape& s = on(d, "M");
  EXPECT_EQ(s.path[0].x, -10);
  EXPECT_EQ(s.path[0].bulge, -1);
}

TEST(DxfReaderTest, BlocksArePlacedScaledTurnedAndNested) {
  DxfText dxf;
  dxf.begin_blocks()
      .block("PANE", 0, 0)
      .lwpolyline("0", "20", {{0, 0, 0}, {100, 0, 0}, {100, 50, 0}, {0, 50, 0}}, true)
      .end_block()
      .block("WINDOW", 10, 0)
      .insert("0", "21", "PANE", 10, 0)
      .end_block()
      .begin_entities()
      .insert("A-GLAZ", "30", "WINDOW", 1000, 2000, 2, 2, 90);
  const Drawing d = read_dxf(dxf.text(), "site.dxf", {});
  const Shape& s = on(d, "A-GLAZ");  // layer 0 takes the insert's
  EXPECT_EQ(s.insert, 0);
  // (0, 0) of the pane lies at the window's base point: scaled by 2, turned 90°: (1000, 2000).
  EXPECT_NEAR(s.path[0].x, 1000, 1e-9);
  EXPECT_NEAR(s.path[0].y, 2000, 1e-9);
  // (100, 0) goes 200 along the turned x: up.
  EXPECT_NEAR(s.path[1].x, 1000, 1e-9);
  EXPECT_NEAR(s.path[1].y, 2200, 1e-9);
}

TEST(DxfReaderTest, SelfInsertingBlocksAreRefused) {
  DxfText dxf;
  dxf.begin_blocks()
      .block("LOOP")
      .insert("0", "1", "LOOP", 1, 1)
      .end_block()
      .begin_entities()
      .insert("X", "2", "LOOP", 0, 0);
  EXPECT_NE(refusal(dxf.text()).find("nested more than"), std::string::npos);
}

// A few vertices, inserted in blocks of blocks, are counted as placed: a fuzzed drawing's
// 16 KB placed hundreds of millions of them (7 s, 770 MB) under the cap on shapes.
TEST(DxfReaderTest, BlocksPlacingTooManyVerticesAreRefused) {
  std::vector<std::array<double, 3>> ring;
  for (int k = 0; k < 1000; ++k)
    ring.push_back({1000 * std::cos(k * 0.00628), 1000 * std::sin(k * 0.00628), 0});
  DxfText dxf;
  dxf.begin_blocks().block("RING").lwpolyline("0", "1", ring, true).end_block().block("ROW");
  for (int k = 0; k < 100; ++k)
    dxf.insert("0", fmt::format("{:X}", 0x100 + k), "RING", 3000 * k, 0);
  dxf.end_block().begin_entities();
  for (int k = 0; k < 30; ++k) dxf.insert("A", fmt::format("{:X}", 0x1000 + k), "ROW", 0, 3000 * k);
  // 3,000 shapes, 3,000,000 vertices.
  const std::string m = refusal(dxf.text());
  EXPECT_NE(m.find("or 2000000 vertices once its blocks are inserted"), std::string::npos) << m;
}

TEST(DxfReaderTest, RefusesWhatIsNotAnAsciiDxf) {
  EXPECT_NE(
      refusal(std::string("AutoCAD Binary DXF\r\n\x1a") + std::string(1, '\0')).find("binary DXF"),
      std::string::npos);
  EXPECT_NE(refusal("AC1032\0\0\0\0").find("DWG"), std::string::npos);
  EXPECT_NE(refusal("<svg></svg>").find("not a DXF"), std::string::npos);
  EXPECT_NE(refusal("").find("not a DXF"), std::string::npos);
  EXPECT_NE(refusal(std::string(kMostDrawingBytes + 1, ' ')).find("at most 64 MiB"),
            std::string::npos);
}

TEST(DxfReaderTest, RefusesShapesOffThePlane) {
  DxfText dxf;
  dxf.begin_entities_only().line("A-OTLN", "5F", 0, 0, 100, 0, 30);
  const std::string m = refusal(dxf.text());
  EXPECT_NE(m.find("LINE with handle 5F on layer \"A-OTLN\""), std::string::npos) << m;
  EXPECT_NE(m.find("plan's plane"), std::string::npos) << m;
}

TEST(DxfReaderTest, LayerNamesInWindows1252AreRead) {
  DxfText dxf;
  dxf.begin_entities_only().circle("Gr\xE8s", "1", 0, 0, 5).circle("Gr\\U+00E8s 2", "2", 0, 0, 5);
  const Drawing d = read_dxf(dxf.text(), "site.dxf", {});
  EXPECT_EQ(on(d, "Gr\xC3\xA8s").entity, "CIRCLE");
  EXPECT_EQ(on(d, "Gr\xC3\xA8s 2").entity, "CIRCLE");
}

TEST(DxfReaderTest, UnitCodes) {
  EXPECT_EQ(insunits_mm(1), 25.4);
  EXPECT_EQ(insunits_mm(2), 304.8);
  EXPECT_EQ(insunits_mm(4), 1);
  EXPECT_EQ(insunits_mm(5), 10);
  EXPECT_EQ(insunits_mm(6), 1000);
  EXPECT_EQ(insunits_mm(0), 0);
  EXPECT_EQ(insunits_mm(3), 0);  // miles: no site is drawn in them
}

}  // namespace
}  // namespace curdle::site
