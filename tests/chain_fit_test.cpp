// Tests of chain_fit.h: a chain the engine drew, fitted back from its finest cells alone.
#include "curdle/chain_fit.h"

#include <gtest/gtest.h>

#include <cmath>

#include "curdle/curdling.h"
#include "curdle/markov.h"
#include "curdle/overlay.h"
#include "markov_support.h"
#include "test_support.h"

namespace curdle {
namespace {

StateTree tree_of(const Design& d, uint64_t seed, size_t states) {
  const std::vector<uint16_t> values = values_in(curdle(d, seed, d.field), d.field);
  return StateTree(d.lattice, d.field, std::vector<uint8_t>(values.begin(), values.end()), states);
}

const char* kChain = R"([[["1", "0", "0"], ["1/8", "5/8", "1/4"], ["1/8", "1/4", "5/8"]]])";

}  // namespace

TEST(ChainFit, AChainTheEngineDrewComesBackInsideItsIntervals) {
  const Design d = test::markov_design(
      "base = 2\ndimension = 2\nstages = 5",
      test::markov_curd(R"(["dark", "mid"])", R"(["1/2", "1/2"])", kChain) + "stages = 5\n",
      "cells = [256, 256]");
  const ChainFit fit = fit_chain(tree_of(d, 3, 3), {});
  ASSERT_TRUE(fit.converged);
  ASSERT_TRUE(fit.intervals);
  ASSERT_EQ(fit.transitions.size(), 1u);
  const MarkovChain& truth = *d.curds[0].chain;
  for (size_t i = 0; i < 3; ++i)
    for (size_t j = 0; j < 3; ++j) {
      const FittedEntry& e = fit.transitions[0][i][j];
      const double want = truth.transitions[0][i][j].value();
      EXPECT_LE(e.low, e.value);
      EXPECT_GE(e.high, e.value);
      if (i == 0) {
        EXPECT_TRUE(e.fixed);
        EXPECT_EQ(e.value, want);
        continue;
      }
      EXPECT_GT(e.high - e.low, 0.005) << i << j;  // honest: never of no width
      EXPECT_LT(e.high - e.low, 0.15) << i << j;
      // Within twice the interval's half width: a fixed seed, so this never flakes.
      EXPECT_NEAR(e.value, want, e.high - e.low) << i << " -> " << j;
    }
  // 64 roots whose state five stages of mixing all but forget: the start is known only loosely.
  EXPECT_GT(fit.start[1].high - fit.start[1].low, 0.4);
  EXPECT_EQ(fit.parameters, 1 + 2 * 2);
  EXPECT_NEAR(fit.bic, -2 * fit.log_likelihood + 5 * std::log(256.0 * 256), 1e-6);
}

TEST(ChainFit, AStageWiseChainWithWheysKeepsItsStatesNames) {
  const Design d = test::markov_design(
      "base = 3\ndimension = 2\nstages = 4",
      test::markov_curd(R"(["dark", "mid"])", "\"dark\"",
                        R"([[["1", "0", "0"], ["0", "3/4", "1/4"], ["0", "1/4", "3/4"]],
                            [["3/4", "1/8", "1/8"], ["1/4", "1/2", "1/4"], ["1/4", "1/4", "1/2"]],
                            [["3/4", "1/8", "1/8"], ["1/4", "1/2", "1/4"], ["1/4", "1/4", "1/2"]],
                            [["3/4", "1/8", "1/8"], ["1/4", "1/2", "1/4"], ["1/4", "1/4", "1/2"]]])"),
      "cells = [243, 243]");
  ChainFitOptions o;
  o.stage_wise = true;
  o.wheys = true;
  const ChainFit fit = fit_chain(tree_of(d, 5, 3), o);
  ASSERT_EQ(fit.transitions.size(), 4u);
  const MarkovChain& truth = *d.curds[0].chain;
  // Stage 2's dead row has no dead parents to learn from (no stage-1 cell is dead): from stage 3.
  for (size_t k = 2; k < 4; ++k)
    for (size_t i = 0; i < 3; ++i)
      for (size_t j = 0; j < 3; ++j) {
        const FittedEntry& e = fit.transitions[k][i][j];
        EXPECT_NEAR(e.value, truth.transitions[k][i][j].value(), 2 * (e.high - e.low) + 0.01)
            << "stage " << k + 1 << " " << i << " -> " << j;
      }
}

TEST(ChainFit, APlainCurdIsTheOneStateChain) {
  const Design d = test::design(3, 2, {{"7/9", "2/3", "5/9", "2/3"}});
  ChainFitOptions o;
  o.stage_wise = true;
  o.start_state = 1;
  const ChainFit fit = fit_chain(tree_of(d, 2, 2), o);
  EXPECT_EQ(fit.parameters, 4);
  const double want[] = {7.0 / 9, 2.0 / 3, 5.0 / 9, 2.0 / 3};
  for (size_t k = 0; k < 4; ++k) {
    const FittedEntry& e = fit.transitions[k][1][1];
    EXPECT_NEAR(e.value, want[k], 2 * (e.high - e.low)) << k;
    EXPECT_NEAR(fit.transitions[k][1][0].value, 1 - e.value, 1e-12);
  }
}

TEST(ChainFit, TheInformationCriterionTellsAnOverlayFromAChain) {
  // Two overlaid curds are a chain of three states (value = state), with fewer parameters.
  const Design overlay = test::design(2, 2, {test::repeat("3/4", 5)[0], test::repeat("5/8", 5)[0]});
  Design wide = overlay;
  wide.field.size = {128, 128, 1};
  const StateTree from_overlay = tree_of(wide, 4, 4);
  ChainFitOptions chain;
  chain.intervals = false;
  const ChainFit as_chain = fit_chain(from_overlay, chain);
  EXPECT_EQ(as_chain.parameters, 2 + 3 * 3);
  // The overlay's own likelihood: each curd a one-state chain.
  double overlay_log_l = 0;
  for (int c = 0; c < 2; ++c) {
    std::vector<uint8_t> bits;
    for (size_t i = 0; i < from_overlay.leaves(); ++i)
      bits.push_back(from_overlay.leaf(i) >> c & 1);
    ChainFitOptions one;
    one.stage_wise = true;
    one.start_state = 1;
    one.intervals = false;
    overlay_log_l += fit_chain(StateTree(wide.lattice, wide.field, bits, 2), one).log_likelihood;
  }
  const double overlay_bic = information_criterion(overlay_log_l, 10, from_overlay.leaves());
  EXPECT_LT(overlay_bic, as_chain.bic);
}

}  // namespace curdle
