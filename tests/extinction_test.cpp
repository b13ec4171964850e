// Tests of extinction.h: expected box counts with extinction, and box counts weighted by the share
// of each box a view shows.
#include "curdle/extinction.h"

#include <gtest/gtest.h>

#include "theory_support.h"

namespace curdle {
using test::design;
using test::repeat;

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
