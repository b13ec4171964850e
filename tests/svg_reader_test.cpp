#include "site/svg_reader.h"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "layout/contour.h"

namespace curdle::site {
namespace {

std::string svg(
    const std::string& body,
    const std::string& size = "width=\"100mm\" height=\"50mm\" viewBox=\"0 0 100 50\"") {
  return "<?xml version=\"1.0\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\" "
         "xmlns:inkscape=\"http://www.inkscape.org/namespaces/inkscape\" "
         "xmlns:xlink=\"http://www.w3.org/1999/xlink\" " +
         size + ">\n" + body + "\n</svg>\n";
}

const Shape& on(const Drawing& d, const std::string& layer, size_t k = 0) {
  for (const Shape& s : d.shapes)
    if (on_layer(s, layer) && k-- == 0) return s;
  throw std::runtime_error("no shape on " + layer);
}

std::string refusal(const std::string& text) {
  try {
    read_svg(text, "site.svg", {});
  } catch (const InputError& e) {
    return e.what();
  }
  return "(read)";
}

TEST(SvgReaderTest, UnitsFromWidthOverViewBoxAndYTurnedUp) {
  // 100 mm wide over a viewBox 200 wide: a user unit is half a millimetre.
  const Drawing d = read_svg(svg("<g inkscape:groupmode=\"layer\" inkscape:label=\"A-OTLN\">"
                                 "<rect x=\"0\" y=\"0\" width=\"200\" height=\"20\"/></g>",
                                 "width=\"100mm\" height=\"50mm\" viewBox=\"0 0 200 100\""),
                             "site.svg", {});
  EXPECT_EQ(d.unit_mm, 1);
  const Shape& s = on(d, "A-OTLN");
  EXPECT_TRUE(s.closed);
  ASSERT_EQ(s.path.size(), 4u);
  // The rect's top-left (0, 0) is the page's top: 50 mm up from its bottom edge.
  EXPECT_NEAR(s.path[0].x, 0, 1e-12);
  EXPECT_NEAR(s.path[0].y, 50, 1e-12);
  EXPECT_NEAR(contour_area(s.path), 100 * 10, 1e-9);
}

TEST(SvgReaderTest, CircularArcsStayArcsThroughTransforms) {
  const Drawing d = read_svg(svg("<g id=\"PIT\" transform=\"translate(50 25) rotate(30) scale(2)\">"
                                 "<circle cx=\"0\" cy=\"0\" r=\"5\"/></g>"
                                 "<g id=\"EDGE\"><path d=\"M 10 40 A 20 20 0 0 1 30 40\"/></g>"),
                             "site.svg", {});
  const Shape& pit = on(d, "PIT");
  EXPECT_EQ(arc_count(pit.path), pit.path.size());  // every edge an arc
  EXPECT_NEAR(contour_area(pit.path), std::numbers::pi * 100, 1e-9);
  const Shape& edge = on(d, "EDGE");
  EXPECT_FALSE(edge.closed);
  ASSERT_EQ(edge.path.size(), 2u);
  const Arc a = arc_between(edge.path[0], edge.path[1]);
  EXPECT_NEAR(a.radius, 20, 1e-9);
  // Sweep flag 1 turns clockwise on the page (y down): with y up, the arc runs clockwise from
  // (10, 10) to (30, 10) and swells upwards, its centre below.
  EXPECT_LT(a.sweep, 0);
  EXPECT_LT(a.centre[1], 10);
}

TEST(SvgReaderTest, UnevenScalesAndBeziersAreFlattenedWithinTheTolerance) {
  const Drawing d = read_svg(svg("<g id=\"E\" transform=\"scale(2 1)\"><circle cx=\"10\" "
                                 "cy=\"10\" r=\"5\"/></g><path id=\"B\" d=\"M0 0 C 10 20 20 20 "
                                 "30 0\"/>"),
                             "site.svg", {0.01, 0});
  const Shape& e = on(d, "E");
  EXPECT_EQ(arc_count(e.path), 0u);
  EXPECT_NEAR(contour_area(e.path), std::numbers::pi * 10 * 5, 0.05 * 2 * std::numbers::pi * 10);
  for (const auto& v : e.path)  // on the ellipse (x - 20)²/100 + (y - 40)²/25 = 1
    EXPECT_NEAR(std::hypot((v.x - 20) / 10, (v.y - 40) / 5), 1, 1e-9);
  EXPECT_GT(on(d, "B").path.size(), 8u);
}

TEST(SvgReaderTest, LayersUseAndUnits) {
  const Drawing d = read_svg(
      svg("<defs><rect id=\"win\" width=\"10\" height=\"20\"/></defs>"
          "<g inkscape:groupmode=\"layer\" inkscape:label=\"A-GLAZ\" id=\"layer9\">"
          "<use xlink:href=\"#win\" x=\"5\" y=\"5\"/><use href=\"#win\" x=\"30\" y=\"5\"/></g>"
          "<polygon id=\"lone\" points=\"0,0 10,0 10,10\"/>",
          "width=\"400\" height=\"200\""),  // px: no units said
      "site.svg", {});
  EXPECT_EQ(d.unit_mm, 0);
  EXPECT_EQ(on(d, "A-GLAZ", 1).path[0].x, 30);
  EXPECT_EQ(on(d, "lone").entity, "polygon");
  // <defs> draws nothing of itself.
  size_t glazing = 0;
  for (const Shape& s : d.shapes) glazing += s.layer == "A-GLAZ";
  EXPECT_EQ(glazing, 2u);
}

TEST(SvgReaderTest, DrawingOnAfterACloseStartsAtTheSubpathsStart) {
  // After z the current point is the subpath's start: the line and the arc begin there.
  const Drawing d = read_svg(svg("<path id=\"P\" d=\"M10 10 H20 V20 z L 30 10 z A 5 5 0 0 1 20 "
                                 "10\"/>"),
                             "site.svg", {});
  ASSERT_EQ(d.shapes.size(), 3u);
  EXPECT_EQ(d.shapes[1].path.front().x, 10);
  EXPECT_EQ(d.shapes[1].path.front().y, 40);  // y 10 from the top of a 50 mm page
  EXPECT_EQ(d.shapes[2].path.front().x, 10);
  EXPECT_NE(d.shapes[2].path.front().bulge, 0);
}

TEST(SvgReaderTest, RefusesWhatIsNotASiteDrawing) {
  EXPECT_NE(refusal("0\nSECTION\n").find("not an SVG drawing"), std::string::npos);
  const std::string cut_short = refusal("<svg xmlns=\"http://www.w3.org/2000/svg\"><g>");
  EXPECT_NE(cut_short.find("not an SVG drawing"), std::string::npos);
  EXPECT_EQ(cut_short.find('\n'), std::string::npos)
      << cut_short;  // one line, libxml2's reason in it
  EXPECT_NE(refusal("<!DOCTYPE svg [<!ENTITY a \"aaaa\">]><svg/>").find("entities"),
            std::string::npos);
  std::string m = refusal(svg("<path id=\"bad\" d=\"M 0 0 L nan 4\"/>"));
  EXPECT_NE(m.find("<path> \"bad\" has path data curdle cannot read"), std::string::npos) << m;
  m = refusal(svg("<g transform=\"scale(0)\"><path d=\"M0 0 L1 1\"/></g>"));
  EXPECT_NE(m.find("flattens it to a line"), std::string::npos) << m;
  m = refusal(svg("<rect width=\"10%\" height=\"5\"/>"));
  EXPECT_NE(m.find("width=\"10%\""), std::string::npos) << m;
  std::string deep;
  for (int i = 0; i < 80; ++i) deep += "<g>";
  for (int i = 0; i < 80; ++i) deep += "</g>";
  EXPECT_NE(refusal(svg(deep)).find("more than 64 deep"), std::string::npos);
  m = refusal(svg("<g id=\"loop\"><use href=\"#loop\"/></g>"));
  EXPECT_NE(m.find("more than 16 deep"), std::string::npos) << m;
}

// Inkscape's layers are what Inkscape's Layers dialog shows: everything below a layer belongs
// to it whatever the inner groups' automatic ids, which still pick a part of it.
TEST(SvgReaderTest, InkscapeLayersHoldEverythingBelowThem) {
  const Drawing d =
      read_svg(svg("<g inkscape:groupmode=\"layer\" inkscape:label=\"L-PLNT-PITS\" id=\"layer2\">"
                   "<g id=\"g812\"><circle cx=\"10\" cy=\"10\" r=\"2\"/></g>"
                   "<g id=\"g900\"><g id=\"g901\"><circle cx=\"30\" cy=\"10\" r=\"2\"/></g></g>"
                   "<g inkscape:groupmode=\"layer\" inkscape:label=\"Sub\"><rect width=\"1\" "
                   "height=\"1\"/></g></g>"
                   "<g id=\"loose\"><rect id=\"r1\" x=\"50\" width=\"5\" height=\"5\"/></g>"),
               "site.svg", {});
  size_t pits = 0;
  for (const Shape& s : d.shapes) pits += s.layer == "L-PLNT-PITS";
  EXPECT_EQ(pits, 2u);
  EXPECT_EQ(on(d, "g900").path[0].x, 28);     // an inner group still picks its part
  EXPECT_EQ(on(d, "Sub").entity, "rect");     // a sublayer is a layer of its own
  EXPECT_EQ(on(d, kRootLayer).handle, "r1");  // outside every layer: "(root)"
}

// Without Inkscape's layers, the top-level groups are the layers (Illustrator's data-name).
TEST(SvgReaderTest, TopLevelGroupsAreLayersElsewhere) {
  const Drawing d =
      read_svg(svg("<g id=\"Layer_1\" data-name=\"Site boundary\"><g id=\"a\"><polygon "
                   "points=\"0,0 10,0 10,10\"/></g></g><g id=\"Pits\"><g id=\"b\"><circle cx=\"5\" "
                   "cy=\"5\" r=\"1\"/></g></g><rect id=\"alone\" width=\"1\" height=\"1\"/>"),
               "site.svg", {});
  EXPECT_EQ(d.shapes[0].layer, "Site boundary");
  EXPECT_EQ(d.shapes[1].layer, "Pits");
  EXPECT_EQ(d.shapes[2].layer, kRootLayer);
  EXPECT_EQ(on(d, "alone").layer, kRootLayer);
}

// A nested <svg> places its content by its x, y, width, height and viewBox.
TEST(SvgReaderTest, NestedViewportsScaleAndMove) {
  const Drawing d =
      read_svg(svg("<svg x=\"100\" y=\"0\" width=\"50\" height=\"50\" viewBox=\"0 0 10 10\">"
                   "<rect id=\"z\" width=\"10\" height=\"10\"/></svg>"),
               "site.svg", {});
  const Rect b = contour_bounds(on(d, "z").path);
  EXPECT_NEAR(b.w, 50, 1e-9);
  EXPECT_NEAR(b.x, 100, 1e-9);
}

// Uses of uses are counted as placed: 10 levels of ten <use> of an empty group place nothing
// ten billion times.
TEST(SvgReaderTest, UsesAreCountedAsTheyArePlaced) {
  std::string defs = "<g id=\"u0\"></g>";
  for (int level = 1; level <= 10; ++level) {
    defs += fmt::format("<g id=\"u{}\">", level);
    for (int k = 0; k < 10; ++k) defs += fmt::format("<use href=\"#u{}\"/>", level - 1);
    defs += "</g>";
  }
  try {
    read_svg(svg("<defs>" + defs + "</defs><use href=\"#u10\"/>"), "site.svg", {});
    ADD_FAILURE() << "read";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("through <use> more than"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace curdle::site
