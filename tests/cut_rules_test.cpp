// Fabrication rules a builder meets: slivers at every edge and the shift that avoids them, a
// façade's open area, punches for real tools, and each sheet's open area and hole counts.
#include "layout/cut_rules.h"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdio>
#include <map>
#include <optional>
#include <string>

#include "curdle/curdling.h"
#include "layout/builder.h"
#include "test_support.h"

namespace curdle {
namespace {

LayoutSpec facade_spec(const std::array<double, 2>& shift, double min_cut, double bond = 0) {
  LayoutSpec spec = test::layout_spec("facade");
  spec.module_w = 215, spec.module_h = 65, spec.joint = 10;
  spec.size = std::array<double, 2>{6000, 3000};
  spec.shift = shift;
  spec.bond = bond;
  spec.min_cut = {min_cut, min_cut};
  // A window whose head is 15 mm above a course and whose sides cut bricks near their ends.
  spec.own<FacadeKeys>().openings = {{1000, 900, 1200, 1475}, {4000, 0, 900, 2100}};
  return spec;
}

Layout facade(const std::array<double, 2>& shift, double min_cut, double bond = 0) {
  Design d = test::design(4, 2, {{"3/4", "1/2", "2/3"}});
  const LayoutSpec spec = facade_spec(shift, min_cut, bond);
  const auto cells = elements_to_cover(spec);
  d.field.size = {cells[0], cells[1], 1};
  const CurdField f = curdle(d, 5, d.field);
  return make_layout(d, f, d.field, spec);
}

// Every cut piece narrower than the rule, measured from its rectangles independently.
size_t slivers_of(const Layout& layout, double least) {
  size_t n = 0;
  for (const Element& e : layout.elements)
    if (e.cut && (narrowest_run(e.shape, true) < least - 1e-6 ||
                  narrowest_run(e.shape, false) < least - 1e-6))
      ++n;
  return n;
}

}  // namespace

TEST(CutRules, TheNarrowestRunIsTheThinnerLegHoweverThePieceIsSplit) {
  // An L: a 10 mm strip over a window beside a full-height leg, split two ways.
  const std::vector<Rect> across{{0, 290, 600, 10}, {300, 0, 300, 290}};
  const std::vector<Rect> down{{0, 290, 300, 10}, {300, 0, 300, 300}};
  for (const auto& piece : {across, down}) {
    EXPECT_NEAR(narrowest_run(piece, false), 10, 1e-9);  // the strip, measured up
    EXPECT_NEAR(narrowest_run(piece, true), 300, 1e-9);  // the leg, measured across
  }
  // A rectangle split into thin slices is as wide as the rectangle.
  EXPECT_NEAR(narrowest_run({{0, 0, 5, 100}, {5, 0, 5, 100}, {10, 0, 90, 100}}, true), 100, 1e-9);
}

TEST(CutRules, SliversAtOpeningsAreReportedAndTheAdvisedShiftLeavesFewer) {
  const Layout plain = facade({0, 0}, 50);
  const size_t found = slivers_of(plain, 50);
  ASSERT_GT(found, 0u);
  size_t reported = 0, at_openings = 0;
  for (const std::string& v : plain.violations) {
    reported += v.find("below 50.0 mm (layout.min_cut)") != std::string::npos;
    at_openings += v.find("at an opening") != std::string::npos;
  }
  EXPECT_EQ(reported, found);
  EXPECT_GT(at_openings, 0u);  // the window head's course, not only the wall's edges
  const LayoutSpec spec = facade_spec({0, 0}, 50);
  const ShiftAdvice x = best_shift(plain, spec, 0), y = best_shift(plain, spec, 1);
  EXPECT_LT(x.slivers + y.slivers, x.now + y.now);
  const Layout moved = facade({x.shift, y.shift}, 50);
  EXPECT_LT(slivers_of(moved, 50), found);
  bool advised = false;
  for (const std::string& note : plain.notes)
    advised |= note.find("layout.shift = [") != std::string::npos;
  EXPECT_TRUE(advised);
}

// The advice minimises cut pieces within the rule: no shift up the wall (the advised one across)
// leaves as few slivers with fewer cut bricks, and the note gives both counts, advised and now.
// It once took the first shift that cleared the slivers, whatever it cut (a whole course more
// on a brick façade: 887 cut bricks became 1228).
TEST(CutRules, TheAdvisedShiftCutsTheFewestPiecesTheRuleAllows) {
  // A window 920 mm up, 1465 mm high, with 20 mm the least cut: shifting the courses 20 mm up
  // is the first shift that clears its slivers (143 panels cut), 45 mm the one that clears
  // them with the fewest cuts (137).
  auto wall = [](double up) {
    Design d = test::design(4, 2, {{"3/4", "1/2", "2/3"}});
    LayoutSpec spec = facade_spec({0, up}, 20);
    spec.own<FacadeKeys>().openings = {{1000, 920, 1200, 1465}};
    const auto cells = elements_to_cover(spec);
    d.field.size = {cells[0], cells[1], 1};
    return std::pair{make_layout(d, curdle(d, 5, d.field), d.field, spec), spec};
  };
  auto cut = [](const Layout& l) {
    size_t n = 0;
    for (const Element& e : l.elements) n += e.cut ? 1 : 0;
    return n;
  };
  const auto [plain, spec] = wall(0);
  const ShiftAdvice y = best_shift(plain, spec, 1);
  const Layout advised = wall(y.shift).first;
  const std::pair<size_t, size_t> got{slivers_of(advised, 20), cut(advised)};
  for (int up = 0; up < 65; ++up) {  // every shift the recipe allows, below the panel's 65 mm
    const Layout other = wall(up).first;
    const std::pair<size_t, size_t> leaves{slivers_of(other, 20), cut(other)};
    ASSERT_FALSE(leaves < got) << "shift up " << up << " leaves " << leaves.first << " slivers and "
                               << leaves.second << " cut, the advice (" << y.shift << ") "
                               << got.first << " and " << got.second;
  }
  bool both = false;
  for (const std::string& note : plain.notes)
    both |= note.find("layout.shift = [0, " + fmt::format("{:g}", y.shift) + "]") !=
                std::string::npos &&
            note.find("cuts " + std::to_string(got.second) + " " + plain.element_type +
                      "s, against " + std::to_string(cut(plain)) + " now") != std::string::npos;
  EXPECT_TRUE(both) << ::testing::PrintToString(plain.notes);
}

// The slivers note of a layout, and the shift it advises (none: nullopt) with what it says that
// shift leaves.
struct SliverNote {
  std::string text;
  std::optional<std::array<double, 2>> shift;
  size_t leaves = 0;
};
SliverNote sliver_note(const Layout& layout) {
  SliverNote out;
  for (const std::string& note : layout.notes)
    if (note.find("narrower than") != std::string::npos) out.text = note;
  const size_t at = out.text.find("layout.shift = [");
  if (at == std::string::npos) return out;
  double x = 0, y = 0;
  char leaves[16] = {};
  EXPECT_EQ(
      std::sscanf(out.text.c_str() + at, "layout.shift = [%lf, %lf] leaves %15s", &x, &y, leaves),
      3);
  out.shift = std::array<double, 2>{x, y};
  out.leaves = std::string(leaves) == "none" ? 0 : std::stoul(leaves);
  return out;
}

// "lay specials or closers, 36 of 65 x 65 mm, 15 of 40 x 65 mm": the counts named.
size_t specials_named(const std::string& note) {
  size_t total = 0;
  for (size_t at = note.find(" of "); at != std::string::npos; at = note.find(" of ", at + 1)) {
    size_t start = at;
    while (start > 0 && std::isdigit(static_cast<unsigned char>(note[start - 1]))) --start;
    if (start < at) total += std::stoul(note.substr(start, at - start));
  }
  return total;
}

// The note promises only what laying the wall with its shift gives (a courtyard's note said a
// shift left 0 slivers and 5 remained), with or without a bond; what is left is named as
// specials, every one of them.
TEST(CutRules, TheAdvisedShiftLeavesWhatTheNoteSaysAndTheRestAreNamedAsSpecials) {
  for (const double bond : {0.0, 0.5}) {
    const Layout plain = facade({0, 0}, 50, bond);
    const SliverNote note = sliver_note(plain);
    ASSERT_FALSE(note.text.empty()) << bond;
    if (!note.shift) {
      EXPECT_NE(note.text.find("no shift of the grid leaves fewer"), std::string::npos);
      EXPECT_EQ(specials_named(note.text), slivers_of(plain, 50)) << note.text;
      continue;
    }
    const Layout moved = facade(*note.shift, 50, bond);
    EXPECT_EQ(slivers_of(moved, 50), note.leaves) << note.text;
    EXPECT_LT(note.leaves, slivers_of(plain, 50)) << note.text;
    if (note.leaves) {
      EXPECT_EQ(specials_named(note.text.substr(note.text.find("specials"))), note.leaves)
          << note.text;
    }
  }
}

// A 21 mm course over a window head is a sliver by default (a third of 65 mm is 21.7); min_cut
// can be set each way: 100 mm along the course and 10 mm up it lets it pass but not a 90 mm end.
TEST(CutRules, TheLeastCutIsGivenEachWayAndIsAThirdOfTheElementByDefault) {
  LayoutSpec spec = facade_spec({0, 0}, 0);
  EXPECT_NEAR(least_cut(spec, 0), 215.0 / 3, 1e-12);
  EXPECT_NEAR(least_cut(spec, 1), 65.0 / 3, 1e-12);
  spec.min_cut = {100, 10};
  EXPECT_EQ(least_cut(spec, 0), 100);
  EXPECT_EQ(least_cut(spec, 1), 10);
  Design d = test::design(4, 2, {{"3/4", "1/2", "2/3"}});
  const auto cells = elements_to_cover(spec);
  d.field.size = {cells[0], cells[1], 1};
  const Layout layout = make_layout(d, curdle(d, 5, d.field), d.field, spec);
  for (const std::string& v : layout.violations) {
    const bool wide = v.find("mm wide") != std::string::npos;
    EXPECT_NE(v.find(wide ? "below 100.0 mm" : "below 10.0 mm"), std::string::npos) << v;
  }
  EXPECT_FALSE(layout.violations.empty());
}

TEST(CutRules, AFacadeReportsTheShareItsOpeningsTake) {
  const Layout layout = facade({0, 0}, 0);
  EXPECT_NEAR(layout.open_area, (1200.0 * 1475 + 900.0 * 2100) / (6000.0 * 3000), 1e-12);
}

namespace {

Layout screen(Combine combine, std::vector<double> punches,
              std::optional<std::array<double, 2>> open_area, uint64_t seed) {
  const Design d = test::design(4, 2, {{"1/2", "1/2"}, {"1/2", "1/2"}, {"1/2", "1/2"}});
  LayoutSpec spec = test::layout_spec();
  spec.set_kind(layout_kind("perforation"));
  spec.combine = combine;
  spec.module_w = spec.module_h = 40;
  spec.size = std::array<double, 2>{640, 640};
  spec.own<PerforationKeys>().thickness = 2;
  // The third opening lies inside the first: their union is the first circle.
  spec.own<PerforationKeys>().holes = {{16, -7, 6}, {16, 7, 6}, {8, -7, 6}};
  spec.own<PerforationKeys>().punches = std::move(punches);
  spec.own<PerforationKeys>().open_area = open_area;
  spec.own<PerforationKeys>().sheet_size = std::array<double, 2>{300, 640};
  const CurdField f = curdle(d, seed, d.field);
  return make_layout(d, f, d.field, spec);
}

}  // namespace

TEST(CutRules, MergedOpeningsTakeTheNearestPunchByArea) {
  const std::vector<double> punches{8, 16, 20, 24};
  const Layout layout = screen(Combine::mix, punches, std::nullopt, 3);
  bool merged = false;
  for (const Element& e : layout.elements) {
    ASSERT_TRUE(e.circle) << e.id;
    EXPECT_TRUE(std::count(punches.begin(), punches.end(), e.circle->d)) << e.id;
    if (std::popcount(e.value) < 2 || (e.value & 3) != 3) continue;
    merged = true;
    // Two 16 mm openings and maybe an 8 mm one overlap: 22.6 or 24 mm exactly; 24 is nearest.
    EXPECT_EQ(e.circle->d, 24) << e.id;
  }
  EXPECT_TRUE(merged);
}

TEST(CutRules, AKeptUnionThatIsOneCircleStaysACircle) {
  const Layout layout = screen(Combine::keep, {}, std::nullopt, 3);
  bool inside = false;
  for (const Element& e : layout.elements) {
    if (e.value != 5) continue;  // the 16 mm opening and the 8 mm one inside it
    inside = true;
    ASSERT_TRUE(e.circle) << e.id;
    EXPECT_FALSE(e.outline) << e.id;
    EXPECT_EQ(e.circle->d, 16);
  }
  EXPECT_TRUE(inside);
}

TEST(CutRules, EachSheetReportsItsOpenAreaAndHoleCountsPerTool) {
  const Layout layout = screen(Combine::keep, {}, std::array<double, 2>{0.2, 0.3}, 4);
  ASSERT_EQ(layout.sheets().size(), 3u);  // 300 + 300 + 40 mm wide
  std::map<int, double> open;
  std::map<int, uint64_t> holes;
  for (const Element& e : layout.elements) open[e.sheet] += e.area(), ++holes[e.sheet];
  size_t outside = 0;
  for (size_t i = 0; i < layout.sheets().size(); ++i) {
    const auto& sheet = layout.sheets()[i];
    EXPECT_NEAR(sheet.open_area, open[static_cast<int>(i)] / sheet.area.area(), 1e-12);
    uint64_t counted = 0;
    for (const auto& [tool, n] : sheet.tools) counted += n;
    EXPECT_EQ(counted, holes[static_cast<int>(i)]) << sheet.id;
    outside += sheet.open_area < 0.2 || sheet.open_area > 0.3;
  }
  size_t reported = 0;
  for (const std::string& v : layout.violations)
    reported += v.find("outside layout.open_area") != std::string::npos;
  EXPECT_EQ(reported, outside);
  EXPECT_GT(outside, 0u);
}

}  // namespace curdle
