// Tests of state_tree.h: the upward-downward pass against every hidden labelling, enumerated.
#include "curdle/state_tree.h"

#include <gtest/gtest.h>

#include <cmath>

namespace curdle {
namespace {

ChainValues three_states() {
  ChainValues c;
  c.start = {0, 0.7, 0.3};
  c.transitions = {{{1, 0, 0}, {0.2, 0.5, 0.3}, {0.1, 0.3, 0.6}},
                   {{0.9, 0.1, 0}, {0.3, 0.4, 0.3}, {0.2, 0.2, 0.6}}};
  return c;
}

}  // namespace

TEST(StateTree, LikelihoodAndStepsAreTheSumsOverEveryHiddenLabelling) {
  // Base 2 in 1-D, 2 stages: a root, two cells, four leaves; a view of the middle three leaves
  // so that the view cuts both stage-1 cells.
  const Lattice l{2, 1, 2, Mode::canonical};
  Box view;
  view.origin = {1, 0, 0};
  view.size = {3, 1, 1};
  const std::vector<uint8_t> leaves = {2, 0, 1};
  const StateTree tree(l, view, leaves, 3);
  ASSERT_EQ(tree.cells(0), 1u);
  ASSERT_EQ(tree.cells(1), 2u);
  EXPECT_EQ(tree.parent(2, 0), 0u);  // leaf 1 is in stage-1 cell 0
  EXPECT_EQ(tree.parent(2, 1), 1u);
  const ChainValues c = three_states();
  double total = 0, roots[3] = {}, steps_1[3][3] = {}, steps_2[3][3] = {};
  for (int r = 0; r < 3; ++r)
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b) {
        // a is the cell over leaf 1 (its other leaf, 0, is outside), b over leaves 2 and 3
        const double w = c.start[r] * c.transitions[0][r][a] * c.transitions[0][r][b] *
                         c.transitions[1][a][2] * c.transitions[1][b][0] * c.transitions[1][b][1];
        total += w;
        roots[r] += w;
        steps_1[r][a] += w, steps_1[r][b] += w;
        steps_2[a][2] += w, steps_2[b][0] += w, steps_2[b][1] += w;
      }
  const StateTreeCounts got = tree.expected_counts(c);
  EXPECT_NEAR(got.log_likelihood, std::log(total), 1e-12);
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(got.roots[i], roots[i] / total, 1e-12) << i;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      EXPECT_NEAR(got.steps[0][i][j], steps_1[i][j] / total, 1e-12) << i << j;
      EXPECT_NEAR(got.steps[1][i][j], steps_2[i][j] / total, 1e-12) << i << j;
    }
}

TEST(StateTree, LeavesTheChainCannotMakeHaveNoLikelihood) {
  const Lattice l{2, 2, 1, Mode::canonical};
  Box view;
  view.size = {2, 2, 1};
  ChainValues c;
  c.start = {0, 1};
  c.transitions = {{{1, 0}, {0, 1}}};  // every child alive
  EXPECT_TRUE(std::isinf(StateTree(l, view, {1, 1, 0, 1}, 2).expected_counts(c).log_likelihood));
  EXPECT_NEAR(StateTree(l, view, {1, 1, 1, 1}, 2).expected_counts(c).log_likelihood, 0, 1e-15);
}

}  // namespace curdle
