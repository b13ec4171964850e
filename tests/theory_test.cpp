#include "curdle/theory.h"

#include <gtest/gtest.h>

#include "theory_support.h"

namespace curdle {
using test::design;
using test::repeat;

TEST(Theory, OneRootWithConstantPIsGaltonWatson) {
  for (int k = 1; k <= 6; ++k) {
    const Design d = design(3, 2, repeat("3/5", 6));
    const double B = 9, p = 0.6, m = p * B, s2 = B * p * (1 - p);
    const double var = s2 * std::pow(m, k - 1) * (std::pow(m, k) - 1) / (m - 1);
    EXPECT_NEAR(survivors_sd(d.lattice, d.curds[0].probabilities, k, d.field), std::sqrt(var),
                1e-9 * std::sqrt(var));
    EXPECT_NEAR(expected_survivors(d.lattice, d.curds[0].probabilities, k, d.field),
                std::pow(B, k) * std::pow(p, k), 1e-9);
  }
}

TEST(Theory, ExactModeOverWholeRootsHasNoVariance) {
  const Design d = design(4, 2, {{"3/4", "1/2", "1/4"}}, Mode::exact);
  // Zero up to rounding of terms of order 1e5.
  EXPECT_NEAR(survivors_sd(d.lattice, d.curds[0].probabilities, 3, d.field), 0.0, 1e-3);
}

TEST(Theory, CellsMeetingACroppedBox) {
  const Lattice l{4, 2, 3, Mode::canonical};
  const Box field{{0, 0, 0}, {67, 67, 1}};
  EXPECT_EQ(cells_meeting(l, 3, field), 67u * 67u);
  EXPECT_EQ(cells_meeting(l, 2, field), 17u * 17u);  // 4-cell squares: 16 whole + 1 cut
  EXPECT_EQ(cells_meeting(l, 1, field), 25u);        // 16-cell squares: 4 whole + 1 cut
  EXPECT_EQ(cells_meeting(l, 0, field), 4u);
}

TEST(Theory, Dimension) {
  const Lattice l{2, 2, 12, Mode::canonical};
  EXPECT_NEAR(theory_dimension(l, 0.7), 2 + std::log2(0.7), 1e-12);
  EXPECT_TRUE(std::isinf(theory_dimension(l, 0.0)));
}

TEST(Theory, NoDimensionInTheReportExceedsTheLatticeDimension) {
  for (const char* p : {"1", "3/4"}) {
    Design d = design(4, 2, {{p, p}, {"2/3", "3/4"}});
    d.field = Box{{0, 0, 0}, {1024, 1024, 1}};
    const Report r = make_report(d, 3, curdle(d, 3, d.field), d.field);
    for (const CurdReport& c : r.curds) {
      for (const StageRow& s : c.stages) {
        ASSERT_TRUE(s.mean_dimension);
        EXPECT_LE(*s.mean_dimension, 2 + 1e-12) << c.name << " stage " << s.stage;
        if (s.local_dimension) {
          EXPECT_LE(*s.local_dimension, 2 + 1e-12);
        }
      }
      ASSERT_TRUE(c.fit);
      EXPECT_LE(c.fit->slope, 2 + 1e-12);
    }
    if (std::string(p) == "1") {
      EXPECT_NEAR(*r.curds[0].stages[1].mean_dimension, 2.0, 1e-12);
    }
  }
}

}  // namespace curdle
