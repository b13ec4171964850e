// Tests of envelope_layout.h: the pavilion laid from a recipe as one curd round its envelope;
// courses level all round, each corner unit one piece counted once, the layout's frames its
// façades, the corners' places on the stage grid reported; and the continuity of tone across
// every corner (the closing one too) no less than across random lines of the strip.
#include "building/envelope_layout.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>

#include "building/run_fill.h"
#include "building_support.h"
#include "curdle/density.h"
#include "curdle/overlay.h"
#include "kinds/facade.h"
#include "layout/piece_rows.h"

namespace curdle {
namespace {

TEST(EnvelopeLayout, CoursesAreLevelAndEachCornerUnitIsOnePieceCountedOnce) {
  const Layout l = test::lay_recipe(test::pavilion_recipe());
  ASSERT_EQ(l.frames().size(), 6u);
  EXPECT_TRUE(l.envelope->closed);
  EXPECT_DOUBLE_EQ(l.width, 64000);
  EXPECT_DOUBLE_EQ(l.thickness, 102.5);
  std::map<int, int> corner_units;
  uint64_t counted = 0;
  for (const Element& e : l.elements) {
    EXPECT_DOUBLE_EQ(e.nominal.y, 75.0 * static_cast<double>(e.row)) << e.id;
    for (const Rect& r : e.shape) EXPECT_DOUBLE_EQ(r.y, e.nominal.y) << e.id;
    if (e.corner >= 0) ++corner_units[e.corner];
  }
  for (const LegendEntry& v : l.legend) counted += v.count;
  EXPECT_EQ(counted, l.elements.size());
  ASSERT_EQ(corner_units.size(), 6u);
  for (const auto& [corner, n] : corner_units) EXPECT_EQ(n, 94) << "corner " << corner;
  // The closing corner's unit lies in two parts on the strip: its end and its start.
  for (const Element& e : l.elements)
    if (e.corner == 5) {
      ASSERT_EQ(e.shape.size(), 2u);
      EXPECT_DOUBLE_EQ(e.shape[0].right(), 64000);
      EXPECT_DOUBLE_EQ(e.shape[1].x, 0);
    }
  size_t placed = 0;
  for (const std::string& n : l.notes) placed += n.rfind("corner at the end of", 0) == 0;
  EXPECT_EQ(placed, 6u);
}

// Round the building the field is a ring of 9 root cells of 32 cells, each 64000 / 288 mm of
// the strip, turned by its phase: a unit takes the cell under the middle of its face.
TEST(EnvelopeLayout, EachUnitTakesTheValueOfTheCellUnderTheMiddleOfItsFace) {
  const Recipe r = parse_recipe(test::pavilion_recipe(), "pavilion.toml");
  const Design& d = r.design;
  ASSERT_EQ(d.field.size[0], 288);
  const CurdField field = curdle(d, r.seed, d.field);
  const std::vector<uint16_t> values = values_in(field, d.field);
  const Layout l = make_layout(d, field, d.field, *r.layout);
  const int64_t phase = r.layout->own<FacadeKeys>().ring->phase;
  for (const Element& e : l.elements) {
    const double middle = wrap_along(e.nominal.x + e.nominal.w / 2, l.width);
    const int64_t column = (static_cast<int64_t>(middle / (64000.0 / 288)) + phase) % 288;
    ASSERT_EQ(e.cell_x, column) << e.id;
    ASSERT_EQ(e.cell_y, e.row) << e.id;
    ASSERT_EQ(e.value, values[static_cast<size_t>(e.row * d.field.size[0] + column)]) << e.id;
  }
}

TEST(EnvelopeLayout, OpeningsCutTheUnitsAndNoUnitLiesInOne) {
  const Layout l = test::lay_recipe(test::pavilion_recipe(R"([[layout.building.openings]]
facade = "S"
rect = [9400, 0, 1200, 2400]
type = "door"
)"));
  ASSERT_EQ(l.openings.size(), 1u);
  double laid = 0;
  for (const Element& e : l.elements)
    for (const Rect& r : e.shape) {
      EXPECT_FALSE(overlaps(r, l.openings[0])) << e.id;
      laid += r.area();
    }
  // Units and their joints cover the strip but for the door: joints are 10 of every 75 mm up
  // and of every 225 mm along (one per unit, the corners' included).
  const double faces = 64000.0 * 7050 - 1200.0 * 2400;
  EXPECT_NEAR(laid / faces, 65.0 / 75 * 215 / 225, 0.01);
}

TEST(EnvelopeLayout, AFacadeLowerThanTheWallHasNoUnitsAboveItsOwnTop) {
  // The bite's two walls one storey high, the rest two.
  const Layout l =
      test::lay_recipe(test::pavilion_recipe("heights = [7050, 7050, 3525, 3525, 7050, 7050]\n"));
  ASSERT_EQ(l.frames()[2].height, 3525);
  EXPECT_EQ(l.frames()[1].height, 0);  // as tall as the wall
  size_t above = 0;
  for (const Element& e : l.elements)
    for (const Rect& r : e.shape) {
      const SurfaceFrame* f = frame_at(l.frames(), r.x + r.w / 2);
      if (f->height > 0) {
        EXPECT_LE(r.top(), f->height + 1e-9) << e.id;
      }
      above += f == &l.frames()[1] && r.y >= 3525;
    }
  EXPECT_GT(above, 0u);  // the east wall goes on up beside the bite's roof
}

// The value of the unit whose face covers the point `u` mm along the strip in each course (-1
// where an opening or nothing covers it), taken round the strip.
std::vector<std::vector<std::pair<Rect, uint16_t>>> courses_of(const Layout& l) {
  std::vector<std::vector<std::pair<Rect, uint16_t>>> courses;
  for (const Element& e : l.elements) {
    if (static_cast<size_t>(e.row) >= courses.size())
      courses.resize(static_cast<size_t>(e.row) + 1);
    for (const Rect& r : e.shape) courses[static_cast<size_t>(e.row)].push_back({r, e.value});
  }
  return courses;
}

int value_at(const std::vector<std::pair<Rect, uint16_t>>& course, double u) {
  for (const auto& [r, v] : course)
    if (u >= r.x && u < r.right()) return v;
  return -1;
}

// The share of courses whose units 150 mm either side of `u` hold the same value.
double agreement(const std::vector<std::vector<std::pair<Rect, uint16_t>>>& courses, double u,
                 double length) {
  int same = 0, pairs = 0;
  for (const auto& course : courses) {
    const int a = value_at(course, std::fmod(u - 150 + length, length));
    const int b = value_at(course, std::fmod(u + 150, length));
    if (a < 0 || b < 0) continue;
    ++pairs, same += a == b;
  }
  return pairs ? static_cast<double>(same) / pairs : 0;
}

// The issue's test of the seam: over 8 seeds, the agreement of the bricks 150 mm either side of
// each corner, the closing one too, is not below the agreement across random vertical lines of
// the strip less 4 standard errors. With the closing seam where two root cells met it was 0.634
// against about 0.76 across random lines.
TEST(EnvelopeLayout, ToneContinuesRoundEveryCornerAsAcrossAnyLine) {
  const std::string recipe = test::pavilion_recipe();
  const Layout probe = test::lay_recipe(recipe);
  const double length = probe.width;
  std::vector<double> corners;
  for (const SurfaceFrame& f : probe.frames()) corners.push_back(f.start + f.length);
  std::vector<double> lines;  // random vertical lines, the same for every seed
  uint64_t state = 12345;
  for (int k = 0; k < 200; ++k) {
    state = state * 6364136223846793005ull + 1442695040888963407ull;
    lines.push_back(static_cast<double>(state >> 11) / 9007199254740992.0 * length);
  }
  const int seeds = 8;
  std::vector<double> corner_sum(corners.size()), corner_sq(corners.size());
  double line_sum = 0, line_sq = 0;
  for (int s = 1; s <= seeds; ++s) {
    const auto courses = courses_of(test::lay_recipe(recipe, static_cast<uint64_t>(s)));
    for (size_t c = 0; c < corners.size(); ++c) {
      const double a = agreement(courses, corners[c], length);
      corner_sum[c] += a, corner_sq[c] += a * a;
    }
    double mean = 0;
    for (double u : lines)
      mean += agreement(courses, u, length) / static_cast<double>(lines.size());
    line_sum += mean, line_sq += mean * mean;
  }
  const double line_mean = line_sum / seeds;
  const double line_var = line_sq / seeds - line_mean * line_mean;
  for (size_t c = 0; c < corners.size(); ++c) {
    const double mean = corner_sum[c] / seeds;
    const double var = corner_sq[c] / seeds - mean * mean;
    const double se = std::sqrt(std::max(0.0, var + line_var) / seeds);
    EXPECT_GE(mean, line_mean - 4 * se)
        << probe.frames()[c].name << " corner: " << mean << " across it, " << line_mean
        << " across random lines (standard error " << se << ")";
  }
}

// layout.building.phase turns the ring by hand, within it; a field the recipe sizes itself
// takes no phase.
TEST(EnvelopeLayout, APhaseGivenTurnsTheRing) {
  const Recipe r = parse_recipe(test::pavilion_recipe("phase = 7\n"), "pavilion.toml");
  EXPECT_EQ(r.layout->own<FacadeKeys>().ring->phase, 7);
  auto refused = [](const std::string& text, const std::string& said) {
    try {
      parse_recipe(text, "pavilion.toml");
      ADD_FAILURE() << "accepted: " << text;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(said), std::string::npos) << e.what();
    }
  };
  refused(test::pavilion_recipe("phase = 288\n"), "from 0 to 287");
  // A root cell of 729 cells round a strip of 284 units would shrink the curd's clusters to
  // units 88 mm long: laid a cell a unit instead, its seam as before.
  std::string coarse = test::pavilion_recipe();
  coarse.replace(coarse.find("base = 2"), 8, "base = 3");
  coarse.insert(coarse.find("\"7/8\""), "\"9/10\", ");
  const Recipe wide = parse_recipe(coarse, "pavilion.toml");
  EXPECT_FALSE(wide.layout->own<FacadeKeys>().ring.has_value());
  refused(test::pavilion_recipe("phase = 3\n", "[field]\ncells = [400, 94]\n"),
          "turns the field round the building");
}

// No schedule row spans the strip's two ends: the closing quoin is one brick, no wider than a
// stretcher, a joint and a header (it was a box 64,000 mm wide).
TEST(EnvelopeLayout, NoScheduleRowIsWiderThanAQuoin) {
  const Layout l = test::lay_recipe(test::pavilion_recipe());
  size_t closing = 0;
  for (size_t i = 0; i < l.elements.size(); ++i) {
    const ScheduleRow row = schedule_row(l, i);
    EXPECT_LE(row.width, 215 + 10 + 102.5 + 1e-6) << row.id;
    closing += l.elements[i].corner == 5;
  }
  EXPECT_EQ(closing, 94u);
}

// The curved garden wall (12 m radius, 18 m, 2.4 m, a gate): its chords leave each course a
// fraction of a millimetre off whole pitches, taken up in the joints. No closer takes up less
// than the joints' tolerance (kJointTolerance, 2 mm over a run): no cut within 2 mm of a whole
// unit, and no two halves side by side that stand for a unit and less than 2 mm.
TEST(EnvelopeLayout, TheCurvedGardenWallHasNoCloserALaidJointWouldTakeUp) {
  const Layout l = test::lay_recipe(test::building_recipe(
      "panel = [215, 65]\njoint = 10\n",
      "path = [[0, 0, 0.393626], [16359.31, 0]]\nheight = 2400\n"
      "[[layout.building.openings]]\nfacade = 0\nrect = [8400, 0, 1200, 2100]\ntype = \"door\"\n"));
  std::map<int64_t, std::vector<std::pair<double, double>>> cuts;  // by course: strip x, width
  size_t laid = 0;
  for (size_t i = 0; i < l.elements.size(); ++i) {
    const ScheduleRow row = schedule_row(l, i);
    ++laid;
    if (row.width > 215 - 1e-6) continue;
    EXPECT_GT(215 - row.width, kJointTolerance) << row.id << " " << row.width;
    cuts[l.elements[i].row].push_back({*row.strip_x, row.width});
  }
  EXPECT_GT(laid, 2000u);
  size_t courses_with_cuts = 0;
  for (auto& [course, pieces] : cuts) {
    ++courses_with_cuts;
    std::sort(pieces.begin(), pieces.end());
    for (size_t k = 1; k < pieces.size(); ++k) {
      const auto [x0, w0] = pieces[k - 1];
      const auto [x1, w1] = pieces[k];
      if (std::fabs(x0 + w0 + 10 - x1) > 0.5) continue;  // not side by side
      // Two halves stand for a unit and what the run has over whole units: a cut of w0 + w1 -
      // 215 beside it, or a gap of w0 + 10 + w1 - 215 after it.
      EXPECT_GT(std::min(std::fabs(w0 + w1 - 215), std::fabs(w0 + 10 + w1 - 215)), kJointTolerance)
          << "course " << course << " at " << x0 << ": " << w0 << " + " << w1;
    }
  }
  // The 28 courses beside the gate, and of the four above it the two with half bats at their
  // stopped ends; the other two are whole bricks, their joints taking up 9.97 mm over 18 m.
  EXPECT_EQ(courses_with_cuts, 30u);
}

// Round the pavilion's ring a density field in millimetres lies where it says: the cell a unit
// takes its value from is placed under the unit's middle (taken round the building), whatever
// the ring's phase, so that a field centred on the closing corner reaches both sides of it.
TEST(EnvelopeLayout, ADensityFieldInMillimetresFollowsTheTurnedRing) {
  const Recipe r = parse_recipe(test::pavilion_recipe("phase = 13\n"), "pavilion.toml");
  const Design& d = r.design;
  const Layout l = make_layout(d, curdle(d, r.seed, d.field), d.field, *r.layout);
  const CellPlacement p = r.layout->kind->cell_placement(*r.layout, d.field);
  ASSERT_NEAR(p.period, 64000, 1e-6);
  const double cell = p.scale[0];
  for (const Element& e : l.elements) {
    const std::array<double, 3> at = p.centre({e.cell_x, e.cell_y, 0}, 2);
    const double middle = wrap_along((e.nominal.x + e.nominal.right()) / 2, 64000);
    double off = std::fabs(at[0] - middle);
    off = std::min(off, 64000 - off);
    ASSERT_LE(off, cell / 2 + 1e-6) << e.id << " at " << middle << ", its cell at " << at[0];
  }
  // A radial field at the closing corner thins both sides of it alike.
  DensityField f;
  f.kind = DensityKind::radial, f.dimension = 2, f.centre = {0, 3525, 0}, f.radius = 3000;
  f.values = {0, 1};
  f.placement = p;
  const auto near_corner = [&](double u) {
    const int64_t column = static_cast<int64_t>(std::floor(wrap_along(u, 64000) / cell + 13)) %
                           static_cast<int64_t>(std::llround(64000 / cell));
    return f.at_cell({column, 47, 0});
  };
  EXPECT_NEAR(near_corner(-500), near_corner(500), 0.1);
  EXPECT_LT(near_corner(-500), 0.3);
}

}  // namespace
}  // namespace curdle
