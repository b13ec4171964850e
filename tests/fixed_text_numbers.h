// Numbers whose fixed-point text is easy to get wrong, for the tests of to_chars_fixed and of
// the programs' "%f": signed zeros, ties at every precision (odd multiples of 2^-k and halves),
// the edges of the fast path (2^63, 2^64, 1e19), the extremes of double, lengths in mm, and
// random numbers over the decimal range and over every bit pattern that is a number.
#pragma once

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <vector>

namespace curdle::test {

inline std::vector<double> hard_fixed_numbers() {
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
                           5e-19,
                           1.0 / 1024,
                           3.0 / 2048,
                           1e22,
                           1e300,
                           -1e300,
                           123456.789,
                           595.2755905511812};
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

}  // namespace curdle::test
