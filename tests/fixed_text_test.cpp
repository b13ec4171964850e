// to_chars_fixed writes std::to_chars's fixed text to the byte: every precision to 18, ties to
// even, signs and zeros, the edges of its fast path and what it leaves to std::to_chars.
#include "curdle/fixed_text.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "fixed_text_numbers.h"

namespace curdle {
namespace {

std::string standard(double v, int precision) {
  std::array<char, 600> text;
  const auto r =
      std::to_chars(text.data(), text.data() + text.size(), v, std::chars_format::fixed, precision);
  return std::string(text.data(), r.ptr);
}

std::string ours(double v, int precision) {
  std::array<char, 600> text;
  const auto r = to_chars_fixed(text.data(), text.data() + text.size(), v, precision);
  EXPECT_EQ(r.ec, std::errc());
  return std::string(text.data(), r.ptr);
}

TEST(FixedText, TheSameTextAsToCharsAtEveryPrecision) {
  for (const double v : test::hard_fixed_numbers())
    for (int precision = 0; precision <= 18; ++precision)
      ASSERT_EQ(ours(v, precision), standard(v, precision)) << v << " to " << precision;
}

TEST(FixedText, PastItsFastPathStdToCharsWritesIt) {
  for (const double v : {1e300, -1e25, std::ldexp(1.0, -80), 1e-300})
    for (const int precision : {0, 6, 16, 19, 25, 40})
      EXPECT_EQ(ours(v, precision), standard(v, precision));
  std::array<char, 4> small;
  EXPECT_EQ(to_chars_fixed(small.data(), small.data() + small.size(), 12345.5, 3).ec,
            std::errc::value_too_large);
  EXPECT_EQ(ours(std::numeric_limits<double>::infinity(), 3), "inf");
}

}  // namespace
}  // namespace curdle
