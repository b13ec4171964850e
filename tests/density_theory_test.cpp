// Tests of density_theory.h.
#include "curdle/density_theory.h"

#include <gtest/gtest.h>

#include "density_support.h"

namespace curdle {
TEST(Density, ReportExpectationsMatchTheMeansOverSeeds) {
  const Design d = radial_design();
  constexpr int kSeeds = 200;
  const int K = d.lattice.stages;
  std::vector<double> sum(K + 1), sum2(K + 1), boxes(K + 1);
  Report report;
  CurdField field;
  for (uint64_t seed = 1; seed <= kSeeds; ++seed) {
    curdle_into(d, seed, d.field, field);
    report = make_report(d, seed, field, d.field);
    const CurdReport& c = report.curds[0];
    for (int k = 1; k <= K; ++k) {
      const double n = static_cast<double>(c.stages[k - 1].survivors);
      sum[k] += n;
      sum2[k] += n * n;
      boxes[k] += static_cast<double>(c.box_counts[k]);
    }
  }
  const CurdReport& c = report.curds[0];
  for (int k = 1; k <= K; ++k) {
    const StageRow& row = c.stages[k - 1];
    const double mean = sum[k] / kSeeds;
    const double sd = std::sqrt(sum2[k] / kSeeds - mean * mean);
    EXPECT_NEAR(mean, row.expected, 5 * row.expected_sd / std::sqrt(kSeeds)) << "stage " << k;
    EXPECT_NEAR(sd, row.expected_sd, 0.3 * row.expected_sd) << "stage " << k;
    EXPECT_NEAR(boxes[k] / kSeeds, c.expected_box_counts[k],
                5 * row.expected_sd / std::sqrt(kSeeds) + 1)
        << "stage " << k;
  }
  // The final expectation is the sum of min(1, P_K g) over the cells.
  double final_sum = 0;
  for (int64_t y = 0; y < 64; ++y)
    for (int64_t x = 0; x < 64; ++x)
      final_sum += std::min(1.0, d.curds[0].density->at_cell({x, y, 0}) / 3);
  EXPECT_NEAR(c.stages.back().expected, final_sum, 1e-6);
  EXPECT_NEAR(report.values[1].expected, final_sum, 1e-6);
}

}  // namespace curdle
