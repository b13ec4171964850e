// Tests of check.h: a broken invariant stops at its line, naming the condition, both values
// and the note; a kept one costs nothing and evaluates each side once.
#include "curdle/check.h"

#include <gtest/gtest.h>

#include <string>

namespace curdle {
namespace {

TEST(Check, AKeptInvariantPassesAndEvaluatesEachSideOnce) {
  int calls = 0;
  auto next = [&] { return ++calls; };
  CHECK(next() == 1);
  CHECK_EQ(next(), 2);
  CHECK_LT(next(), 4);
  CHECK_GE(next(), 4);
  CHECK(true, "a note is only read when the check fails");
  EXPECT_EQ(calls, 4);
}

TEST(Check, ABrokenOneStopsAtItsLineWithItsValuesAndNote) {
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  const int cells = 3, values = 4;
  EXPECT_DEATH(CHECK_EQ(cells, values),
               "check_test.cpp:[0-9]+: check failed: cells == values \\(3 vs 4\\)");
  EXPECT_DEATH(CHECK(cells > values, "more cells than values"),
               "check failed: cells > values: more cells than values");
  EXPECT_DEATH(CHECK_NE(std::string("a"), std::string("a")), "\\(a vs a\\)");
}

TEST(Check, ADebugCheckIsNothingInARelease) {
  int calls = 0;
  DCHECK(++calls == 1);
#ifdef NDEBUG
  EXPECT_EQ(calls, 0);
#else
  EXPECT_EQ(calls, 1);
#endif
}

}  // namespace
}  // namespace curdle
