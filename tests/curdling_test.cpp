#include "curdle/curdling.h"

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include "curdle/cell_index.h"
#include "curdle/error.h"
#include "curdle/overlay.h"
#include "curdle/theory.h"
#include "test_support.h"

namespace curdle {
using test::design;
using test::repeat;

namespace {

Box window(int64_t x, int64_t y, int64_t w, int64_t h) { return Box{{x, y, 0}, {w, h, 1}}; }

bool same_bits(const CurdField& a, const CurdField& b) {
  if (a.curds.size() != b.curds.size()) return false;
  for (size_t c = 0; c < a.curds.size(); ++c)
    for (size_t k = 0; k < a.curds[c].stages.size(); ++k)
      if (a.curds[c].stages[k].words != b.curds[c].stages[k].words) return false;
  return true;
}

}  // namespace

TEST(Curdling, OnlyChildrenOfSurvivorsSurvive) {
  for (Mode mode : {Mode::canonical, Mode::exact, Mode::quota}) {
    const Design d = design(4, 2, {{"3/4", "1/2", "1/4"}, {"1/2", "3/4", "1/2"}}, mode);
    const CurdField f = curdle(d, 11, d.field);
    for (const Curd& curd : f.curds)
      for (int k = 1; k <= d.lattice.stages; ++k)
        for_each_set(curd.stages[k], 0, curd.stages[k].size,
                     [&](uint64_t i) { ASSERT_TRUE(curd.stages[k - 1].test(i / 16)); });
  }
}

TEST(Curdling, CertainAndImpossibleProbabilities) {
  const Design all = design(3, 2, {{"1", "1"}});
  EXPECT_EQ(curdle(all, 1, all.field).finest(0).count(), 81u);
  const Design none = design(3, 2, {{"1", "0"}});
  EXPECT_EQ(curdle(none, 1, none.field).finest(0).count(), 0u);
}

TEST(Curdling, AWindowShowsTheSameCellsAsTheWholeCurd) {
  for (Mode mode : {Mode::canonical, Mode::exact, Mode::quota}) {
    Design d = design(4, 2, {{"3/4", "1/2", "3/4"}, {"1/2", "1/2", "3/4"}}, mode);
    d.field = window(0, 0, 150, 100);  // 3 x 2 roots, cropped
    const CurdField whole = curdle(d, 5, d.field);
    for (const Box& w : {window(0, 0, 150, 100), window(37, 11, 64, 50), window(120, 90, 30, 10)}) {
      const CurdField part = curdle(d, 5, w);
      EXPECT_EQ(values_in(part, w), values_in(whole, w)) << to_string(mode);
    }
  }
}

TEST(Curdling, ACroppedFieldShowsTheSameCellsAsTheRootsItCrops) {
  Design d = design(4, 2, {{"3/4", "2/3", "1/3"}});
  Design roots = d;
  roots.field = window(0, 0, 128, 128);
  d.field = window(0, 0, 67, 67);
  EXPECT_EQ(values_in(curdle(d, 9, d.field), d.field),
            values_in(curdle(roots, 9, roots.field), d.field));
}

TEST(Curdling, ThreadCountDoesNotChangeAnyBit) {
  // 2^22 cells: enough parents per stage that the work is split between threads.
  const Design canonical = design(2, 2, repeat("7/10", 11));
  const Design exact = design(2, 2, repeat("3/4", 11), Mode::exact);
  for (const Design& d : {canonical, exact}) {
    CurdField one, two;
    {
      tbb::global_control limit(tbb::global_control::max_allowed_parallelism, 1);
      one = curdle(d, 3, d.field);
    }
    {
      tbb::global_control limit(tbb::global_control::max_allowed_parallelism, 2);
      two = curdle(d, 3, d.field);
    }
    EXPECT_TRUE(same_bits(one, two));
  }
}

// The draws do not depend on the probabilities: under one seed, raising a stage's p only adds
// cells (the README's promise for comparing variants).
TEST(Curdling, RaisingAProbabilityUnderOneSeedOnlyAddsCells) {
  for (uint64_t seed = 1; seed <= 20; ++seed) {
    const Design low = design(3, 2, {{"0.6", "0.3", "0.5"}});
    const Design high = design(3, 2, {{"0.6", "0.7", "0.5"}});
    const CurdField a = curdle(low, seed, low.field), b = curdle(high, seed, high.field);
    const Bitset& small = a.finest(0);
    const Bitset& large = b.finest(0);
    uint64_t kept = 0;
    for_each_set(small, 0, small.size, [&](uint64_t i) { kept += large.test(i); });
    EXPECT_EQ(kept, small.count()) << "seed " << seed;
    EXPECT_GE(large.count(), small.count());
  }
}

TEST(Curdling, SeedsAndCurdsAreIndependentStreams) {
  const Design d = design(4, 2, {{"1/2", "1/2"}, {"1/2", "1/2"}});
  const CurdField a = curdle(d, 1, d.field), b = curdle(d, 2, d.field);
  EXPECT_NE(a.finest(0).words, b.finest(0).words);
  EXPECT_NE(a.finest(0).words, a.finest(1).words);
}

TEST(Curdling, ExactModeKeepsExactlyPTimesBChildren) {
  const Design d = design(4, 2, {{"3/4", "1/2", "1/4"}}, Mode::exact);
  for (uint64_t seed = 0; seed < 20; ++seed) {
    const CurdField f = curdle(d, seed, d.field);
    EXPECT_EQ(f.curds[0].stages[1].count(), 12u);
    EXPECT_EQ(f.curds[0].stages[2].count(), 12u * 8);
    EXPECT_EQ(f.curds[0].stages[3].count(), 12u * 8 * 4);
    for_each_set(f.curds[0].stages[2], 0, f.curds[0].stages[2].size, [&](uint64_t i) {
      int children = 0;
      for (uint64_t c = 0; c < 16; ++c) children += f.curds[0].stages[3].test(i * 16 + c);
      ASSERT_EQ(children, 4);
    });
  }
}

TEST(Curdling, QuotaModeHitsEveryStageTargetExactly) {
  Design d = design(4, 2, {{"2/3", "1/2", "1/3"}}, Mode::quota);
  for (uint64_t seed = 0; seed < 20; ++seed) {
    const CurdField f = curdle(d, seed, d.field);
    EXPECT_EQ(f.curds[0].stages[1].count(), 11u);   // round(16 * 2/3)
    EXPECT_EQ(f.curds[0].stages[2].count(), 85u);   // round(256 / 3)
    EXPECT_EQ(f.curds[0].stages[3].count(), 455u);  // round(4096 / 9): the paper's 1 : 8
  }
  d.field = window(0, 0, 67, 67);  // 20 x 20 m of 300 mm tiles
  for (uint64_t seed = 0; seed < 20; ++seed)
    EXPECT_EQ(value_counts(curdle(d, seed, d.field))[1], 499u);  // round(4489 / 9)
}

TEST(Curdling, QuotaTargetsAreExactRationals) {
  const auto p = test::design(4, 2, {{"1/2", "1/2"}}).curds[0].probabilities;
  EXPECT_EQ(quota_target(p, 2, 18), 5u);  // 4.5 rounds up
  EXPECT_EQ(quota_target(p, 1, 3), 2u);   // 1.5 rounds up
}

TEST(Curdling, RefusesWorkAboveTheMemoryLimit) {
  const Design d = design(2, 2, repeat("7/10", 14));
  GenerateOptions options;
  options.max_memory_bytes = 1 << 20;
  options.memory_limit_hint = "raise the limit with --max-memory";
  try {
    curdle(d, 1, d.field, options);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("memory limit"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("--max-memory"), std::string::npos);
  }
  EXPECT_GT(estimate_memory(d, d.field), (uint64_t{1} << 28) / 8);
  EXPECT_LT(estimate_memory(d, d.field),
            (uint64_t{1} << 28) / 8 * 4 / 3 + 4096 + CellIndex::table_bytes(d.lattice));
}

TEST(Curdling, OneAndThreeDimensions) {
  const Design line = design(3, 1, {{"2/3", "2/3", "2/3", "2/3"}}, Mode::exact);
  EXPECT_EQ(curdle(line, 1, line.field).finest(0).count(), 16u);
  const Design cube = design(2, 3, {{"1/2", "1/2", "1/2"}}, Mode::exact);
  EXPECT_EQ(curdle(cube, 1, cube.field).finest(0).count(), 64u);
}

}  // namespace curdle

namespace curdle {

// A deep 1-D lattice's index tables alone are gigabytes: the estimate counts them without
// building them, and the engine refuses before allocating anything.
TEST(Curdling, DeepLatticesAreRefusedBeforeTheirTablesAreBuilt) {
  const Design d = test::design(
      2, 1, std::vector<std::vector<std::string>>{std::vector<std::string>(56, "1/2")});
  EXPECT_GT(CellIndex::table_bytes(d.lattice), uint64_t{1} << 31);
  EXPECT_GE(estimate_memory(d, d.field), CellIndex::table_bytes(d.lattice));
  GenerateOptions options;
  options.max_memory_bytes = uint64_t{1} << 30;
  EXPECT_THROW(curdle(d, 1, d.field, options), ResourceLimitError);
}

}  // namespace curdle
