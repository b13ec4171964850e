// Curdling against theory over many fixed seeds. Bounds are 4 standard errors (mean) or
// 4 estimated standard errors of the sample variance, so a pass is the same on every run.
#include "curdle/report.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numeric>

#include "curdle/boxcount.h"
#include "curdle/curdling.h"
#include "curdle/extinction.h"
#include "curdle/overlay.h"
#include "curdle/theory.h"
#include "test_support.h"

namespace curdle {
using test::design;
using test::repeat;

namespace {

struct Moments {
  double mean = 0, variance = 0, se_mean = 0, se_variance = 0;
};

Moments moments(const std::vector<double>& x) {
  const double n = static_cast<double>(x.size());
  Moments m;
  m.mean = std::accumulate(x.begin(), x.end(), 0.0) / n;
  double m2 = 0, m4 = 0;
  for (double v : x) {
    const double d = v - m.mean;
    m2 += d * d, m4 += d * d * d * d;
  }
  m2 /= n, m4 /= n;
  m.variance = m2 * n / (n - 1);
  m.se_mean = std::sqrt(m.variance / n);
  m.se_variance = std::sqrt(std::max(0.0, m4 - m2 * m2) / n);
  return m;
}

// Survivors of the last stage of curd 0 over seeds 0..n-1, seen through `view`.
std::vector<double> final_counts(const Design& d, const Box& view, int seeds) {
  std::vector<double> counts;
  CurdField f;
  for (int seed = 0; seed < seeds; ++seed) {
    curdle_into(d, static_cast<uint64_t>(seed), view, f);
    counts.push_back(static_cast<double>(f.finest(0).count()));
  }
  return counts;
}

void expect_matches_theory(const Design& d, const Box& view, int seeds) {
  const Moments m = moments(final_counts(d, view, seeds));
  const auto& p = d.curds[0].probabilities;
  const int K = d.lattice.stages;
  const double mean = expected_survivors(d.lattice, p, K, view);
  const double sd = survivors_sd(d.lattice, p, K, view);
  EXPECT_NEAR(m.mean, mean, 4 * sd / std::sqrt(seeds)) << "mean";
  EXPECT_NEAR(m.variance, sd * sd, 4 * m.se_variance) << "variance";
}

}  // namespace

TEST(Statistics, CanonicalConstantProbabilityMatchesGaltonWatson) {
  expect_matches_theory(design(2, 2, repeat("7/10", 8)), design(2, 2, repeat("7/10", 8)).field,
                        4000);
}

TEST(Statistics, CanonicalStagewiseProbabilitiesMatchTheory) {
  const Design d = design(4, 2, {{"3/4", "2/3", "1/3"}});  // the paper's fig. 6
  expect_matches_theory(d, d.field, 4000);
  const Design r = design(4, 2, {{"1/3", "2/3", "3/4"}});
  expect_matches_theory(r, r.field, 4000);
}

TEST(Statistics, ChildCountsThatAreNotMultiplesOf16MatchTheory) {
  // b^E = 9 and 25: one draw serves several parents, or a parent spans draws.
  const Design nine = design(3, 2, repeat("7/10", 4));
  expect_matches_theory(nine, nine.field, 3000);
  const Design twenty_five = design(5, 2, {{"3/5", "1/2", "2/5"}});
  expect_matches_theory(twenty_five, twenty_five.field, 3000);
}

TEST(Statistics, AWindowAcrossRootsMatchesTheory) {
  Design d = design(4, 2, {{"3/4", "2/3", "1/2"}});
  d.field = Box{{0, 0, 0}, {128, 128, 1}};
  expect_matches_theory(d, Box{{40, 50, 0}, {45, 30, 1}}, 3000);
}

TEST(Statistics, ExactModeInAWindowMatchesTheory) {
  Design d = design(4, 2, {{"3/4", "1/2", "1/4"}}, Mode::exact);
  expect_matches_theory(d, Box{{5, 9, 0}, {37, 21, 1}}, 3000);
}

TEST(Statistics, OneAndThreeDimensionalMeansMatchTheory) {
  const Design line = design(3, 1, repeat("4/5", 7));
  expect_matches_theory(line, line.field, 3000);
  const Design cube = design(2, 3, repeat("3/5", 5));
  expect_matches_theory(cube, cube.field, 3000);
}

TEST(Statistics, ValueFrequenciesMatchTheProducts) {
  const Design d = design(4, 2, {{"3/4", "2/3"}, {"1/2", "1/2"}, {"3/4", "1/3"}});
  const int seeds = 3000;
  std::vector<std::vector<double>> counts(8);
  CurdField f;
  for (int seed = 0; seed < seeds; ++seed) {
    curdle_into(d, static_cast<uint64_t>(seed), d.field, f);
    const auto c = value_counts(f);
    for (size_t v = 0; v < 8; ++v) counts[v].push_back(static_cast<double>(c[v]));
  }
  const double P[3] = {0.5, 0.25, 0.25};
  for (uint32_t v = 0; v < 8; ++v) {
    double p = 1;
    for (int i = 0; i < 3; ++i) p *= (v >> i & 1) ? P[i] : 1 - P[i];
    const Moments m = moments(counts[v]);
    EXPECT_NEAR(m.mean, 256 * p, 4 * m.se_mean + 1e-9) << "value " << v;
  }
}

namespace {

// Mean fitted box dimension over seeds whose curd survived to the last stage.
double mean_fitted_dimension(const Design& d, int seeds) {
  CurdField f;
  std::vector<Bitset> scratch;
  double sum = 0;
  int n = 0;
  for (int seed = 0; seed < seeds; ++seed) {
    curdle_into(d, static_cast<uint64_t>(seed), d.field, f);
    const auto fit =
        fit_box_dimension(box_counts(f.curds[0], d.lattice.children(), scratch), d.lattice.base);
    if (!fit || f.finest(0).count() == 0) continue;
    sum += fit->slope;
    ++n;
  }
  EXPECT_GT(n, seeds / 2);
  return sum / n;
}

}  // namespace

TEST(Statistics, FittedBoxDimensionConvergesToTheory) {
  const Design plane = design(2, 2, repeat("7/10", 12));
  EXPECT_NEAR(mean_fitted_dimension(plane, 400), 2 + std::log2(0.7), 0.03);
  const Design line = design(2, 1, repeat("17/20", 16));
  EXPECT_NEAR(mean_fitted_dimension(line, 400), 1 + std::log2(0.85), 0.03);
  const Design cube = design(2, 3, repeat("7/10", 7));
  EXPECT_NEAR(mean_fitted_dimension(cube, 200), 3 + std::log2(0.7), 0.03);
}

}  // namespace curdle

namespace curdle {
namespace {

// Box counts at every level against their finite-K expectation with extinction, over seeds.
void expect_box_counts_match(const Design& d, const Box& view, int seeds) {
  const int K = d.lattice.stages;
  std::vector<std::vector<double>> counts(static_cast<size_t>(K + 1)), weighted = counts;
  CurdField f;
  std::vector<Bitset> scratch;
  for (int seed = 0; seed < seeds; ++seed) {
    curdle_into(d, static_cast<uint64_t>(seed), view, f);
    const auto c = box_counts(f.curds[0], d.lattice.children(), scratch);
    const std::vector<uint16_t> values = values_in(f, view);
    const auto w =
        share_weighted_box_counts(d.lattice, view, std::vector<bool>(values.begin(), values.end()));
    for (int k = 0; k <= K; ++k) {
      counts[k].push_back(static_cast<double>(c[k]));
      weighted[k].push_back(w[k]);
      // Weights are at most 1, and whole boxes weigh 1: between the boxes inside and all.
      EXPECT_LE(w[k], static_cast<double>(c[k]) + 1e-9);
    }
  }
  const auto& p = d.curds[0].probabilities;
  const auto expected = expected_box_counts(d.lattice, p, view);
  const auto expected_weighted = expected_share_weighted_box_counts(d.lattice, p, view);
  for (int k = 0; k <= K; ++k) {
    // A level of few cells may show no spread in the sample: the spread of one cell kept with
    // the mean share is the least the bound allows.
    const double share = expected[k] / static_cast<double>(cells_meeting(d.lattice, k, view));
    const double floor = std::sqrt(share * (1 - share) / seeds);
    const Moments m = moments(counts[k]), mw = moments(weighted[k]);
    EXPECT_NEAR(m.mean, expected[k], 4 * std::max(m.se_mean, floor)) << "level " << k;
    EXPECT_NEAR(mw.mean, expected_weighted[k], 4 * std::max(mw.se_mean, floor) + 1e-9)
        << "weighted, level " << k;
  }
}

}  // namespace

TEST(Statistics, BoxCountsMatchTheirFiniteStageExpectationWithExtinction) {
  // Low probabilities late, so that many early survivors leave nothing: a cropped field,
  // a window across roots, and exact mode in a window.
  Design d = design(3, 2, {{"4/5", "1/2", "1/3", "1/4"}});
  d.field = Box{{0, 0, 0}, {100, 70, 1}};
  // Extinction matters here: a surviving stage-3 cell keeps no child with chance (3/4)^9.
  const auto expected = expected_box_counts(d.lattice, d.curds[0].probabilities, d.field);
  EXPECT_LT(expected[3],
            expected_survivors(d.lattice, d.curds[0].probabilities, 3, d.field) * 0.95);
  expect_box_counts_match(d, d.field, 1500);
  expect_box_counts_match(d, Box{{17, 30, 0}, {50, 33, 1}}, 1500);
  Design exact = design(3, 2, {{"7/9", "5/9", "1/3", "1/3"}}, Mode::exact);
  exact.field = Box{{0, 0, 0}, {100, 70, 1}};
  expect_box_counts_match(exact, Box{{5, 9, 0}, {61, 40, 1}}, 1500);
  const Design cube = design(2, 3, {{"3/4", "1/2", "1/2", "1/2"}});
  expect_box_counts_match(cube, Box{{3, 0, 1}, {11, 13, 9}}, 1500);
}

}  // namespace curdle

namespace curdle {

// Where each cell's children survive one at a time on average or fewer (p b^E <= 1), run on the
// curd dies out almost surely: the report says so instead of a negative dimension.
TEST(Report, ACurdThatDiesOutHasNoLimitDimension) {
  const Design dying = test::design(2, 2, {{"0.2", "0.2", "0.2"}});  // 0.2 x 4 = 0.8
  const Report r = make_report(dying, 3, curdle(dying, 3, dying.field), dying.field);
  EXPECT_TRUE(r.curds[0].dies_out);
  EXPECT_FALSE(r.curds[0].theory_dimension);
  const Design critical = test::design(2, 2, {{"1/4", "1/4"}});  // exactly 1: still dies out
  EXPECT_TRUE(make_report(critical, 1, curdle(critical, 1, critical.field), critical.field)
                  .curds[0]
                  .dies_out);
  const Design living = test::design(2, 2, {{"1/2", "1/2"}});
  const Report l = make_report(living, 3, curdle(living, 3, living.field), living.field);
  EXPECT_FALSE(l.curds[0].dies_out);
  ASSERT_TRUE(l.curds[0].theory_dimension);
  EXPECT_NEAR(*l.curds[0].theory_dimension, 1.0, 1e-12);  // 2 + log2(1/2)
}

}  // namespace curdle

namespace curdle {

// Quota mode hits every stage's target when the field can hold it; when the survivors' children
// inside a cropped field are fewer, the report says which target was missed and claims no zero
// spread (p = 1/2, 1/2, 1 on 67 x 67 cells missed in 133 of 200 seeds, silently).
TEST(Report, AQuotaTheFieldCannotHoldIsReportedMissed) {
  Design d = test::design(4, 2, {{"1/2", "1/2", "1"}}, Mode::quota);
  d.field.size = {67, 67, 1};
  int missed = 0;
  for (uint64_t seed = 1; seed <= 20; ++seed) {
    const Report r = make_report(d, seed, curdle(d, seed, d.field), d.field);
    for (const StageRow& s : r.curds[0].stages) {
      const uint64_t target = quota_target(d.curds[0].probabilities, s.stage, s.cells);
      if (s.quota_missed) {
        ++missed;
        EXPECT_EQ(*s.quota_missed, target);
        EXPECT_LT(s.survivors, target);
        EXPECT_GT(s.expected_sd, 0);
      } else {
        EXPECT_EQ(s.survivors, target) << "seed " << seed << " stage " << s.stage;
        EXPECT_EQ(s.expected_sd, 0);
      }
    }
  }
  EXPECT_GT(missed, 5);
}

}  // namespace curdle
