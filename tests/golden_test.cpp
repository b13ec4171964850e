// Golden outputs: the values of a few designs and seeds, hashed. They lock the random stream
// layout (random_stream.h) and the cell order: any change to either changes every curd, and
// must be deliberate (update the hashes and say so in the change).
#include <gtest/gtest.h>

#include "curdle/curdling.h"
#include "curdle/overlay.h"
#include "test_support.h"

namespace curdle {
using test::design;

namespace {

uint64_t fnv1a(const std::vector<uint16_t>& values) {
  uint64_t h = 1469598103934665603ull;
  for (uint16_t v : values) {
    h ^= v;
    h *= 1099511628211ull;
  }
  return h;
}

struct GoldenCase {
  const char* name;
  Design design;
  uint64_t seed;
  Box view;
};

std::vector<GoldenCase> cases() {
  std::vector<GoldenCase> c;
  const Design fig3 = design(4, 2, {{"3/4", "2/3"}, {"3/4", "2/3"}});
  c.push_back({"fig3 seed 3", fig3, 3, fig3.field});
  Design cropped = design(4, 2, {{"2/3", "1/2", "1/3"}});
  cropped.field = Box{{0, 0, 0}, {67, 67, 1}};
  c.push_back({"67x67 canonical", cropped, 7, cropped.field});
  Design quota = cropped;
  quota.lattice.mode = Mode::quota;
  c.push_back({"67x67 quota", quota, 7, quota.field});
  const Design exact = design(4, 2, {{"3/4", "1/2", "1/4"}, {"1/2", "1/2", "1/2"}}, Mode::exact);
  c.push_back({"exact window", exact, 11, Box{{5, 9, 0}, {40, 30, 1}}});
  const Design line = design(3, 1, {{"2/3", "2/3", "2/3", "2/3", "2/3"}});
  c.push_back({"1-D", line, 1, line.field});
  const Design cube = design(2, 3, {{"3/4", "3/4", "3/4", "3/4"}, {"1/2", "1", "1/2", "1"}});
  c.push_back({"3-D", cube, 2, cube.field});
  const Design b9 = design(3, 2, {{"0.7", "0.7", "0.7", "0.7"}});  // b^E = 9: draws span parents
  c.push_back({"b=3 decimal", b9, 5, b9.field});
  return c;
}

const uint64_t kExpected[] = {
    0xfc5aff74dd4c309eull, 0x4aff38be766b07aeull, 0xe4a7450eb242a426ull, 0x9f67e56ae3f08ae7ull,
    0xb8b862160e438780ull, 0x99ce67ad0b7cae88ull, 0x3bc3a6739f41e81bull,
};

}  // namespace

TEST(Golden, ValuesOfFixedSeedsNeverChange) {
  const auto all = cases();
  for (size_t i = 0; i < all.size(); ++i) {
    const GoldenCase& g = all[i];
    const uint64_t h = fnv1a(values_in(curdle(g.design, g.seed, g.view), g.view));
    EXPECT_EQ(h, kExpected[i]) << g.name << ": got 0x" << std::hex << h;
  }
}

}  // namespace curdle
