#include "curdle/markov.h"

#include <gtest/gtest.h>

#include "curdle/overlay.h"
#include "curdle/palette.h"
#include "markov_support.h"

namespace curdle {
using test::markov_curd;
using test::markov_design;

namespace {

std::vector<Probability> row(std::initializer_list<const char*> texts) {
  std::vector<Probability> r;
  for (const char* t : texts) r.push_back(*Probability::parse(t));
  return r;
}

}  // namespace

TEST(Markov, SumsOfFractionsStayExact) {
  const Probability third = probability_sum(row({"1/3", "1/3", "1/3"}), 2);
  EXPECT_EQ(third.text(), "2/3");
  EXPECT_TRUE(probability_sum(row({"1/3", "1/3", "1/3"}), 3).certain());
  EXPECT_NEAR(probability_sum(row({"0.1", "0.2"}), 2).value(), 0.3, 1e-15);
}

TEST(Markov, TheFirstBoundIsThePlainCurdsThreshold) {
  // Dead first: the living states take the low end of the draw, in order.
  const StateBounds b = state_bounds(row({"1/4", "1/2", "1/4"}));
  ASSERT_EQ(b.bound.size(), 2u);
  EXPECT_EQ(b.bound[0], Probability::parse("1/2")->threshold());
  EXPECT_EQ(b.bound[1], Probability::parse("3/4")->threshold());
  EXPECT_EQ(b.state_of(0), 1u);
  EXPECT_EQ(b.state_of(b.bound[0]), 2u);
  EXPECT_EQ(b.state_of(b.bound[1]), 0u);
  EXPECT_EQ(state_bounds(row({"0", "1"})).state_of(UINT64_MAX), 1u);  // certain
}

TEST(Markov, PlanesHoldTheStateInTheValue) {
  const Design d =
      markov_design("base = 2\ndimension = 2",
                    "[[curds]]\nname = \"red\"\nprobabilities = [\"1/2\"]\n" +
                        markov_curd(R"(["dark", "mid", "light"])", "\"dark\"",
                                    R"([[["1", "0", "0", "0"], ["0", "1/3", "1/3", "1/3"],
                          ["0", "1/3", "1/3", "1/3"], ["0", "1/3", "1/3", "1/3"]]])"));
  ASSERT_EQ(d.curds.size(), 3u);  // red, then two planes for three states
  const auto groups = curd_groups(d.curds);
  ASSERT_EQ(groups.size(), 2u);
  EXPECT_EQ(groups[1].first, 1u);
  EXPECT_EQ(groups[1].planes, 2);
  EXPECT_EQ(groups[1].state(0b101), 2u);
  EXPECT_EQ(value_label(0b101, d.curds), "red+mid");
  EXPECT_EQ(value_label(0b110, d.curds), "light");
  EXPECT_EQ(value_label(0, d.curds), "empty");
  // A state's colour, from the default set where the recipe gives none, differs by state.
  const auto colours = value_colours(d.curds);
  EXPECT_NE(colours[0b010], colours[0b100]);
  EXPECT_EQ(value_parts(d.curds, 0b111).size(), 2u);  // red and light: one part per curd
}

TEST(Markov, SharesFollowTheChain) {
  const Design d =
      markov_design("base = 2\ndimension = 2",
                    markov_curd(R"(["dark", "mid"])", R"(["1/2", "1/2"])",
                                R"([[["1", "0", "0"], ["1/2", "1/2", "0"], ["0", "1/4", "3/4"]],
                      [["1", "0", "0"], ["0", "1", "0"], ["1", "0", "0"]]])"));
  const MarkovChain& chain = *d.curds[0].chain;
  const auto s1 = state_shares(chain, 1);
  EXPECT_DOUBLE_EQ(s1[0], 0.25);
  EXPECT_DOUBLE_EQ(s1[1], 0.375);
  EXPECT_DOUBLE_EQ(s1[2], 0.375);
  const auto s2 = state_shares(chain, 2);
  EXPECT_DOUBLE_EQ(s2[1], 0.375);
  EXPECT_DOUBLE_EQ(s2[0], 0.625);
  EXPECT_FALSE(chain.stationary());
  EXPECT_FALSE(chain.revives(1));
  EXPECT_EQ(chain.state_name(0), "dead");
}

}  // namespace curdle
