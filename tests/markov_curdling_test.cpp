#include "curdle/markov_curdling.h"

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <cmath>

#include "curdle/curdling.h"
#include "curdle/overlay.h"
#include "markov_support.h"
#include "test_support.h"

namespace curdle {
using test::markov_curd;
using test::markov_design;

namespace {

std::string complement(const std::string& p) {
  const Probability q = *Probability::parse(p);
  return Probability::fraction(q.denominator() - q.numerator(), q.denominator()).text();
}

std::string chain_of(const std::vector<std::string>& p) {
  std::string t = "[";
  for (const std::string& q : p)
    t += "[[\"1\", \"0\"], [\"" + complement(q) + "\", \"" + q + "\"]],";
  return t + "]";
}

const char* kThree = R"([[["1", "0", "0"], ["1/4", "1/2", "1/4"], ["1/4", "1/4", "1/2"]]])";

}  // namespace

TEST(MarkovCurdling, OneLivingStateDrawsExactlyThePlainCurd) {
  // Canonical (bytes and tie breaks), exact (the smallest keys) and quota (the same order of
  // keys, weighted by one p) all give the same cells, after a plain curd as well as first.
  const std::vector<std::string> p{"3/4", "1/2", "3/4", "1/4", "3/5"};
  for (const char* mode : {"canonical", "exact", "quota"}) {
    std::vector<std::string> q = p;
    if (std::string(mode) == "exact") q = {"3/4", "1/2", "3/4", "1/4", "1/2"};
    std::string probabilities = "[";
    for (const auto& x : q) probabilities += "\"" + x + "\",";
    probabilities += "]";
    const std::string lattice = "base = 2\ndimension = 2\nmode = \"" + std::string(mode) + "\"";
    const std::string before = "[[curds]]\nname = \"red\"\nprobabilities = " + probabilities + "\n";
    const Design plain = markov_design(
        lattice, before + "[[curds]]\nname = \"c\"\nprobabilities = " + probabilities + "\n",
        "cells = [70, 45]");
    const Design chain = markov_design(
        lattice, before + markov_curd(R"(["c"])", "\"c\"", chain_of(q), "c"), "cells = [70, 45]");
    for (uint64_t seed : {1u, 2u, 77u}) {
      const CurdField a = curdle(plain, seed, plain.field), b = curdle(chain, seed, chain.field);
      for (size_t k = 0; k < a.curds[1].stages.size(); ++k)
        EXPECT_TRUE(a.curds[1].stages[k].words == b.curds[1].stages[k].words)
            << mode << " seed " << seed << " stage " << k;
      EXPECT_GT(a.finest(1).count(), 0u);
    }
  }
}

TEST(MarkovCurdling, ACellsStateDependsOnlyOnSeedAndPath) {
  const Design d =
      markov_design("base = 3\ndimension = 2\nstages = 4",
                    markov_curd(R"(["dark", "mid"])", R"(["1/3", "2/3"])", kThree) + "stages = 4\n",
                    "cells = [200, 170]");
  const Box window{{37, 51, 0}, {90, 77, 1}};
  const CurdField whole = curdle(d, 5, d.field);
  const CurdField part = curdle(d, 5, window);
  EXPECT_EQ(values_in(whole, window), values_in(part, window));
  std::vector<uint16_t> one;
  {
    tbb::global_control only(tbb::global_control::max_allowed_parallelism, 1);
    one = values_in(curdle(d, 5, d.field), d.field);
  }
  EXPECT_EQ(one, values_in(whole, d.field));
  // Both states occur, and a third code never does.
  std::array<int, 4> seen{};
  for (uint16_t v : one) ++seen[v];
  EXPECT_GT(seen[1], 0);
  EXPECT_GT(seen[2], 0);
  EXPECT_EQ(seen[3], 0);
}

TEST(MarkovCurdling, ExactModeSplitsEveryParentAsItsRowSays) {
  const Design d = markov_design(
      "base = 2\ndimension = 2\nstages = 4\nmode = \"exact\"",
      markov_curd(R"(["dark", "mid"])", "\"dark\"",
                  R"([[["1", "0", "0"], ["1/4", "1/2", "1/4"], ["0", "1/4", "3/4"]]])") +
          "stages = 4\n");
  const CurdField f = curdle(d, 3, d.field);
  const std::span<const Curd> planes(f.curds.data(), 2);
  for (int k = 1; k <= 4; ++k)
    for (uint64_t parent = 0; parent < planes[0].stages[k - 1].size; ++parent) {
      const uint32_t s = state_at(planes, k - 1, parent);
      std::array<int, 4> children{};
      for (uint64_t c = 0; c < 4; ++c) ++children[state_at(planes, k, parent * 4 + c)];
      const std::array<int, 4> want = s == 1   ? std::array<int, 4>{1, 2, 1, 0}
                                      : s == 2 ? std::array<int, 4>{0, 1, 3, 0}
                                               : std::array<int, 4>{4, 0, 0, 0};
      ASSERT_EQ(children, want) << "stage " << k << " parent " << parent;
    }
}

TEST(MarkovCurdling, WheysBringDeadCellsBack) {
  const Design absorbing =
      markov_design("base = 2\ndimension = 2\nstages = 5",
                    markov_curd(R"(["dark", "mid"])", "\"dark\"", kThree) + "stages = 5\n");
  const Design wheys = markov_design(
      "base = 2\ndimension = 2\nstages = 5",
      markov_curd(R"(["dark", "mid"])", "\"dark\"",
                  R"([[["1/2", "1/4", "1/4"], ["1/4", "1/2", "1/4"], ["1/4", "1/4", "1/2"]]])") +
          "stages = 5\n");
  int revived = 0;
  const CurdField f = curdle(wheys, 9, wheys.field);
  const std::span<const Curd> planes(f.curds.data(), 2);
  for (int k = 1; k <= 5; ++k)
    for (uint64_t i = 0; i < planes[0].stages[k].size; ++i)
      revived += state_at(planes, k - 1, i / 4) == 0 && state_at(planes, k, i) != 0;
  EXPECT_GT(revived, 10);
  // Without them, the children of dead cells stay dead.
  const CurdField g = curdle(absorbing, 9, absorbing.field);
  const std::span<const Curd> dead(g.curds.data(), 2);
  for (int k = 1; k <= 5; ++k)
    for (uint64_t i = 0; i < dead[0].stages[k].size; ++i)
      if (state_at(dead, k - 1, i / 4) == 0) {
        ASSERT_EQ(state_at(dead, k, i), 0u);
      }
}

TEST(MarkovCurdling, QuotaModeHitsEveryStatesCountOverTheField) {
  const Design d = markov_design(
      "base = 2\ndimension = 2\nstages = 5\nmode = \"quota\"",
      markov_curd(R"(["dark", "mid"])", "\"dark\"", kThree) + "stages = 5\n", "cells = [96, 64]");
  for (uint64_t seed : {1u, 4u}) {
    const CurdField f = curdle(d, seed, d.field);
    const std::span<const Curd> planes(f.curds.data(), 2);
    for (int k = 1; k <= 5; ++k) {
      const std::vector<double> share = state_shares(*d.curds[0].chain, k);
      std::array<uint64_t, 4> count{};
      for (uint64_t i = 0; i < planes[0].stages[k].size; ++i) ++count[state_at(planes, k, i)];
      const double cells = 96.0 * 64 / std::pow(4, 5 - k);
      const auto dark = static_cast<uint64_t>(std::floor(cells * share[1] + 0.5));
      EXPECT_EQ(count[1], dark) << "stage " << k;
      EXPECT_EQ(count[1] + count[2],
                static_cast<uint64_t>(std::floor(cells * (share[1] + share[2]) + 0.5)))
          << "stage " << k;
    }
  }
}

}  // namespace curdle
