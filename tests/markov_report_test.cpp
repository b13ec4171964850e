#include "curdle/markov_report.h"

#include <gtest/gtest.h>

#include <cmath>

#include "curdle/curdling.h"
#include "curdle/report.h"
#include "export/report/report_table.h"
#include "markov_support.h"

namespace curdle {
using test::markov_curd;
using test::markov_design;

TEST(MarkovReport, CountsAddUpAndSitBesideTheirTheory) {
  const Design d = markov_design(
      "base = 2\ndimension = 2\nstages = 5",
      "[[curds]]\nname = \"red\"\nprobabilities = [\"1/2\", \"1\", \"1\", \"1\", \"1\"]\n" +
          markov_curd(R"(["dark", "mid"])", "\"dark\"",
                      R"([[["1", "0", "0"], ["1/4", "1/2", "1/4"], ["1/4", "1/4", "1/2"]]])") +
          "stages = 5\n",
      "cells = [64, 64]");
  const CurdField f = curdle(d, 3, d.field);
  const Report r = make_report(d, 3, f, d.field);
  ASSERT_EQ(r.curds.size(), 1u);  // the plain curd; the chain's planes are not curds
  ASSERT_EQ(r.markov.size(), 1u);
  const MarkovReport& m = r.markov[0];
  ASSERT_EQ(m.stages.size(), 6u * 3u);
  for (int k = 0; k <= 5; ++k) {
    uint64_t total = 0;
    double share = 0;
    for (int s = 0; s < 3; ++s) {
      total += m.stages[static_cast<size_t>(3 * k + s)].count;
      share += m.stages[static_cast<size_t>(3 * k + s)].share;
    }
    EXPECT_EQ(total, m.stages[static_cast<size_t>(3 * k)].cells);
    EXPECT_NEAR(share, 1.0, 1e-12);
  }
  const StateStageRow& dark = m.stages[3 * 5 + 1];
  ASSERT_TRUE(dark.z);
  EXPECT_NEAR(*dark.z, (static_cast<double>(dark.count) - dark.expected) / dark.expected_sd, 1e-12);
  ASSERT_EQ(m.sets.size(), 3u);
  EXPECT_EQ(m.sets[2].name, "living");
  EXPECT_EQ(m.sets[2].box_counts.back(), m.stages[3 * 5 + 1].count + m.stages[3 * 5 + 2].count);
  ASSERT_TRUE(m.sets[2].theory_dimension);
  EXPECT_NEAR(*m.sets[2].theory_dimension, std::log2(3.0), 1e-6);
  // The values: red's bit and the chain's two bits; the code no state has is never expected.
  double expected = 0;
  uint64_t cells = 0;
  for (const ValueRow& v : r.values) {
    expected += v.expected;
    cells += v.count;
    if ((v.value >> 1) == 3) {
      EXPECT_EQ(v.expected, 0.0) << v.label;
    }
  }
  EXPECT_NEAR(expected, 4096.0, 1e-6);
  EXPECT_EQ(cells, 4096u);
  const std::string table = format_report_table(r);
  EXPECT_NE(table.find("Markov curd 'tone': states dead, dark, mid; stationary P"),
            std::string::npos)
      << table;
  EXPECT_NE(table.find("living: box dimension fit"), std::string::npos);
}

// Beside a plain curd with a density field, the values' expectations take the Markov curd's
// state shares (they took its bit planes for curds): they add up to the cells, and a code no
// state has is never expected.
TEST(MarkovReport, ValuesBesideADensityFieldTakeTheStateShares) {
  const Design d = markov_design(
      "base = 2\ndimension = 2\nstages = 4",
      "[[curds]]\nname = \"red\"\nprobabilities = [\"3/4\", \"3/4\", \"3/4\", \"3/4\"]\n"
      "[curds.density]\nkind = \"radial\"\ncentre = [8, 8]\nradius = 8\nvalues = [2, 0.5]\n" +
          markov_curd(R"(["dark", "mid"])", "\"dark\"",
                      R"([[["1", "0", "0"], ["1/4", "1/2", "1/4"], ["1/4", "1/4", "1/2"]]])") +
          "stages = 4\n");
  const Report r = make_report(d, 3, curdle(d, 3, d.field), d.field);
  double total = 0;
  for (const ValueRow& v : r.values) {
    total += v.expected;
    if ((v.value >> 1) == 3) {
      EXPECT_EQ(v.expected, 0.0) << v.label;
    }
  }
  EXPECT_NEAR(total, 256.0, 1e-6);
  // The Markov curd's dark share is (3/4)^4 / 2 of the cells whatever the red curd does.
  double dark = 0;
  for (const ValueRow& v : r.values)
    if ((v.value >> 1) == 1) dark += v.expected;
  EXPECT_NEAR(dark, 256.0 * state_shares(*d.curds[1].chain, 4)[1], 1e-6);
}

}  // namespace curdle
