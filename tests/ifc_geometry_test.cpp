// The IFC model's geometry: circles as polygons with their extremes exact, a piece in parts as
// one composite profile, holes as clockwise voids, and profiles drawn from the product's own
// corner.
#include "export/ifc/ifc_geometry.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <sstream>

#include "layout/zone.h"

namespace curdle {
namespace {

TEST(IfcGeometry, ACircleRingHasItsExtremesExactlyAndStaysWithinTheTolerance) {
  const Circle c{100, 50, 20};
  const Ring ring = ifc_circle_ring(c, 0.05);
  double min_x = 1e9, max_x = -1e9, min_y = 1e9, max_y = -1e9;
  for (const auto& [x, y] : ring) {
    min_x = std::min(min_x, x), max_x = std::max(max_x, x);
    min_y = std::min(min_y, y), max_y = std::max(max_y, y);
    EXPECT_NEAR(std::hypot(x - 100, y - 50), 10, 1e-9);
  }
  EXPECT_EQ(min_x, 90);
  EXPECT_EQ(max_x, 110);
  EXPECT_EQ(min_y, 40);
  EXPECT_EQ(max_y, 60);
  EXPECT_GT(signed_area(ring), 0);  // counter-clockwise
  // No chord strays more than the tolerance inside the circle.
  const double half = 3.14159265358979323846 / static_cast<double>(ring.size());
  EXPECT_LE(10 * (1 - std::cos(half)), 0.05);
}

TEST(IfcGeometry, APieceInPartsIsOneCompositeProfileAndHolesRunClockwise) {
  std::ostringstream out;
  StepWriter w(out, "t.ifc", "IFC4", "ReferenceView_V1.2");
  IfcGeometryWriter g(w, 0.1);
  g.set_local_origin(10, 20);
  const Outline a{{rect_polygon({10, 20, 100, 50})}, 5000};
  const Outline b{{rect_polygon({200, 20, 100, 50})}, 5000};
  const int64_t profile = g.profile({a, b});
  g.profile_with_holes(rect_polygon({10, 20, 100, 50}), {rect_polygon({30, 30, 10, 10})});
  w.finish();
  const std::string text = out.str();
  std::string composite = "#";
  composite += std::to_string(profile);
  composite += "=IFCCOMPOSITEPROFILEDEF(.AREA.,$,(";
  EXPECT_NE(text.find(composite), std::string::npos);
  // Drawn from the product's corner (10, 20): the first part starts at the origin.
  EXPECT_NE(text.find("IFCCARTESIANPOINT((0.,0.))"), std::string::npos);
  EXPECT_NE(text.find("IFCCARTESIANPOINT((190.,0.))"), std::string::npos);
  // The hole (20, 10)-(30, 20) from the corner, clockwise and closed, as one list of points
  // (IfcIndexedPolyCurve), not a point entity for each corner.
  EXPECT_NE(text.find("=IFCCARTESIANPOINTLIST2D(((20.,20.),(30.,20.),(30.,10.),(20.,10.),"
                      "(20.,20.)));"),
            std::string::npos);
  EXPECT_EQ(text.find("IFCCARTESIANPOINT((30.,20.))"), std::string::npos);
  EXPECT_NE(text.find("=IFCINDEXEDPOLYCURVE(#"), std::string::npos);
  EXPECT_NE(text.find("IFCARBITRARYPROFILEDEFWITHVOIDS(.AREA.,$,"), std::string::npos);
}

TEST(IfcGeometry, AContourKeepsItsArcsAsArcIndicesThroughTheirMiddles) {
  std::ostringstream out;
  StepWriter w(out, "t.ifc", "IFC4", "ReferenceView_V1.2");
  IfcGeometryWriter g(w, 0.1);
  g.set_local_origin(10, 20);  // a contour is in the surface's own coordinates
  // A straight edge along x, and a half circle back over it, counter-clockwise.
  const int64_t curve = g.contour_curve({{0, 0, 0}, {100, 0, 1}});
  w.finish();
  const std::string text = out.str();
  const size_t list = text.find("=IFCCARTESIANPOINTLIST2D(((0.,0.),(100.,0.),(");
  ASSERT_NE(list, std::string::npos);
  // The third point is the arc's middle, (50, 50).
  const size_t middle = text.find("),(", list + 40) + 3;
  double x = 0, y = 0;
  ASSERT_EQ(std::sscanf(text.c_str() + middle, "%lf,%lf", &x, &y), 2);
  EXPECT_NEAR(x, 50, 1e-9);
  EXPECT_NEAR(y, 50, 1e-9);
  const std::string polycurve =
      "#" + std::to_string(curve) + "=IFCINDEXEDPOLYCURVE(#" +
      text.substr(text.rfind('#', list) + 1, list - text.rfind('#', list) - 1) +
      ",(IFCLINEINDEX((1,2)),IFCARCINDEX((2,3,1))),.F.);";
  EXPECT_NE(text.find(polycurve), std::string::npos) << text;
}

TEST(IfcGeometry, RingsOfOneShapeFromTheirCornersShareOnePolyline) {
  std::ostringstream out;
  StepWriter w(out, "t.ifc", "IFC4", "ReferenceView_V1.2");
  IfcGeometryWriter g(w, 0.1);
  const Ring ring = ifc_circle_ring(Circle{116, 216, 32}, 0.05);
  Ring moved = ring;
  for (auto& [x, y] : moved) x += 4000.1, y -= 1234.7;  // the same opening elsewhere
  g.set_local_origin(100, 200);
  const int64_t first = g.shared_polyline(ring);
  g.set_local_origin(4100.1, 200 - 1234.7);
  EXPECT_EQ(g.shared_polyline(moved), first);
  // Another shape, or the same one from another corner, is a polyline of its own.
  EXPECT_NE(g.shared_polyline(ifc_circle_ring(Circle{4116.1, 216 - 1234.7, 30}, 0.05)), first);
  g.set_local_origin(4000, 200 - 1234.7);
  EXPECT_NE(g.shared_polyline(moved), first);
  w.finish();
  size_t polylines = 0;
  for (size_t at = out.str().find("IFCPOLYLINE("); at != std::string::npos;
       at = out.str().find("IFCPOLYLINE(", at + 1))
    ++polylines;
  EXPECT_EQ(polylines, 3u);
}

}  // namespace
}  // namespace curdle
