#include "curdle/fixed_text.h"

#include <array>
#include <bit>
#include <cstdint>
#include <cstring>

namespace curdle {
namespace {

constexpr std::array<uint64_t, 19> kPowersOfTen = [] {
  std::array<uint64_t, 19> p{};
  p[0] = 1;
  for (size_t i = 1; i < p.size(); ++i) p[i] = p[i - 1] * 10;
  return p;
}();

// The text longest written here: a sign, 20 digits, the point and 18 decimals.
constexpr std::ptrdiff_t kLongest = 1 + 20 + 1 + 18;

}  // namespace

std::to_chars_result to_chars_fixed(char* first, char* last, double value, int precision) {
  const auto bits = std::bit_cast<uint64_t>(value);
  const auto biased = static_cast<int>(bits >> 52 & 0x7ff);
  uint64_t mantissa = bits & ((uint64_t{1} << 52) - 1);
  if (biased != 0) mantissa |= uint64_t{1} << 52;
  const int exponent = (biased != 0 ? biased : 1) - 1075;  // value = ±mantissa * 2^exponent
  const bool fast = biased != 0x7ff && precision >= 0 && precision <= 18 && exponent <= 11 &&
                    (mantissa == 0 || exponent >= -64) && last - first >= kLongest;
  if (!fast) return std::to_chars(first, last, value, std::chars_format::fixed, precision);
  // The whole part, and the fraction as `fraction` / 2^shift.
  uint64_t whole = 0, fraction = 0;
  int shift = 0;
  if (mantissa == 0) {  // ±0
  } else if (exponent >= 0) {
    whole = mantissa << exponent;
  } else {
    shift = -exponent;
    whole = shift == 64 ? 0 : mantissa >> shift;
    fraction = shift == 64 ? mantissa : mantissa & ((uint64_t{1} << shift) - 1);
  }
  // The decimals: fraction * 10^precision / 2^shift, rounded to nearest, ties to even.
  uint64_t decimals = 0;
  if (shift > 0) {
    const unsigned __int128 scaled =
        static_cast<unsigned __int128>(fraction) * kPowersOfTen[static_cast<size_t>(precision)];
    decimals = static_cast<uint64_t>(scaled >> shift);
    const unsigned __int128 rest = scaled - (static_cast<unsigned __int128>(decimals) << shift);
    const unsigned __int128 half = static_cast<unsigned __int128>(1) << (shift - 1);
    const uint64_t last_digit = precision > 0 ? decimals : whole;  // its parity breaks a tie
    if (rest > half || (rest == half && (last_digit & 1) != 0)) ++decimals;
    if (decimals == kPowersOfTen[static_cast<size_t>(precision)]) {  // 0.9996 -> 1.000
      decimals = 0;
      ++whole;
    }
  }
  char* out = first;
  if (bits >> 63) *out++ = '-';
  out = std::to_chars(out, last, whole).ptr;
  if (precision > 0) {
    *out++ = '.';
    char* end = out + precision;
    for (char* digit = end; digit != out; decimals /= 10)
      *--digit = static_cast<char>('0' + decimals % 10);
    out = end;
  }
  return {out, std::errc()};
}

}  // namespace curdle
