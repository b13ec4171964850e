// Tests of philox_batch.h: the batched Philox4x32-10 gives Random123's words for every counter,
// for batch sizes that are and are not multiples of the vector width.
#include "curdle/philox_batch.h"

#include <Random123/philox.h>
#include <gtest/gtest.h>

#include <vector>

namespace curdle {
namespace {

TEST(PhiloxBatch, IsRandom123sPhilox4x32WordForWord) {
  const uint32_t key0 = 0x9e3779b9, key1 = 12345;
  for (const size_t n : {1u, 7u, 8u, 9u, 100u}) {
    std::vector<uint32_t> w0(n), w1(n), w2(n), w3(n);
    for (size_t i = 0; i < n; ++i)
      w0[i] = static_cast<uint32_t>(i), w1[i] = 77, w2[i] = static_cast<uint32_t>(i * 31),
      w3[i] = 0xabcdef;
    const auto in = std::vector<std::vector<uint32_t>>{w0, w1, w2, w3};
    philox_in_place(w0.data(), w1.data(), w2.data(), w3.data(), n, key0, key1);
    r123::Philox4x32 philox;
    for (size_t i = 0; i < n; ++i) {
      const r123::Philox4x32::ctr_type c{{in[0][i], in[1][i], in[2][i], in[3][i]}};
      const auto r = philox(c, r123::Philox4x32::key_type{{key0, key1}});
      EXPECT_EQ(w0[i], r[0]) << n << " " << i;
      EXPECT_EQ(w1[i], r[1]);
      EXPECT_EQ(w2[i], r[2]);
      EXPECT_EQ(w3[i], r[3]);
    }
  }
}

}  // namespace
}  // namespace curdle
