// Tests of framed_sheet.h: a perforated sheet laid on a building's frame, rolled to an arc:
// closed, its metal's volume the sheet's at mid-thickness less its holes, within the rise of
// its strips from the arc; and its tiles placed on the chord across their openings.
#include "layout/framed_sheet.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <map>
#include <sstream>

#include "building_support.h"
#include "layout/framed_boxes.h"
#include "layout/piece.h"
#include "layout/zone.h"

namespace curdle {
namespace {

// An arc of radius 8 m from (0, 0) sweeping 60° anticlockwise (its centre at (0, 8000)), or a
// straight frame of the same length.
SurfaceFrame arc_frame(bool curved) {
  SurfaceFrame f;
  f.name = "SE";
  f.from = {0, 0};
  const double sweep = M_PI / 3;
  f.bulge = curved ? std::tan(sweep / 4) : 0;
  f.to = curved ? std::array<double, 2>{8000 * std::sin(sweep), 8000 - 8000 * std::cos(sweep)}
                : std::array<double, 2>{8000 * sweep, 0};
  f.length = 8000 * sweep;
  f.bent = curved;
  return f;
}

// The volume a mesh encloses (divergence theorem), mm³, and how many of its directed edges
// have no partner running the other way between the same points (0 for a closed solid).
struct Closure {
  double volume = 0;
  size_t open_edges = 0;
};
double enclosed_volume(const FramedMesh& m) {
  double volume = 0;
  for (size_t i = 0; i + 2 < m.indices.size(); i += 3) {
    const BuildingPoint &a = m.positions[m.indices[i]], &b = m.positions[m.indices[i + 1]],
                        &d = m.positions[m.indices[i + 2]];
    volume += (a[0] * (b[1] * d[2] - b[2] * d[1]) - a[1] * (b[0] * d[2] - b[2] * d[0]) +
               a[2] * (b[0] * d[1] - b[1] * d[0])) /
              6;
  }
  return volume;
}

Closure closure(const FramedMesh& m) {
  std::map<std::array<int64_t, 3>, size_t> at;
  std::vector<size_t> id;
  for (const BuildingPoint& p : m.positions)
    id.push_back(at.try_emplace({std::llround(p[0] * 1e6), std::llround(p[1] * 1e6),
                                 std::llround(p[2] * 1e6)},
                                at.size())
                     .first->second);
  std::map<std::pair<size_t, size_t>, int> edges;
  Closure c;
  for (size_t i = 0; i + 2 < m.indices.size(); i += 3) {
    const BuildingPoint &a = m.positions[m.indices[i]], &b = m.positions[m.indices[i + 1]],
                        &d = m.positions[m.indices[i + 2]];
    c.volume += (a[0] * (b[1] * d[2] - b[2] * d[1]) - a[1] * (b[0] * d[2] - b[2] * d[0]) +
                 a[2] * (b[0] * d[1] - b[1] * d[0])) /
                6;
    for (int k = 0; k < 3; ++k) ++edges[{id[m.indices[i + k]], id[m.indices[i + (k + 1) % 3]]}];
  }
  for (const auto& [e, n] : edges)
    if (edges.count({e.second, e.first}) == 0 || edges.at({e.second, e.first}) != n) ++c.open_edges;
  return c;
}

// A merged opening's ring (two overlapping circles' union, roughly), clockwise, at (x, y).
Ring merged_hole(double x, double y) {
  Ring ring;
  for (int k = 0; k < 40; ++k) {
    const double a = -2 * M_PI * k / 40;  // clockwise
    const double r = k < 20 ? 13 : 8;
    ring.push_back({x + r * std::cos(a), y + r * std::sin(a)});
  }
  return ring;
}

TEST(FramedSheet, ARolledSheetIsClosedAndHoldsItsMetalAtMidThickness) {
  for (const bool curved : {false, true}) {
    const SurfaceFrame f = arc_frame(curved);
    // A 1200 x 2400 mm sheet from 600 mm along, with three holes, two across a station.
    const Rect sheet{600, 0, 1200, 2400};
    std::vector<Ring> rings{rect_polygon(sheet), merged_hole(700, 300), merged_hole(1234.5, 1200),
                            merged_hole(1700, 2000)};
    FramedMesh mesh;
    add_framed_sheet(f, rings, {}, 3, mesh);
    const Closure c = closure(mesh);
    EXPECT_EQ(c.open_edges, 0u) << (curved ? "rolled" : "flat");
    double holes = 0;
    for (size_t i = 1; i < rings.size(); ++i) holes += polygon_area(rings[i]);
    // Rolled, the metal's area is the face's at mid-thickness: (R - t / 2) / R of the outer.
    const double mid = curved ? (8000 - 1.5) / 8000 : 1;
    const double expected = 3 * (sheet.area() - holes) * mid;
    // The strips lie inside the arc by at most their rise: a little less metal, never more.
    EXPECT_LE(c.volume, expected * (1 + 1e-9)) << (curved ? "rolled" : "flat");
    EXPECT_GT(c.volume, expected - 3 * 2400 * 1200 * kRolledSheetRise / 8000 * 2)
        << (curved ? "rolled" : "flat");
  }
}

TEST(FramedSheet, EveryCornerLiesOnTheArcOrWithinItsStripsRise) {
  const SurfaceFrame f = arc_frame(true);
  const std::vector<double> stations = roll_stations(f, 0, f.length, kRolledSheetRise);
  ASSERT_GT(stations.size(), 10u);
  const double step = stations[1] - stations[0];
  EXPECT_LE(step * step / (8 * 8000), kRolledSheetRise + 1e-12);  // a chord's rise
  FramedMesh mesh;
  add_framed_sheet(f, {rect_polygon(Rect{0, 0, f.length, 600})}, {}, 3, mesh);
  for (const BuildingPoint& p : mesh.positions) {
    const double r = std::hypot(p[0], p[1] - 8000);
    EXPECT_TRUE(std::fabs(r - 8000) < 1e-6 || std::fabs(r - 7997) < 1e-6) << r;
  }
}

TEST(FramedSheet, ATileStandsOnTheChordAcrossItsOpeningOnTheSheetsBack) {
  Layout l;
  l.envelope.emplace().frames = {arc_frame(true)};
  l.thickness = 3;
  Element e;
  e.form = ElementForm::opening;
  e.circle = Circle{4000, 1000, 26};
  const FramedPose pose = tile_pose(l, e);
  // Its front on the chord of the outer face across its square, its back 3 mm behind.
  const BuildingPoint a = frame_point(l.frames()[0], 4000 - 13, 1000, 0);
  const BuildingPoint b = frame_point(l.frames()[0], 4000 + 13, 1000, 0);
  const double len = std::hypot(b[0] - a[0], b[1] - a[1]);
  const std::array<double, 2> d{(b[0] - a[0]) / len, (b[1] - a[1]) / len};
  EXPECT_NEAR(pose.origin[0], (a[0] + b[0]) / 2 - 3 * d[1], 1e-9);
  EXPECT_NEAR(pose.origin[1], (a[1] + b[1]) / 2 + 3 * d[0], 1e-9);
  EXPECT_NEAR(pose.origin[2], 1000, 1e-12);
  EXPECT_NEAR(pose.along[0], d[0], 1e-12);
  EXPECT_NEAR(pose.along[1], d[1], 1e-12);
  // Its middle, as schedule.csv and the glb's node for it give it: on that chord's face.
  const BuildingPoint c = framed_centre(l, e);
  EXPECT_NEAR(c[0], (a[0] + b[0]) / 2, 1e-9);
  EXPECT_NEAR(c[1], (a[1] + b[1]) / 2, 1e-9);
  EXPECT_NEAR(c[2], 1000, 1e-9);
}

// Each sheet of the shipped curved screen, with its tiles, holds the metal punching.csv says it
// keeps: its area less its openings, at mid-thickness where it is rolled.
TEST(FramedSheet, TheCurvedScreensSheetsHoldTheMetalTheyAreOrderedWith) {
  std::ifstream in(std::string(CURDLE_SOURCE_DIR) + "/patterns/perforated-screen-curved.toml");
  std::stringstream text;
  text << in.rdbuf();
  const Layout l = test::lay_recipe(text.str());
  ASSERT_EQ(l.sheets().size(), 9u);
  const FramedScreen screen = framed_screen(l);
  std::vector<FramedMesh> meshes(l.sheets().size());
  for (size_t i = 0; i < l.elements.size(); ++i) {  // each tile where it stands, as written
    const Element& e = l.elements[i];
    const std::vector<size_t>& on_sheet = screen.tiled[static_cast<size_t>(e.sheet)];
    if (std::find(on_sheet.begin(), on_sheet.end(), i) == on_sheet.end()) continue;
    const OpeningTile tile = tile_of(l, e);
    std::vector<Vec3> p, n;
    std::vector<uint32_t> idx;
    add_caps(true, tile.triangles, 0, l.thickness, p, n, idx);
    add_walls(true, {tile.hole}, 0, l.thickness, p, n, idx);
    const FramedPose pose = tile_pose(l, e);
    const auto& [d0, d1] = pose.along;
    FramedMesh& m = meshes[static_cast<size_t>(e.sheet)];
    const auto first = static_cast<uint32_t>(m.positions.size());
    for (const Vec3& v : p) {
      const double x = v[0] * 1000.0, y = v[1] * 1000.0, z = v[2] * 1000.0;  // along, up, out
      m.positions.push_back(
          {pose.origin[0] + x * d0 + z * d1, pose.origin[1] + x * d1 - z * d0, pose.origin[2] + y});
    }
    for (const uint32_t k : idx) m.indices.push_back(first + k);
  }
  for (size_t k = 0; k < l.sheets().size(); ++k) {
    const FabricationSheet& s = l.sheets()[k];
    FramedMesh& mesh = meshes[k];
    add_framed_sheet(*frame_at(l.frames(), s.area.x + s.area.w / 2), screen.rings[k],
                     screen.squares[k], l.thickness, mesh);
    const double metal = enclosed_volume(mesh) / l.thickness;
    const double net = s.surface * (1 - s.open_area) * s.developed;
    // The openings' polygons lie inside their circles by at most the chord tolerance: at most
    // that much of each one's perimeter more metal; the strips lie inside the arc: a little less.
    double slack = 0;
    for (const Element& e : l.elements)
      if (e.sheet == static_cast<int>(k)) slack += M_PI * laid_bounds(e).w * l.chord_tolerance;
    EXPECT_GE(metal, net - 1e-5 * s.surface) << s.id;
    EXPECT_LE(metal, net + slack) << s.id;
    EXPECT_GT(slack, 0) << s.id;
  }
}

}  // namespace
}  // namespace curdle
