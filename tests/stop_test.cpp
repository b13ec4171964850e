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

// Whether this thread's rule stops work at a point that asks it now.
bool stops_now() {
  try {
    stop_point_now();
  } catch (const WorkStopped&) {
    return true;
  }
  return false;
}

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
  std::thread other([&] { stopped_elsewhere = stops_now(); });
  other.join();
  EXPECT_FALSE(stopped_elsewhere);
  EXPECT_THROW(stop_point_now(), WorkStopped);
}

// Work handed to another thread takes the rule it was handed with (current_stop_rule() there),
// and none leaves that thread as it is.
TEST(Stop, HandedOverWorkTakesTheRuleItCameWith) {
  StopAfter rule(0);
  StopRule* handed = nullptr;
  {
    StopScope scope(rule);
    handed = current_stop_rule();
  }
  bool stopped = false, stopped_without = true;
  std::thread other([&] {
    {
      const StopScope none(static_cast<StopRule*>(nullptr));
      stopped_without = current_stop_rule() != nullptr;
    }
    const StopScope scope(handed);
    stopped = stops_now();
  });
  other.join();
  EXPECT_TRUE(stopped);
  EXPECT_FALSE(stopped_without);
  StopAfter outer(1000000);
  const StopScope kept(outer);
  {
    const StopScope none(static_cast<StopRule*>(nullptr));
    EXPECT_EQ(current_stop_rule(), &outer);
  }
  EXPECT_EQ(current_stop_rule(), &outer);
}

}  // namespace
}  // namespace curdle
