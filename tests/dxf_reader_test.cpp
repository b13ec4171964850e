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
  } catch (const InputError& e) {
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
  EXPECT_NE(
      m.find("or 2000000 vertices (or 1000000 block placements) once its blocks are inserted"),
      std::string::npos)
      << m;
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

// A shape off the plan's plane is a fault of its layer (site.cpp refuses it where the recipe
// names the layer), so that a 3-D detail on a layer of its own does not stop the drawing.
TEST(DxfReaderTest, ShapesOffThePlaneAreFaultsOfTheirLayer) {
  DxfText dxf;
  dxf.begin_entities_only().line("A-OTLN", "5F", 0, 0, 100, 0, 30).circle("PIT", "60", 0, 0, 5);
  const Drawing d = read_dxf(dxf.text(), "site.dxf", {});
  const std::string& m = on(d, "A-OTLN").fault;
  EXPECT_NE(m.find("LINE with handle 5F on layer \"A-OTLN\" does not lie in the plan's plane"),
            std::string::npos)
      << m;
  EXPECT_TRUE(on(d, "PIT").fault.empty());
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

TEST(DxfReaderTest, NumbersAreReadStrictly) {
  for (const char* bad : {"1,5", " 1 2", "1.#QNAN", "nan", "inf", "0x10"}) {
    const std::string text = fmt::format(
        "0\nSECTION\n2\nENTITIES\n0\nLINE\n5\n7A\n8\nA\n10\n{}\n20\n0\n11\n5\n21\n5\n"
        "0\nENDSEC\n0\nEOF\n",
        bad);
    const std::string m = refusal(text);
    EXPECT_NE(m.find("line 12: the LINE 7A has"), std::string::npos) << bad << ": " << m;
  }
  // A group code that is no whole number is named by its line.
  EXPECT_NE(refusal("0\nSECTION\n2\nENTITIES\n1O\nLINE\n").find("line 5 should be a group code"),
            std::string::npos);
  // A line longer than any DXF's is refused, not read for ever.
  const std::string m = refusal("0\nSECTION\n2\nENTITIES\n999\n" + std::string(70000, 'x') + "\n");
  EXPECT_NE(m.find("line 6 is 70000 characters long"), std::string::npos) << m;
}

TEST(DxfReaderTest, WidePolylinesAreTheStripsTheyCover) {
  DxfText dxf;
  dxf.begin_entities_only().lwpolyline("C-DRAN", "40", {{0, 0, 0}, {1000, 0, 0}, {1000, 500, 0}},
                                       false, 1, 150);
  const Drawing d = read_dxf(dxf.text(), "site.dxf", {});
  const Shape& s = on(d, "C-DRAN");
  EXPECT_FALSE(s.closed);
  ASSERT_FALSE(s.strip.empty());
  // An L of 1,000 and 500 along its centre line, 150 wide, mitred at the corner.
  EXPECT_NEAR(contour_area(s.strip), 150.0 * 1500, 1e-6);
  const Rect b = contour_bounds(s.strip);
  EXPECT_NEAR(b.x, 0, 1e-9);
  EXPECT_NEAR(b.y, -75, 1e-9);
  EXPECT_NEAR(b.right(), 1075, 1e-9);
  EXPECT_NEAR(b.top(), 500, 1e-9);
}

TEST(DxfReaderTest, SplinesByFitPointsRunThroughThem) {
  // A quarter circle's five points: the interpolating cubic runs through each and stays close
  // to the circle between them (chords through the fit points would cut up to 7.6 inside).
  const std::string text =
      "0\nSECTION\n2\nENTITIES\n0\nSPLINE\n5\n51\n8\nEDGE\n70\n8\n71\n3\n72\n0\n73\n0\n"
      "74\n5\n11\n1000\n21\n0\n31\n0\n11\n923.88\n21\n382.68\n31\n0\n11\n707.11\n21\n"
      "707.11\n31\n0\n11\n382.68\n21\n923.88\n31\n0\n11\n0\n21\n1000\n31\n0\n"
      "0\nENDSEC\n0\nEOF\n";
  const Drawing d = read_dxf(text, "site.dxf", {0.05, 0});
  const Shape& s = on(d, "EDGE");
  ASSERT_GT(s.path.size(), 20u);
  EXPECT_NEAR(s.path.front().x, 1000, 1e-9);
  EXPECT_NEAR(s.path.back().y, 1000, 1e-9);
  for (const ContourVertex& v : s.path) EXPECT_NEAR(std::hypot(v.x, v.y), 1000, 2.0);
  EXPECT_NE(d.notes.front().find("1 splines given by fit points"), std::string::npos);
}

TEST(DxfReaderTest, HatchBoundariesAreClosedShapes) {
  const std::string text =
      "0\nSECTION\n2\nENTITIES\n0\nHATCH\n5\n60\n8\nL-PAVE\n10\n0\n20\n0\n30\n0\n"
      "2\nSOLID\n70\n1\n71\n0\n91\n2\n"
      // A polyline path: a 100 square.
      "92\n3\n72\n0\n73\n1\n93\n4\n10\n0\n20\n0\n10\n100\n20\n0\n10\n100\n20\n100\n"
      "10\n0\n20\n100\n97\n0\n"
      // An edge path: a circle of radius 10 as one arc edge.
      "92\n1\n93\n1\n72\n2\n10\n300\n20\n0\n40\n10\n50\n0\n51\n360\n73\n1\n97\n0\n"
      "75\n0\n76\n1\n98\n0\n0\nENDSEC\n0\nEOF\n";
  const Drawing d = read_dxf(text, "site.dxf", {});
  EXPECT_NEAR(contour_area(on(d, "L-PAVE", 0).path), 10000, 1e-9);
  EXPECT_NEAR(contour_area(on(d, "L-PAVE", 1).path), 3.14159265358979323846 * 100, 1e-9);
  EXPECT_TRUE(on(d, "L-PAVE", 1).closed);
}

TEST(DxfReaderTest, MirroredBlockInsertsArePlacedInThePlan) {
  DxfText dxf;
  dxf.begin_blocks()
      .block("PIT")
      .lwpolyline("0", "20", {{0, 0, 0}, {100, 0, 0}, {100, 50, 0}}, true)
      .end_block()
      .begin_entities()
      .insert("L-PLNT-PITS", "30", "PIT", 1000, 0, 1, 1, 0, -1);
  const Drawing d = read_dxf(dxf.text(), "site.dxf", {});
  const Shape& s = on(d, "L-PLNT-PITS");
  // Seen from below, (1000, 0) in the insert's system is (-1000, 0) in the plan, and x runs left.
  EXPECT_NEAR(s.path[1].x, -1100, 1e-9);
  EXPECT_EQ(s.block, "PIT");
  EXPECT_EQ(s.insert_handle, "30");
}

// A name with control characters (an ESC sequence that would clear a terminal) is shown
// escaped wherever it is printed.
TEST(DxfReaderTest, ControlCharactersInNamesAreShownEscaped) {
  DxfText dxf;
  dxf.begin_entities_only().circle("X\x1b[2J\x07", "1", 0, 0, 5);
  const Drawing d = read_dxf(dxf.text(), "site.dxf", {});
  EXPECT_EQ(d.shapes.at(0).layer, "X\\x1B[2J\\x07");
}

}  // namespace
}  // namespace curdle::site
