// Laying patterns tile the surface: every point of it lies in exactly one unit or in a joint (no
// further from a unit than half the joint, or where joints cross, than half its diagonal), so that
// no two units overlap and no gap opens but the joints; the laid units' areas add up to the share
// of the surface they cover; each unit takes its own cell (a basketweave square's units one cell);
// and at every origin corner.
#include "layout/laying_pattern.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <random>
#include <set>

#include "layout/cell_placement.h"
#include "layout_support.h"

namespace curdle {
namespace {

bool in_rings(const std::vector<Ring>& rings, double x, double y) {
  bool in = false;
  for (const Ring& ring : rings) in = in != contains(ring, x, y);
  return in;
}

double distance_to_rings(const std::vector<Ring>& rings, double x, double y) {
  double best = 1e300;
  for (const Ring& ring : rings)
    for (size_t i = 0, j = ring.size() - 1; i < ring.size(); j = i++) {
      const double ax = ring[j][0], ay = ring[j][1], bx = ring[i][0], by = ring[i][1];
      const double dx = bx - ax, dy = by - ay, len = dx * dx + dy * dy;
      const double t = len > 0 ? std::clamp(((x - ax) * dx + (y - ay) * dy) / len, 0.0, 1.0) : 0;
      best = std::min(best, std::hypot(x - ax - t * dx, y - ay - t * dy));
    }
  return best;
}

struct Case {
  LayingPattern pattern;
  double length, width, joint;
};

class LayingPatterns : public ::testing::TestWithParam<std::tuple<Case, Corner>> {};

TEST_P(LayingPatterns, TileTheSurfaceWithJointsAndNoOverlap) {
  const auto& [c, corner] = GetParam();
  LayoutSpec spec = test::layout_spec();
  spec.set_kind(layout_kind("paving"));
  spec.pattern = c.pattern;
  spec.module_w = c.length, spec.module_h = c.width, spec.joint = c.joint;
  spec.origin = corner;
  const double W = 3210, H = 2370;
  spec.size = std::array<double, 2>{W, H};
  const Layout layout = lay_floor(design(2, 2, {{"3/4", "2/3", "1/2"}}), spec, 7);
  ASSERT_GT(layout.elements.size(), 100u);
  // Each unit its own cell; a basketweave square's units share one.
  std::map<std::pair<int64_t, int64_t>, int> per_cell;
  std::set<std::string> ids;
  double laid = 0;
  for (const Element& e : layout.elements) {
    ASSERT_TRUE(e.outline) << e.id;
    ++per_cell[{e.cell_x, e.cell_y}];
    EXPECT_TRUE(ids.insert(e.id).second) << e.id << " twice";
    laid += e.area();
  }
  const int per =
      c.pattern == LayingPattern::basketweave ? basketweave_units(c.length, c.width, c.joint) : 1;
  for (const auto& [cell, n] : per_cell) EXPECT_LE(n, per) << cell.first << "," << cell.second;
  // Points of the surface: in one unit, or within half a joint of one (a joint).
  std::mt19937_64 random(11);
  std::uniform_real_distribution<double> along(0, W), up(0, H);
  const int samples = 20000;
  int inside = 0, overlapping = 0, gaps = 0;
  for (int k = 0; k < samples; ++k) {
    const double x = along(random), y = up(random);
    int holding = 0;
    double nearest = 1e300;
    for (const Element& e : layout.elements) {
      const Rect& b = e.nominal;
      if (x < b.x - c.joint || x > b.right() + c.joint || y < b.y - c.joint ||
          y > b.top() + c.joint)
        continue;
      if (in_rings(e.outline->rings, x, y)) ++holding;
      nearest = std::min(nearest, distance_to_rings(e.outline->rings, x, y));
    }
    inside += holding == 1;
    overlapping += holding > 1;
    // In a joint: within half a joint of a unit, or where joints cross, of a unit's corner.
    gaps += holding == 0 && nearest > c.joint / std::sqrt(2.0) + 1e-6;
  }
  EXPECT_EQ(overlapping, 0) << "points in two units";
  EXPECT_EQ(gaps, 0) << "points further than half a joint from every unit";
  // The units' laid areas add up to the share of the surface the points found in them.
  EXPECT_NEAR(laid / (W * H), static_cast<double>(inside) / samples, 0.01);
  // A density field in millimetres reads each cell where its unit lies: within a unit (the
  // 90° herringbone's diagonal courses excepted), exactly for a basketweave square's middle.
  if (c.pattern == LayingPattern::herringbone) return;
  const CellPlacement placement = cell_placement(spec, layout.view);
  const double reach = c.pattern == LayingPattern::basketweave ? 1e-6 : c.length / 2 + c.joint;
  // Each cell's units laid whole, and the middle of them (a basketweave square's middle).
  std::map<std::pair<int64_t, int64_t>, std::array<double, 3>> middles;  // sum x, sum y, count
  for (const Element& e : layout.elements) {
    auto& m = middles[{e.cell_x, e.cell_y}];
    if (e.cut) m[2] = -1e9;  // a cell with a cut unit is left out
    m[0] += e.nominal.x + e.nominal.w / 2, m[1] += e.nominal.y + e.nominal.h / 2, m[2] += 1;
  }
  size_t far = 0, placed = 0;
  for (const auto& [cell, m] : middles) {
    if (m[2] != per) continue;
    const auto at = placement.centre({cell.first, cell.second, 0}, 2);
    ++placed;
    far += std::hypot(at[0] - m[0] / m[2], at[1] - m[1] / m[2]) > reach;
  }
  EXPECT_GT(placed, 50u);
  EXPECT_EQ(far, 0u) << "cells placed away from their units";
}

std::string name_of(const ::testing::TestParamInfo<std::tuple<Case, Corner>>& info) {
  const auto& [c, corner] = info.param;
  std::string name = std::string(pattern_name(c.pattern)) + "_" +
                     std::to_string(static_cast<int>(c.width)) + "_" +
                     std::to_string(static_cast<int>(corner));
  std::replace(name.begin(), name.end(), '-', '_');
  return name;
}

INSTANTIATE_TEST_SUITE_P(
    Patterns, LayingPatterns,
    ::testing::Combine(::testing::Values(Case{LayingPattern::herringbone, 200, 98.5, 3},
                                         Case{LayingPattern::herringbone_45, 200, 98.5, 3},
                                         Case{LayingPattern::basketweave, 200, 98, 4},
                                         Case{LayingPattern::basketweave, 210, 68, 3},
                                         Case{LayingPattern::hexagon, 300, 300, 4},
                                         Case{LayingPattern::hexagon_flat, 300, 300, 4}),
                       ::testing::Values(Corner::bottom_left, Corner::bottom_right,
                                         Corner::top_left, Corner::top_right)),
    name_of);

}  // namespace
}  // namespace curdle

namespace curdle {
namespace {

// A surface far too large for its units is refused before any unit is made, naming the limit.
TEST(LayingPattern, TooManyUnitsAreRefusedBeforeAnyIsMade) {
  try {
    pattern_units(LayingPattern::herringbone_45, 200, 98.5, 3, 1e7, 1e7);
    ADD_FAILURE() << "no error";
  } catch (const ResourceLimitError& e) {
    EXPECT_NE(std::string(e.what()).find("above the limit of 4194304"), std::string::npos)
        << e.what();
  }
  EXPECT_FALSE(pattern_units(LayingPattern::hexagon, 300, 300, 4, 60000, 40000).empty());
}

}  // namespace
}  // namespace curdle
