#include "curdle/probability.h"

#include <gtest/gtest.h>

#include <cmath>

namespace curdle {

TEST(Probability, ParsesFractionsAndDecimalsExactly) {
  auto p = Probability::parse("3/4");
  ASSERT_TRUE(p);
  EXPECT_DOUBLE_EQ(p->value(), 0.75);
  EXPECT_EQ(p->threshold(), uint64_t{3} << 62);
  auto q = Probability::parse("0.7");
  ASSERT_TRUE(q);
  EXPECT_EQ(q->numerator(), 7u);
  EXPECT_EQ(q->denominator(), 10u);
  EXPECT_TRUE(Probability::parse("1")->certain());
  EXPECT_EQ(Probability::parse("0")->threshold(), 0u);
  EXPECT_EQ(Probability::parse(" 2/3 ")->text(), "2/3");
}

TEST(Probability, RejectsImpossibleValues) {
  for (const char* bad : {"", "4/3", "1/0", "-0.5", "1.5", "abc", "1/2/3", "0.5.5", "2", "."})
    EXPECT_FALSE(Probability::parse(bad)) << bad;
  EXPECT_FALSE(Probability::from_double(-0.1));
  EXPECT_FALSE(Probability::from_double(1.01));
  EXPECT_FALSE(Probability::from_double(std::nan("")));
}

TEST(Probability, FromDoubleKeepsTheTypedDecimal) {
  auto p = Probability::from_double(0.7);
  ASSERT_TRUE(p);
  EXPECT_TRUE(p->is_rational());
  EXPECT_EQ(p->denominator(), 10u);
}

TEST(Probability, WholeMultiplesAndRounding) {
  EXPECT_TRUE(Probability::parse("3/4")->times_is_whole(16));
  EXPECT_FALSE(Probability::parse("2/3")->times_is_whole(16));
  EXPECT_EQ(Probability::parse("2/3")->round_times(16), 11u);  // 10.67
  EXPECT_EQ(Probability::parse("1/2")->round_times(9), 5u);    // 4.5 rounds up
}

}  // namespace curdle

// The batched generator must give Random123's Philox4x32-10 bit for bit, on any CPU path.
#include <Random123/philox.h>

#include <random>

#include "curdle/philox_batch.h"

namespace curdle {

TEST(PhiloxBatch, MatchesRandom123BitForBit) {
  std::mt19937 rng(7);
  for (size_t n : {1u, 7u, 8u, 9u, 64u, 1000u}) {
    std::vector<uint32_t> w[4];
    for (auto& v : w) {
      v.resize(n);
      for (auto& x : v) x = rng();
    }
    const uint32_t k0 = rng(), k1 = rng();
    std::vector<uint32_t> in[4] = {w[0], w[1], w[2], w[3]};
    philox_in_place(w[0].data(), w[1].data(), w[2].data(), w[3].data(), n, k0, k1);
    const r123::Philox4x32 philox;
    for (size_t i = 0; i < n; ++i) {
      const auto r = philox(r123::Philox4x32::ctr_type{{in[0][i], in[1][i], in[2][i], in[3][i]}},
                            r123::Philox4x32::key_type{{k0, k1}});
      for (int j = 0; j < 4; ++j) ASSERT_EQ(w[j][i], r[j]) << "counter " << i << " word " << j;
    }
  }
}

}  // namespace curdle

namespace curdle {

TEST(Probability, ExactSumsInLowestTermsWhileTheyFit) {
  std::vector<Probability> p;
  for (const char* t : {"1/3", "1/6", "1/4", "0.25"}) p.push_back(*Probability::parse(t));
  EXPECT_EQ(exact_sum(p, 2), (std::pair<uint64_t, uint64_t>{1, 2}));
  EXPECT_EQ(exact_sum(p, 4), (std::pair<uint64_t, uint64_t>{1, 1}));
  EXPECT_EQ(exact_sum(p, 0), (std::pair<uint64_t, uint64_t>{0, 1}));
  p.push_back(*Probability::from_double(0.1));
  EXPECT_EQ(exact_sum(p, 5).has_value(), p[4].is_rational());
}

}  // namespace curdle
