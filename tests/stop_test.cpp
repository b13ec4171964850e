// Stop points: work stops when the rule installed on its thread says so, within 256 points,
// and nowhere else.
#include "curdle/stop.h"

#include <gtest/gtest.h>

#include <thread>

namespace curdle {
namespace {

class StopAfter : public StopRule {
 public:
  explicit StopAfter(int asks) : left_(asks) {}
  std::optional<std::string> stop_reason() override {
    ++asked;
    if (left_-- > 0) return std::nullopt;
    return "enough";
  }
  int asked = 0;

 private:
  int left_;
};

TEST(Stop, WorkStopsWhenItsRuleSaysSoAndNotBefore) {
  StopAfter rule(3);
  StopScope scope(rule);
  int points = 0;
  try {
    for (;; ++points) stop_point();
  } catch (const WorkStopped& e) {
    EXPECT_STREQ(e.what(), "enough");
  }
  // Asked at the first point, then once every 256: the fourth ask stops it.
  EXPECT_EQ(rule.asked, 4);
  EXPECT_EQ(points, 3 * 256);
}

TEST(Stop, WithoutARuleNothingStopsAndRulesNest) {
  for (int i = 0; i < 100000; ++i) stop_point();  // no rule: never throws
  StopAfter outer(1000000), inner(0);
  StopScope a(outer);
  {
    StopScope b(inner);
    EXPECT_THROW(stop_point_now(), WorkStopped);
  }
  EXPECT_NO_THROW(stop_point_now());  // the outer rule is back
  EXPECT_EQ(outer.asked, 1);
}

TEST(Stop, ARuleHoldsForItsOwnThreadOnly) {
  StopAfter rule(0);
  StopScope scope(rule);
  bool stopped_elsewhere = false;
  std::thread other([&] {
    try {
      stop_point_now();
    } catch (const WorkStopped&) {
      stopped_elsewhere = true;
    }
  });
  other.join();
  EXPECT_FALSE(stopped_elsewhere);
  EXPECT_THROW(stop_point_now(), WorkStopped);
}

}  // namespace
}  // namespace curdle
