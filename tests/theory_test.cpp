#include "curdle/theory.h"

#include <gtest/gtest.h>

#include <cmath>

#include "test_support.h"

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

}  // namespace curdle

#include "curdle/curdling.h"
#include "curdle/extinction.h"
#include "curdle/report.h"

namespace curdle {

// The paper's fig. 3 on a field of 64 x 64 roots: every dimension in the report is at most E,
// and with p = 1 the per-root log ratio is E exactly.
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

// With p = 1 nothing dies out: every cell meeting the view keeps a survivor. For a whole root
// in canonical mode the recursion is the Galton-Watson extinction e_k = f(e_(k+1)).
TEST(Theory, ExpectedBoxCountsFollowTheGeneratingFunction) {
  const Lattice l{3, 2, 4, Mode::canonical};
  const Box crop{{2, 5, 0}, {50, 31, 1}};
  const auto all =
      expected_box_counts(l, std::vector<Probability>(4, *Probability::parse("1")), crop);
  for (int k = 0; k <= 4; ++k)
    EXPECT_NEAR(all[k], static_cast<double>(cells_meeting(l, k, crop)), 1e-9);
  const std::vector<Probability> p(4, *Probability::parse("1/2"));
  const Box root{{0, 0, 0}, {81, 81, 1}};
  const auto counts = expected_box_counts(l, p, root);
  double e = 0;  // a surviving stage-k cell leaves nothing
  for (int k = 4; k >= 0; --k) {
    EXPECT_NEAR(counts[k], std::pow(9.0, k) * std::pow(0.5, k) * (1 - e), 1e-9) << k;
    e = std::pow(1 - 0.5 * (1 - e), 9);
  }
}

}  // namespace curdle

namespace curdle {

// The 20 m paving: 67 x 67 cells of base-4 roots of 64. Counted whole, the crop's boxes pull
// the expected fit far below the limit; weighted by the share the view shows, it is near it.
TEST(Theory, SharesOfCutBoxesBringACropsFitToTheLimit) {
  Design d = design(4, 2, {{"2/3", "1/2", "1/3"}});
  d.field = Box{{0, 0, 0}, {67, 67, 1}};
  const Report r = make_report(d, 7, curdle(d, 7, d.field), d.field);
  const CurdReport& c = r.curds[0];
  ASSERT_TRUE(c.expected_fit && c.expected_share_weighted_fit && c.theory_dimension);
  EXPECT_LT(c.expected_fit->slope, *c.theory_dimension - 0.2);
  EXPECT_NEAR(c.expected_share_weighted_fit->slope, *c.theory_dimension, 0.02);
  ASSERT_TRUE(c.share_weighted_fit);
  EXPECT_NEAR(c.share_weighted_fit->slope, *c.theory_dimension, 0.1);  // this seed's curd
}

}  // namespace curdle

#include "curdle/boxcount.h"
#include "curdle/overlay.h"

namespace curdle {

// A view of whole root cells cuts no box: weighted by share its counts are the plain ones, which
// is why the report fits them only once.
TEST(Theory, AViewOfWholeRootsWeighsEveryBoxWhole) {
  const Design d = design(4, 2, {{"3/4", "2/3", "1/2"}});
  Design two_roots = d;
  two_roots.field = Box{{64, 0, 0}, {128, 64, 1}};
  const CurdField f = curdle(two_roots, 5, two_roots.field);
  const std::vector<uint16_t> values = values_in(f, two_roots.field);
  const auto weighted = share_weighted_box_counts(two_roots.lattice, two_roots.field,
                                                  std::vector<bool>(values.begin(), values.end()));
  const auto counts = box_counts(f.curds[0], two_roots.lattice.children());
  ASSERT_EQ(weighted.size(), counts.size());
  for (size_t k = 0; k < counts.size(); ++k) EXPECT_EQ(weighted[k], static_cast<double>(counts[k]));
  const Report r = make_report(two_roots, 5, f, two_roots.field);
  ASSERT_TRUE(r.curds[0].share_weighted_fit && r.curds[0].fit);
  EXPECT_EQ(r.curds[0].share_weighted_fit->slope, r.curds[0].fit->slope);
}

}  // namespace curdle
