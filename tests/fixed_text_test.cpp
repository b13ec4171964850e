// to_chars_fixed writes std::to_chars's fixed text to the byte: every precision to 18, ties to
// even, signs and zeros, the edges of its fast path and what it leaves to std::to_chars.
#include "curdle/fixed_text.h"

#include <gtest/gtest.h>

#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <string>
#include <vector>

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

std::vector<double> numbers() {
  std::vector<double> v = {0.0,
                           -0.0,
                           1.0,
                           -1.0,
                           0.5,
                           1.5,
                           2.5,
                           3.5,
                           -2.5,
                           0.125,
                           0.0078125,
                           0.1,
                           0.05,
                           1e-7,
                           5e-7,
                           9.9999999,
                           0.99999999999999999,
                           1e15,
                           1e19,
                           1.8e19,
                           1.9e19,
                           1e20,
                           std::ldexp(1.0, 64),
                           std::ldexp(1.0, 63),
                           std::ldexp(1.0, -64),
                           std::ldexp(1.0, -65),
                           std::ldexp(3.0, -66),
                           std::numeric_limits<double>::max(),
                           std::numeric_limits<double>::min(),
                           std::numeric_limits<double>::denorm_min(),
                           1234.567,
                           215.0 / 3,
                           841.8897637795275,
                           -0.0004999,
                           0.0005,
                           999.9995,
                           1e-18,
                           5e-19};
  // Ties at every precision: odd multiples of 2^-k.
  for (int k = 1; k <= 64; ++k)
    for (int odd = 1; odd < 64; odd += 2) v.push_back(std::ldexp(odd, -k));
  for (int whole = 0; whole < 40; ++whole) v.push_back(whole + 0.5);
  std::mt19937_64 random(11);
  std::uniform_real_distribution<double> exponent(-25, 22);
  for (int i = 0; i < 5000; ++i) v.push_back(std::pow(10.0, exponent(random)) * (i % 2 ? -1 : 1));
  for (int i = 0; i < 3000; ++i) {  // any bit pattern that is a number
    const double d = std::bit_cast<double>(random());
    if (std::isfinite(d)) v.push_back(d);
  }
  for (int i = 0; i < 2000; ++i) v.push_back(std::round(exponent(random) * 1e6) / 1e3);  // mm
  return v;
}

TEST(FixedText, TheSameTextAsToCharsAtEveryPrecision) {
  for (const double v : numbers())
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
