#include "curdle/markov_theory.h"

#include <gtest/gtest.h>

#include <cmath>

#include "curdle/curdling.h"
#include "curdle/extinction.h"
#include "curdle/markov_report.h"
#include "curdle/theory.h"
#include "markov_support.h"
#include "test_support.h"

namespace curdle {
using test::markov_curd;
using test::markov_design;

namespace {

// Over many seeds, the counts of each stage and state and the box counts of each set: their
// means within 4 standard errors of the theory, and the counts' SDs within 10 % of it.
struct Tally {
  double sum = 0, square = 0;
  int n = 0;
  void add(double x) { sum += x, square += x * x, ++n; }
  double mean() const { return sum / n; }
  double sd() const { return std::sqrt(std::max(0.0, (square - sum * sum / n) / (n - 1))); }
};

void check_against_theory(const Design& d, int seeds) {
  const Lattice& l = d.lattice;
  const CurdGroup group = curd_groups(d.curds)[0];
  const MarkovReport theory = make_markov_report(d, group, curdle(d, 1, d.field), d.field);
  std::vector<Tally> counts(theory.stages.size());
  std::vector<std::vector<Tally>> boxes(theory.sets.size(),
                                        std::vector<Tally>(theory.sets[0].box_counts.size()));
  CurdField field;
  for (int seed = 1; seed <= seeds; ++seed) {
    curdle_into(d, static_cast<uint64_t>(seed), d.field, field);
    const MarkovReport r = make_markov_report(d, group, field, d.field);
    for (size_t i = 0; i < r.stages.size(); ++i)
      counts[i].add(static_cast<double>(r.stages[i].count));
    for (size_t s = 0; s < r.sets.size(); ++s)
      for (size_t m = 0; m < r.sets[s].box_counts.size(); ++m)
        boxes[s][m].add(static_cast<double>(r.sets[s].box_counts[m]));
  }
  for (size_t i = 0; i < theory.stages.size(); ++i) {
    const StateStageRow& t = theory.stages[i];
    const std::string where = "stage " + std::to_string(t.stage) + " " + t.state;
    EXPECT_NEAR(counts[i].mean(), t.expected, 4 * t.expected_sd / std::sqrt(seeds) + 1e-9) << where;
    if (t.expected_sd > 1)
      EXPECT_NEAR(counts[i].sd(), t.expected_sd, 0.1 * t.expected_sd) << where;
    else
      EXPECT_NEAR(counts[i].sd(), t.expected_sd, 0.5) << where;
  }
  // A box count's standard error from the seeds, but never below what independent boxes would
  // give: a count that hardly varies (every root keeps a cell in all 1000) has a sample SD of 0.
  for (size_t s = 0; s < theory.sets.size(); ++s)
    for (size_t m = 0; m < boxes[s].size(); ++m) {
      const double expected = theory.sets[s].expected_box_counts[m];
      const double cells = static_cast<double>(cells_meeting(l, static_cast<int>(m), d.field));
      const double q = std::clamp(expected / cells, 0.0, 1.0);
      const double se =
          std::max(boxes[s][m].sd(), std::sqrt(cells * q * (1 - q))) / std::sqrt(seeds);
      EXPECT_NEAR(boxes[s][m].mean(), expected, 4 * se + 1e-9 * expected)
          << theory.sets[s].name << " level " << m;
    }
}

// Over 1,000 seeds an SD is known to about 2.2 %, so that 10 % is over 4 standard errors and
// the check does not fail by chance (4,000 seeds, for 5 %, cost the suite 7 s).
constexpr int kSeeds = 1000;

const char* kStationary = R"([[["1", "0", "0"], ["1/8", "5/8", "1/4"], ["1/8", "1/4", "5/8"]]])";

}  // namespace

TEST(MarkovTheory, ThreeStatesInTwoDimensionsMatchOverAThousandSeeds) {
  const Design d =
      markov_design("base = 2\ndimension = 2\nstages = 5",
                    markov_curd(R"(["dark", "mid"])", "\"dark\"", kStationary) + "stages = 5\n",
                    "cells = [128, 128]");
  check_against_theory(d, kSeeds);
}

TEST(MarkovTheory, ThreeStatesInThreeDimensionsMatchOverAThousandSeeds) {
  const Design d = markov_design(
      "base = 2\ndimension = 3\nstages = 4",
      markov_curd(R"(["dark", "mid"])", R"(["1/2", "1/2"])",
                  R"([[["1", "0", "0"], ["1/4", "1/2", "1/4"], ["1/4", "1/4", "1/2"]]])") +
          "stages = 4\n",
      "cells = [32, 32, 32]");
  check_against_theory(d, kSeeds);
}

TEST(MarkovTheory, StageWiseMatricesMatchOverAThousandSeeds) {
  const Design d =
      markov_design("base = 3\ndimension = 2",
                    markov_curd(R"(["dark", "mid"])", "\"mid\"",
                                R"([[["1", "0", "0"], ["0", "1/2", "1/2"], ["0", "1/3", "2/3"]],
                      [["1", "0", "0"], ["1/6", "2/3", "1/6"], ["1/6", "1/6", "2/3"]],
                      [["1", "0", "0"], ["1/3", "1/3", "1/3"], ["1/2", "0", "1/2"]]])"),
                    "cells = [81, 81]");
  check_against_theory(d, kSeeds);
}

TEST(MarkovTheory, WheysMatchOverAThousandSeeds) {
  // Dead cells come back as dark with 1/8 at every stage.
  const Design d = markov_design(
      "base = 2\ndimension = 2\nstages = 5",
      markov_curd(R"(["dark", "mid"])", "\"dark\"",
                  R"([[["3/4", "1/8", "1/8"], ["1/4", "1/2", "1/4"], ["1/4", "1/4", "1/2"]]])") +
          "stages = 5\n",
      "cells = [128, 128]");
  check_against_theory(d, kSeeds);
}

TEST(MarkovTheory, ExactModeMatchesOverAThousandSeeds) {
  const Design d = markov_design(
      "base = 2\ndimension = 2\nstages = 5\nmode = \"exact\"",
      markov_curd(R"(["dark", "mid"])", R"(["1/2", "1/2"])",
                  R"([[["1", "0", "0"], ["1/4", "1/2", "1/4"], ["0", "1/4", "3/4"]]])") +
          "stages = 5\n",
      "cells = [128, 128]");
  check_against_theory(d, kSeeds);
}

TEST(MarkovTheory, AFieldThatCutsRootCellsMatchesOverAThousandSeeds) {
  // 100 x 70 cells of roots 32 a side: every level has cells the field cuts.
  const Design d =
      markov_design("base = 2\ndimension = 2\nstages = 5",
                    markov_curd(R"(["dark", "mid"])", "\"dark\"", kStationary) + "stages = 5\n",
                    "cells = [100, 70]");
  check_against_theory(d, kSeeds);
}

TEST(MarkovTheory, ExactModeThroughAFieldThatCutsRootCellsMatchesOverAThousandSeeds) {
  // Exact mode deals each parent's children a fixed multiset of states: the children a field
  // cuts off take some of them, which the box counts of cut cells must follow.
  const Design d = markov_design(
      "base = 2\ndimension = 2\nstages = 5\nmode = \"exact\"",
      markov_curd(R"(["dark", "mid"])", R"(["1/2", "1/2"])",
                  R"([[["1", "0", "0"], ["1/4", "1/2", "1/4"], ["0", "1/4", "3/4"]]])") +
          "stages = 5\n",
      "cells = [100, 70]");
  check_against_theory(d, 1000);
}

TEST(MarkovTheory, OneLivingStateInExactModeThroughACutFieldIsTheCurdsBoxCounts) {
  // Fig. 7's lattice on 67 x 67 cells: a plain exact curd's expected box counts, to 1e-9.
  const std::string stage = R"([["1", "0"], ["4/9", "5/9"]])";
  const Design d =
      markov_design("base = 3\ndimension = 2\nstages = 4\nmode = \"exact\"",
                    markov_curd(R"(["alive"])", "\"alive\"",
                                "[" + stage + ", " + stage + ", " + stage + ", " + stage + "]"),
                    "cells = [67, 67]");
  const Design plain = test::design(3, 2, test::repeat("5/9", 4), Mode::exact);
  const std::vector<double> want =
      expected_box_counts(plain.lattice, plain.curds[0].probabilities, d.field);
  const std::vector<double> got =
      expected_state_box_counts(d.lattice, *d.curds[0].chain, {false, true}, d.field);
  ASSERT_EQ(got.size(), want.size());
  for (size_t m = 0; m < want.size(); ++m) EXPECT_NEAR(got[m], want[m], 1e-9 * want[m]) << m;
}

TEST(MarkovTheory, OneLivingStateIsTheCurdsTheory) {
  // P = [[1, 0], [1 - p, p]]: the plain curd's expectation and Galton-Watson SD.
  const Design d =
      markov_design("base = 3\ndimension = 2",
                    markov_curd(R"(["alive"])", "\"alive\"",
                                R"([[["1", "0"], ["2/5", "3/5"]], [["1", "0"], ["2/5", "3/5"]],
                      [["1", "0"], ["2/5", "3/5"]], [["1", "0"], ["2/5", "3/5"]]])"));
  const Design plain = test::design(3, 2, test::repeat("3/5", 4));
  for (int k = 1; k <= 4; ++k) {
    const double expected =
        expected_survivors(plain.lattice, plain.curds[0].probabilities, k, plain.field);
    const double sd = survivors_sd(plain.lattice, plain.curds[0].probabilities, k, plain.field);
    EXPECT_NEAR(state_count_sd(d.lattice, *d.curds[0].chain, k, d.field)[1], sd, 1e-9 * sd);
    EXPECT_NEAR(state_shares(*d.curds[0].chain, k)[1] * std::pow(9, k), expected, 1e-9);
  }
  // The limit dimension E + log p / log b.
  EXPECT_NEAR(*stationary_dimension(d.lattice, *d.curds[0].chain, {false, true}),
              2 + std::log(0.6) / std::log(3.0), 1e-9);
}

TEST(MarkovTheory, SpectralDimensionOfTheLivingSetAndOfEachState) {
  const Design d = markov_design("base = 2\ndimension = 2\nstages = 4",
                                 markov_curd(R"(["dark", "mid"])", "\"dark\"",
                                             R"([[["1", "0", "0"], ["1/4", "1/2", "1/4"],
                                                 ["1/2", "0", "1/2"]]])") +
                                     "stages = 4\n");
  const MarkovChain& chain = *d.curds[0].chain;
  // Living: rho of 4 [[1/2, 1/4], [0, 1/2]] is 2: D = 1. Mid is fed by dark too: also 1.
  EXPECT_NEAR(*stationary_dimension(d.lattice, chain, {false, true, true}), 1.0, 1e-6);
  EXPECT_NEAR(*stationary_dimension(d.lattice, chain, {false, false, true}), 1.0, 1e-6);
  // Dark alone feeds itself only: 4 * 1/2 = 2, D = 1 as well; with p = 1/4 it would die out.
  const Design thin = markov_design("base = 2\ndimension = 2\nstages = 4",
                                    markov_curd(R"(["dark", "mid"])", "\"dark\"",
                                                R"([[["1", "0", "0"], ["5/8", "1/8", "1/4"],
                                                    ["1/4", "0", "3/4"]]])") +
                                        "stages = 4\n");
  EXPECT_FALSE(stationary_dimension(thin.lattice, *thin.curds[0].chain, {false, true, false}));
  EXPECT_NEAR(*stationary_dimension(thin.lattice, *thin.curds[0].chain, {false, false, true}),
              std::log2(3.0), 1e-6);
}

TEST(MarkovTheory, ExtinctionOfOneStateIsTheGeneratingFunction) {
  // One stage, B = 4 children each dead with 1/4: none alive with (1/4)^4.
  const Design d =
      markov_design("base = 2\ndimension = 2\nstages = 1",
                    markov_curd(R"(["alive"])", "\"alive\"", R"([[["1", "0"], ["1/4", "3/4"]]])") +
                        "stages = 1\n");
  EXPECT_NEAR(extinction_chance(d.lattice, *d.curds[0].chain, {false, true}), 1.0 / 256, 1e-12);
}

}  // namespace curdle
