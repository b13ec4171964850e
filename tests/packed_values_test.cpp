// Values packed to as few bits as their curds need: the same values as values_in, for one to
// nine curds, over views whose rows do not end on a whole byte, in two and three dimensions.
#include "curdle/packed_values.h"

#include <gtest/gtest.h>

#include "curdle/curdling.h"
#include "curdle/overlay.h"
#include "test_support.h"

namespace curdle {
namespace {

TEST(PackedValues, BitsFollowTheCurds) {
  EXPECT_EQ(value_bits(0), 1);
  EXPECT_EQ(value_bits(1), 1);
  EXPECT_EQ(value_bits(2), 2);
  EXPECT_EQ(value_bits(3), 4);
  EXPECT_EQ(value_bits(4), 4);
  EXPECT_EQ(value_bits(5), 8);
  EXPECT_EQ(value_bits(8), 8);
  EXPECT_EQ(value_bits(9), 16);
}

uint32_t unpacked(const PackedValues& p, size_t i) {
  const auto* b = reinterpret_cast<const uint8_t*>(p.bytes.data());
  const size_t at = i * static_cast<size_t>(p.bits);
  if (p.bits == 16) return b[at / 8] | b[at / 8 + 1] << 8;
  return b[at / 8] >> (at % 8) & ((1u << p.bits) - 1);
}

TEST(PackedValues, UnpackToTheValuesOfEveryCell) {
  for (const int curds : {1, 2, 3, 5, 9}) {
    for (const int dimension : {2, 3}) {
      std::vector<std::vector<std::string>> probabilities(curds, {"3/4", "2/3", "3/4"});
      const Design d = test::design(4, dimension, probabilities);
      // Rows of 37 cells: a row ends inside a byte at every width but 8 and 16 bits; 150 rows
      // make blocks of 64 rows and a last short one, and run over z slices in 3-D.
      Box view = d.field;
      view.origin = {3, 5, 0};
      view.size = {37, dimension == 2 ? 150 : 30, dimension == 2 ? 1 : 5};
      const CurdField field = curdle(d, 11, view);
      const PackedValues p = pack_values(field, view);
      const std::vector<uint16_t> want = values_in(field, view);
      ASSERT_EQ(p.bits, value_bits(static_cast<size_t>(curds)));
      ASSERT_EQ(p.bytes.size(), (want.size() * static_cast<size_t>(p.bits) + 7) / 8);
      size_t wrong = 0, nonzero = 0;
      for (size_t i = 0; i < want.size(); ++i) {
        wrong += unpacked(p, i) != want[i];
        nonzero += want[i] != 0;
      }
      EXPECT_EQ(wrong, 0u) << curds << " curds, E = " << dimension;
      EXPECT_GT(nonzero, want.size() / 10);
    }
  }
}

}  // namespace
}  // namespace curdle
