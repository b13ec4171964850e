#include "curdle/chi_square.h"

#include <gtest/gtest.h>

#include <cmath>

namespace curdle {
namespace {

TEST(ChiSquare, TailsAreTheTablesOnes) {
  // Upper 5 % and 0.1 % points of the chi-square table.
  EXPECT_NEAR(chi_square_tail(3.841, 1), 0.05, 1e-4);
  EXPECT_NEAR(chi_square_tail(5.991, 2), 0.05, 1e-4);
  EXPECT_NEAR(chi_square_tail(18.307, 10), 0.05, 1e-4);
  EXPECT_NEAR(chi_square_tail(29.588, 10), 0.001, 1e-5);
  EXPECT_NEAR(chi_square_tail(124.342, 100), 0.05, 1e-4);
  EXPECT_NEAR(chi_square_tail(2, 2), std::exp(-1.0), 1e-12);  // 2 degrees: e^(-x/2)
}

TEST(ChiSquare, EdgesAreOneOrZero) {
  EXPECT_EQ(chi_square_tail(0, 3), 1.0);
  EXPECT_EQ(chi_square_tail(5, 0), 1.0);  // no test: nothing is unlikely
  EXPECT_LT(chi_square_tail(1e4, 3), 1e-100);
}

}  // namespace
}  // namespace curdle
