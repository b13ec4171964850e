// Tests of design_reader.h.
#include "recipe/design_reader.h"

#include <gtest/gtest.h>

#include "recipe_support.h"

namespace curdle {
TEST(Recipe, ExactModeNeedsWholeCounts) {
  const std::string e = error_of(kGood, {"lattice.mode=exact"});
  EXPECT_NE(e.find("curds.0.probabilities.1"), std::string::npos) << e;
  EXPECT_NE(e.find("not a whole number"), std::string::npos) << e;
}

}  // namespace curdle
