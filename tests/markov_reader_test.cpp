#include "recipe/markov_reader.h"

#include <gtest/gtest.h>

#include "curdle/markov.h"
#include "markov_support.h"
#include "recipe_support.h"

namespace curdle {
using test::markov_curd;

namespace {

const std::string kLattice = "name = \"m\"\n[lattice]\nbase = 2\ndimension = 2\n";
const char* kGoodMatrix = R"([["1", "0", "0"], ["1/4", "1/2", "1/4"], ["1/4", "1/4", "1/2"]])";

std::string recipe(const std::string& curd) { return kLattice + curd; }

}  // namespace

TEST(MarkovReader, TheIssuesFormReads) {
  const Recipe r = parse_recipe(recipe(R"([[curds]]
name = "tone"
states = ["dark", "mid"]
colours = ["#3b3b3b", "#8c8c8c"]
start = "dark"
transitions = [
  [["1", "0", "0"], ["1/4", "1/2", "1/4"], ["1/4", "1/4", "1/2"]],
  [["1", "0", "0"], ["1/3", "1/3", "1/3"], ["1/3", "1/3", "1/3"]],
]
)"),
                                "m.toml");
  ASSERT_EQ(r.design.curds.size(), 2u);
  const MarkovChain& chain = *r.design.curds[0].chain;
  EXPECT_EQ(r.design.lattice.stages, 2);
  EXPECT_EQ(chain.states, (std::vector<std::string>{"dark", "mid"}));
  EXPECT_EQ(chain.row(2, 1)[2].text(), "1/3");
  EXPECT_EQ(chain.start[1].value(), 1.0);
  EXPECT_EQ(r.design.curds[1].plane, 1);
  EXPECT_EQ(r.design.curds[1].chain, r.design.curds[0].chain);
  // One matrix for every stage, and a start distribution; numbers as well as text.
  const Recipe one = parse_recipe(
      recipe(markov_curd(R"(["dark", "mid"])", "[0.25, \"3/4\"]", kGoodMatrix) + "stages = 6\n"),
      "m.toml");
  EXPECT_EQ(one.design.lattice.stages, 6);
  EXPECT_EQ(one.design.curds[0].chain->transitions.size(), 6u);
  EXPECT_EQ(one.design.curds[0].chain->start[2].value(), 0.75);
}

TEST(MarkovReader, BadMatricesAreRefusedWithTheKeyAndTheAllowedForm) {
  auto error = [](const std::string& transitions, const std::string& extra = "stages = 2\n",
                  const std::string& states = R"(["dark", "mid"])",
                  const std::string& start = "\"dark\"") {
    return error_of(recipe(markov_curd(states, start, transitions) + extra));
  };
  // A row that does not sum to 1: which row, which stage, by how much.
  const std::string over =
      error(R"([[["1", "0", "0"], ["1/2", "1/2", "1/4"], ["1/4", "1/4", "1/2"]]])");
  EXPECT_NE(over.find("curds.0.transitions.0.1"), std::string::npos) << over;
  EXPECT_NE(over.find("row 'dark' of stage 1 sums to 1 + 1/4"), std::string::npos) << over;
  const std::string under = error(R"([["1", "0", "0"], ["0.2", "0.2", "0.2"], ["0", "0", "1"]])");
  EXPECT_NE(under.find("sums to 1 - 2/5"), std::string::npos) << under;
  // Negative, NaN and text entries.
  EXPECT_NE(
      error(R"([["1", "0", "0"], ["-1/4", "1", "1/4"], ["0", "0", "1"]])").find("from 0 to 1"),
      std::string::npos);
  EXPECT_NE(error(R"([["1", "0", "0"], [nan, 1, 0], ["0", "0", "1"]])").find("from 0 to 1"),
            std::string::npos);
  // The wrong size, at a stage.
  const std::string size = error(
      R"([[["1", "0"], ["1/2", "1/2"]], [["1", "0", "0"], ["0", "1", "0"], ["0", "0", "1"]]])", "");
  EXPECT_NE(size.find("stage 1's matrix must have 3 rows"), std::string::npos) << size;
  // A state named twice, "dead" named, no states.
  EXPECT_NE(error(kGoodMatrix, "stages = 2\n", R"(["dark", "dark"])").find("named twice"),
            std::string::npos);
  EXPECT_NE(error(kGoodMatrix, "stages = 2\n", R"(["dead", "mid"])").find("implicit"),
            std::string::npos);
  EXPECT_NE(error(kGoodMatrix, "stages = 2\n", "[]").find("living states"), std::string::npos);
  // 0 stages, and a single matrix with no count.
  EXPECT_NE(error(kGoodMatrix, "stages = 0\n").find("stages"), std::string::npos);
  EXPECT_NE(error(kGoodMatrix, "").find("is needed with a single matrix"), std::string::npos);
  EXPECT_NE(error("[]").find("is required"), std::string::npos);
  // A start that names no state or does not sum to 1.
  EXPECT_NE(
      error(kGoodMatrix, "stages = 2\n", R"(["dark", "mid"])", "\"light\"").find("names no state"),
      std::string::npos);
  EXPECT_NE(error(kGoodMatrix, "stages = 2\n", R"(["dark", "mid"])", R"(["1/2", "1/3"])")
                .find("sums to 1 - 1/6"),
            std::string::npos);
  // A plain key a Markov curd does not take.
  EXPECT_NE(error(kGoodMatrix, "stages = 2\nprobabilities = [\"1/2\"]\n").find("probabilities"),
            std::string::npos);
}

TEST(MarkovReader, MoreStatesThanValuesAllowAreRefused) {
  std::string states = "[", row;
  for (int i = 0; i < 3; ++i) states += "\"s" + std::to_string(i) + "\",";
  states += "]";
  // 15 plain curds leave one bit: three states need two.
  std::string plain;
  for (int i = 0; i < 15; ++i)
    plain += "[[curds]]\nname = \"c" + std::to_string(i) + "\"\nprobabilities = [\"1/2\"]\n";
  const std::string e = error_of(recipe(plain +
                                        markov_curd(states, "\"s0\"",
                                                    R"([["1", "0", "0", "0"], ["1", "0", "0", "0"],
                                     ["1", "0", "0", "0"], ["1", "0", "0", "0"]])") +
                                        "stages = 1\n"));
  EXPECT_NE(e.find("take 2 bits of a cell's value, but only 1"), std::string::npos) << e;
}

TEST(MarkovReader, ExactModeNeedsWholeCountsPerParent) {
  const std::string e =
      error_of("name = \"m\"\n[lattice]\nbase = 2\ndimension = 2\nmode = \"exact\"\n" +
               markov_curd(R"(["dark", "mid"])", "\"dark\"",
                           R"([["1", "0", "0"], ["1/3", "1/3", "1/3"], ["0", "0", "1"]])") +
               "stages = 2\n");
  EXPECT_NE(e.find("curds.0.transitions.1.0"), std::string::npos) << e;
  EXPECT_NE(e.find("multiples of 1/4"), std::string::npos) << e;
}

TEST(MarkovReader, StagesMustAgreeWithTheOtherCurds) {
  const std::string e = error_of(
      recipe("[[curds]]\nname = \"red\"\nprobabilities = [\"1/2\", \"1/2\", \"1/2\"]\n" +
             markov_curd(R"(["dark", "mid"])", "\"dark\"", std::string("[") + kGoodMatrix + "]")));
  EXPECT_NE(e.find("gives 1 stages but the curds before it have 3"), std::string::npos) << e;
}

}  // namespace curdle
