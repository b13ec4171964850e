// Tests of run_fill.h: each fill covers its run with one joint between pieces and no cut under
// the narrowest allowed; on a phase every whole unit starts on it, a closer too narrow taken
// with its neighbour as two halves; in a bond's order each end follows its order (a queen
// closer, then headers), the cut in the middle.
#include "building/run_fill.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace curdle {
namespace {

constexpr double kL = 215, kJ = 10, kMinCut = 215.0 / 3;

struct Filled {
  std::vector<CourseUnit> units;
  bool sliver = false;
  RunFill fill() {
    RunFill f;
    f.l = kL, f.j = kJ, f.min_cut = kMinCut, f.out = &units, f.sliver = &sliver;
    return f;
  }
};

// Pieces in order along the run, one joint apart, from s to e.
void expect_covers(std::vector<CourseUnit> units, double s, double e, double narrowest) {
  std::sort(units.begin(), units.end(),
            [](const CourseUnit& a, const CourseUnit& b) { return a.from < b.from; });
  ASSERT_FALSE(units.empty());
  EXPECT_NEAR(units.front().from, s, 1e-9);
  EXPECT_NEAR(units.back().to, e, 1e-9);
  for (size_t k = 0; k < units.size(); ++k) {
    EXPECT_GE(units[k].to - units[k].from, narrowest - 1e-9) << "piece " << k;
    EXPECT_LE(units[k].to - units[k].from, kL + 1e-9) << "piece " << k;
    if (k > 0) {
      EXPECT_NEAR(units[k].from - units[k - 1].to, kJ, 1e-9) << "piece " << k;
    }
  }
}

TEST(RunFill, OnAPhaseWholeUnitsStartOnItAndANarrowCloserIsTakenWithItsNeighbour) {
  for (double phase : {0.0, 56.25, 75.0, 112.5, 150.0, 168.75}) {
    for (double e : {1000.0, 2000.0, 2345.0}) {
      Filled f;
      fill_on_phase(f.fill(), 0, e, phase);
      expect_covers(f.units, 0, e, kMinCut);
      EXPECT_FALSE(f.sliver);
      for (const CourseUnit& u : f.units)
        if (u.role == UnitRole::stretcher) {
          const double off = std::fmod(u.from - phase + 10 * (kL + kJ), kL + kJ);
          EXPECT_TRUE(off < 1e-6 || off > kL + kJ - 1e-6) << phase << " " << u.from;
        }
    }
  }
  // Phase 75 over [0, 2000]: a 65 mm closer would lead, so the first unit and it are two
  // halves of 140 mm.
  Filled f;
  fill_on_phase(f.fill(), 0, 2000, 75);
  std::sort(f.units.begin(), f.units.end(),
            [](const CourseUnit& a, const CourseUnit& b) { return a.from < b.from; });
  EXPECT_NEAR(f.units[0].to - f.units[0].from, 140, 1e-9);
  EXPECT_NEAR(f.units[1].to - f.units[1].from, 140, 1e-9);
  EXPECT_NEAR(f.units[2].from, 300, 1e-9);
}

TEST(RunFill, InABondsOrderEachEndFollowsItAndTheCutIsInTheMiddle) {
  const BondPiece S{kL, UnitRole::stretcher, 0}, H{102.5, UnitRole::header, kL};
  const BondPiece Q{46.25, UnitRole::closer, kL};
  for (double e : {1000.0, 1500.0, 2222.0, 3000.0}) {
    Filled f;  // an English header course between two corners
    fill_in_order(f.fill(), 0, e, {{Q}, {H}}, {{Q}, {H}});
    expect_covers(f.units, 0, e, 46.25);
    std::sort(f.units.begin(), f.units.end(),
              [](const CourseUnit& a, const CourseUnit& b) { return a.from < b.from; });
    EXPECT_NEAR(f.units.front().to, 46.25, 1e-9);
    EXPECT_NEAR(f.units.back().from, e - 46.25, 1e-9);
    EXPECT_NEAR(f.units.front().depth, kL, 1e-9);
    EXPECT_EQ(f.units[1].role, UnitRole::header);
    size_t cuts = 0;
    for (size_t k = 1; k + 1 < f.units.size(); ++k)
      if (f.units[k].role == UnitRole::closer) {
        ++cuts;
        EXPECT_GE(f.units[k].to - f.units[k].from, kMinCut - 1e-9);
        EXPECT_GT(f.units[k].from, e / 4);
        EXPECT_LT(f.units[k].to, e * 3 / 4);
      }
    EXPECT_LE(cuts, 2u);
  }
  Filled f;  // Flemish after a quoin's stretcher: a header, a stretcher, by turns
  fill_in_order(f.fill(), 0, 3000, {{}, {H, S}}, {{Q}, {S, H}});
  expect_covers(f.units, 0, 3000, 46.25);
  std::sort(f.units.begin(), f.units.end(),
            [](const CourseUnit& a, const CourseUnit& b) { return a.from < b.from; });
  EXPECT_EQ(f.units[0].role, UnitRole::header);
  EXPECT_EQ(f.units[1].role, UnitRole::stretcher);
  EXPECT_EQ(f.units[2].role, UnitRole::header);
  EXPECT_NEAR(f.units.back().to - f.units.back().from, 46.25, 1e-9);
  EXPECT_EQ(f.units[f.units.size() - 2].role, UnitRole::stretcher);
}

TEST(RunFill, WholeUnitsFromTheEndsWithTheCutInTheMiddle) {
  Filled f;
  fill_whole_from_ends(f.fill(), 0, 2000);
  expect_covers(f.units, 0, 2000, kMinCut);
  Filled sliver;
  fill_whole_from_ends(sliver.fill(), 0, 50);
  EXPECT_TRUE(sliver.sliver);
  ASSERT_EQ(sliver.units.size(), 1u);
  EXPECT_NEAR(sliver.units[0].to, 50, 1e-9);
}

// A run a fraction of a millimetre short of whole pitches (a curved wall's chords), or off by
// up to a joint over 80 units (a wall set out a joint off brick sizes) is laid in whole units,
// its joints taking the difference up: no closer. More than a joint over the run, or more than
// a millimetre a joint over three units, is no longer the joints' play: a closer.
TEST(RunFill, ARunWithinTheJointsPlayOfWholeUnitsHasNoCloser) {
  EXPECT_DOUBLE_EQ(joint_play(79, 10), 10);
  EXPECT_DOUBLE_EQ(joint_play(4, 10), 4);
  EXPECT_DOUBLE_EQ(joint_play(1, 10), 2);
  for (const double off : {-0.027, 0.027, -1.9, 1.9, -9.973, 9.9}) {
    Filled f;
    const double run = 80 * (kL + kJ) - kJ + off;
    fill_whole_from_ends(f.fill(), 0, run);
    ASSERT_EQ(f.units.size(), 80u) << off;
    for (const CourseUnit& u : f.units) EXPECT_EQ(u.role, UnitRole::stretcher) << off;
    EXPECT_NEAR(f.units.front().from, 0, 1e-9);
    EXPECT_NEAR(f.units.back().to, run, 1e-9) << off;
    EXPECT_NEAR(f.units[1].from - f.units[0].to, kJ + off / 79, 1e-9) << off;
  }
  for (const auto& [units, off] : {std::pair{80, -12.0}, {80, 12.0}, {3, 2.5}, {3, -2.5}}) {
    Filled closer;
    fill_whole_from_ends(closer.fill(), 0, units * (kL + kJ) - kJ + off);
    EXPECT_TRUE(std::any_of(closer.units.begin(), closer.units.end(),
                            [](const CourseUnit& u) { return u.role == UnitRole::closer; }))
        << units << " units " << off;
  }
  // The gap left in a bond's middle: a unit's width within 2 mm is a whole unit.
  Filled gap;
  const BondOrder none{{}, {BondPiece{1000, UnitRole::stretcher, 0}}};
  fill_in_order(gap.fill(), 0, kL + 1.5, none, none);
  ASSERT_EQ(gap.units.size(), 1u);
  EXPECT_EQ(gap.units[0].role, UnitRole::stretcher);
}

}  // namespace
}  // namespace curdle
