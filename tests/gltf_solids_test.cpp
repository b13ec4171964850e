// Solids in glTF coordinates: the axes a floor and a wall map to, and a prism's faces.
#include "layout/gltf_solids.h"

#include <gtest/gtest.h>

#include <cmath>

#include "kinds/registry.h"

namespace curdle {
namespace {

Layout laid(const char* kind) {
  Layout l;
  l.kind = &layout_kind(kind);
  return l;
}

TEST(GltfSolids, FloorsRunIntoMinusZAndWallsStandInXY) {
  const Vec3 floor = to_gltf(laid("paving"), 1000, 2000, 30);
  EXPECT_EQ(floor, (Vec3{1, 0.03f, -2}));
  const Vec3 wall = to_gltf(laid("facade"), 1000, 2000, 30);
  EXPECT_EQ(wall, (Vec3{1, 2, 0.03f}));
}

TEST(GltfSolids, APrismWithAHoleHasItsAreaOnEachCapAndWallsFacingOut) {
  const Layout l = laid("paving");
  // A 100 mm square with a 40 mm square hole (clockwise), 10 mm thick.
  const std::vector<Ring> rings{{{0, 0}, {100, 0}, {100, 100}, {0, 100}},
                                {{30, 30}, {30, 70}, {70, 70}, {70, 30}}};
  std::vector<Vec3> p, n;
  std::vector<uint32_t> idx;
  add_prism(l, rings, 0, 10, p, n, idx);
  ASSERT_EQ(idx.size() % 3, 0u);
  double up = 0, down = 0;
  for (size_t i = 0; i < idx.size(); i += 3) {
    const Vec3 &a = p[idx[i]], &b = p[idx[i + 1]], &c = p[idx[i + 2]];
    // The face's normal from its winding, against the normal its corners carry.
    const double ux = b[0] - a[0], uy = b[1] - a[1], uz = b[2] - a[2];
    const double vx = c[0] - a[0], vy = c[1] - a[1], vz = c[2] - a[2];
    const double nx = uy * vz - uz * vy, ny = uz * vx - ux * vz, nz = ux * vy - uy * vx;
    const Vec3& given = n[idx[i]];
    EXPECT_GT(nx * given[0] + ny * given[1] + nz * given[2], 0) << "wound as it faces";
    if (ny > 0) up += ny / 2;
    if (ny < 0) down -= ny / 2;
    // A wall faces away from the material: out of the square, into the hole.
    if (ny == 0) {
      const double cx = (a[0] + b[0] + c[0]) / 3, cz = (a[2] + b[2] + c[2]) / 3;
      const double away = (cx - 0.05) * given[0] + (cz + 0.05) * given[2];
      const bool in_hole = std::fabs(cx - 0.05) < 0.021 && std::fabs(cz + 0.05) < 0.021;
      EXPECT_TRUE(in_hole ? away < 0 : away > 0);
    }
  }
  EXPECT_NEAR(up, 0.01 - 0.0016, 1e-7);
  EXPECT_NEAR(down, 0.01 - 0.0016, 1e-7);
}

TEST(GltfSolids, ARoundHoleSharesItsWallCornersAndASquareKeepsItsOwn) {
  const Layout l = laid("paving");
  std::vector<Vec3> p, n;
  std::vector<uint32_t> idx;
  add_walls(l.kind->upright(), {{{0, 0}, {10, 0}, {10, 10}, {0, 10}}}, 0, 1, p, n, idx);
  EXPECT_EQ(p.size(), 16u) << "a square's corners turn 90 degrees: two pairs each";
  Ring round;
  for (int i = 0; i < 64; ++i)
    round.push_back({std::cos(i * 2 * M_PI / 64) * 10, std::sin(i * 2 * M_PI / 64) * 10});
  p.clear();
  n.clear();
  idx.clear();
  add_walls(l.kind->upright(), {round}, 0, 1, p, n, idx);
  EXPECT_EQ(p.size(), 128u) << "one pair a corner";
  EXPECT_EQ(idx.size(), 64u * 6);
}

}  // namespace
}  // namespace curdle
