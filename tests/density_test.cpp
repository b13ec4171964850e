// Density fields: survival follows the field (statistically, over fixed seeds), the report's
// expectations are exact, the field lies where the layout lays each cell, and bad fields are
// refused with what is allowed.
#include "curdle/density.h"

#include <gtest/gtest.h>

#include "density_support.h"

namespace curdle {
TEST(Density, SurvivalFollowsTheFieldInEveryRing) {
  const Design d = radial_design();
  const DensityField& f = *d.curds[0].density;
  constexpr int kRings = 4;
  std::array<double, kRings> expected{}, alive{};
  std::array<int64_t, kRings> cells{};
  auto ring = [](int64_t x, int64_t y) {
    return std::min(kRings - 1, static_cast<int>(distance_from_centre(x, y) / 8));
  };
  for (int64_t y = 0; y < 64; ++y)
    for (int64_t x = 0; x < 64; ++x) {
      expected[ring(x, y)] += std::min(1.0, f.at_cell({x, y, 0}) / 3);
      ++cells[ring(x, y)];
    }
  constexpr int kSeeds = 200;
  CurdField field;
  for (uint64_t seed = 1; seed <= kSeeds; ++seed) {
    curdle_into(d, seed, d.field, field);
    for (int64_t y = 0; y < 64; ++y)
      for (int64_t x = 0; x < 64; ++x) alive[ring(x, y)] += field.value_at({x, y, 0});
  }
  for (int r = 0; r < kRings; ++r) {
    const double want = expected[r] / cells[r], got = alive[r] / (cells[r] * kSeeds);
    EXPECT_NEAR(got, want, 0.05) << "ring " << r;
  }
  // The field falls outwards, and so do the shares.
  EXPECT_GT(alive[0] / cells[0], 2 * alive[3] / cells[3]);
}

TEST(Density, AFieldOfOneIsThePlainCurd) {
  Design plain = test::design(2, 2, test::repeat("1/2", 6));
  Design flat = plain;
  DensityField f;
  f.kind = DensityKind::linear;
  f.to = {64, 0, 0};
  f.values = {1, 1};
  flat.curds[0].density = f;
  for (uint64_t seed : {1, 7, 99}) {
    const CurdField a = curdle(plain, seed, plain.field), b = curdle(flat, seed, flat.field);
    EXPECT_TRUE(a.finest(0).words == b.finest(0).words) << "seed " << seed;
  }
}

TEST(Density, EveryCellsBoundHoldsItsChildren) {
  for (DensityKind kind : {DensityKind::linear, DensityKind::radial}) {
    Design d = radial_design();
    DensityField& f = *d.curds[0].density;
    f.kind = kind;
    f.from = {5, 60, 0};
    f.to = {50, 3, 0};
    f.values = {0.1, 3};
    f.placement.course_shift = {0, -0.5};
    for (int k = 1; k <= d.lattice.stages; ++k) {
      const int64_t n = 1 << (2 * k);
      const double P = std::pow(0.75, 1) * (k > 1 ? std::pow(2.0 / 3, k - 1) : 1);
      const double Pp = k == 1 ? 1 : std::pow(0.75, 1) * (k > 2 ? std::pow(2.0 / 3, k - 2) : 1);
      for (int64_t y = 0; y < n; ++y)
        for (int64_t x = 0; x < n; ++x) {
          const double child = f.survival(d.lattice, k, {x, y, 0}, P);
          const double parent = f.survival(d.lattice, k - 1, {x / 4, y / 4, 0}, Pp);
          ASSERT_LE(child, parent + 1e-12) << "stage " << k << " cell " << x << "," << y;
        }
    }
  }
}

// Round a building's ring (a period along x) a radial field is measured the nearer way round,
// and a cell's span that runs past the period is taken round to its start: near the closing
// corner the field is as near the centre as on the other side.
TEST(Density, ARadialFieldIsMeasuredRoundARing) {
  DensityField f;
  f.kind = DensityKind::radial, f.dimension = 2, f.centre = {0, 0, 0}, f.radius = 100;
  f.values = {1, 0};
  f.placement.period = 1000;
  EXPECT_DOUBLE_EQ(f.at({950, 0, 0}), f.at({50, 0, 0}));
  EXPECT_DOUBLE_EQ(f.at({950, 0, 0}), 0.5);
  EXPECT_NEAR(f.most_in({900, 0, 0}, {990, 10, 0}), 0.9, 1e-12);  // its nearest point: 10 away
  f.placement.period = 0;
  EXPECT_DOUBLE_EQ(f.most_in({900, 0, 0}, {990, 10, 0}), 0);
}

}  // namespace curdle
