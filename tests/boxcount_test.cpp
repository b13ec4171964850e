#include "curdle/boxcount.h"

#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "curdle/curdling.h"
#include "test_support.h"

namespace curdle {
using test::design;

// The definition, by coordinates: stage-j cells holding at least one final survivor.
TEST(BoxCount, CountsAreTheStageCellsWithSurvivingDescendants) {
  for (const Design& d :
       {design(4, 2, {{"3/4", "1/2", "1/3"}}), design(3, 3, {{"2/3", "1/2", "1/2"}}),
        design(2, 1, {{"3/4", "3/4", "3/4", "3/4", "3/4"}})}) {
    for (uint64_t seed = 0; seed < 10; ++seed) {
      const CurdField f = curdle(d, seed, d.field);
      const auto counts = box_counts(f.curds[0], d.lattice.children());
      const int K = d.lattice.stages;
      for (int j = 0; j <= K; ++j) {
        std::set<Coord> boxes;
        const int64_t shrink = static_cast<int64_t>(d.lattice.side_in_cells(j));
        for_each_set(f.finest(0), 0, f.finest(0).size, [&](uint64_t i) {
          Coord c = f.index.decode(K, i);
          for (auto& x : c) x /= shrink;
          boxes.insert(c);
        });
        EXPECT_EQ(counts[j], boxes.size()) << "level " << j;
      }
    }
  }
}

// Large sparse stages are read only under live coarse cells; the counts must not change.
// Fields of several roots and a window exercise ancestors that straddle tasks and roots.
TEST(BoxCount, SparseStagesReadOnlyUnderLiveCellsCountTheSame) {
  std::vector<std::pair<Design, Box>> cases;
  auto add = [&](Design d, int64_t roots_x, bool window) {
    d.field.size[0] *= roots_x;
    Box view = d.field;
    if (window) {
      view.origin[0] = d.field.size[0] / 5;
      view.size[0] = d.field.size[0] / 2;
    }
    cases.emplace_back(d, view);
  };
  const std::vector<std::string> plane(10, "0.7");
  add(design(2, 2, {plane}), 1, false);
  add(design(2, 2, {plane}), 3, true);
  add(design(2, 3, {{"0.6", "0.6", "0.6", "0.6", "0.6", "0.6", "0.6"}}), 2, false);
  add(design(4, 2, {{"0.5", "0.5", "0.5", "0.5", "0.5"}}), 2, true);
  for (const auto& [d, view] : cases) {
    for (uint64_t seed = 0; seed < 3; ++seed) {
      const CurdField f = curdle(d, seed, view);
      const int K = d.lattice.stages;
      ASSERT_GE(f.finest(0).words.size(), 1u << 14) << "too small to take the sparse path";
      const auto counts = box_counts(f.curds[0], d.lattice.children());
      for (int j = 0; j <= K; ++j) {
        std::set<Coord> boxes;
        const int64_t shrink = static_cast<int64_t>(d.lattice.side_in_cells(j));
        for_each_set(f.finest(0), 0, f.finest(0).size, [&](uint64_t i) {
          Coord c = f.index.decode(K, i);
          for (auto& x : c) x = x >= 0 ? x / shrink : -((-x + shrink - 1) / shrink);
          boxes.insert(c);
        });
        EXPECT_EQ(counts[j], boxes.size()) << "level " << j << ", seed " << seed;
        EXPECT_EQ(count_survivors(f.curds[0], j, d.lattice.children()),
                  f.curds[0].stages[j].count())
            << "stage " << j;
      }
    }
  }
}

TEST(BoxCount, FitOfAnExactPowerLaw) {
  const std::vector<uint64_t> counts{1, 3, 9, 27, 81};  // N_j = 3^j at scale 2^-j
  const auto fit = fit_box_dimension(counts, 2);
  ASSERT_TRUE(fit);
  EXPECT_NEAR(fit->slope, std::log2(3.0), 1e-12);
  EXPECT_NEAR(fit->r2, 1.0, 1e-12);
  EXPECT_FALSE(fit_box_dimension(std::vector<uint64_t>{1, 0, 0}, 2));
}

}  // namespace curdle
