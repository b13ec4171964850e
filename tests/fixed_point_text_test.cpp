// The programs' fast path for cairo's "%f" gives glibc's text to the byte: rounding to nearest
// with ties to even, signs, zeros, cut buffers and the length returned; everything else is
// glibc's own.
#include "app/fixed_point_text.h"

#include <gtest/gtest.h>

#include <clocale>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include "fixed_text_numbers.h"

extern "C" int __snprintf_chk(char* text, size_t size, int flag, size_t room, const char* format,
                              ...) noexcept;

namespace curdle::app {
namespace {

std::string glibc_text(double v, int precision, int* length) {
  std::vector<char> text(512);
  *length = std::snprintf(text.data(), text.size(), "%.*f", precision, v);
  return text.data();
}

void expect_as_glibc(double v, int precision) {
  int glibc_length = 0;
  const std::string expected = glibc_text(v, precision, &glibc_length);
  std::vector<char> text(512, 'x');
  const int length = fixed_point_text(text.data(), text.size(), v, precision);
  ASSERT_EQ(length, glibc_length) << v << " to " << precision;
  ASSERT_EQ(std::string(text.data()), expected) << v << " to " << precision;
}

TEST(FixedPointSnprintf, TheSameTextAsGlibcForEveryKindOfNumber) {
  for (const double v : curdle::test::hard_fixed_numbers())
    for (const int precision : {0, 1, 3, 6, 9, 12, 18, 25, 40}) expect_as_glibc(v, precision);
}

TEST(FixedPointSnprintf, ACutBufferKeepsWhatFitsAndTellsTheWholeLength) {
  for (const size_t size : {0, 1, 2, 5, 9, 10, 11}) {
    std::vector<char> ours(16, 'x'), glibc(16, 'x');
    const int length = fixed_point_text(ours.data(), size, -12.3456789, 6);
    const int expected = std::snprintf(glibc.data(), size, "%.*f", 6, -12.3456789);
    EXPECT_EQ(length, expected) << size;
    EXPECT_EQ(ours, glibc) << size;  // the bytes past the NUL untouched too
  }
}

TEST(FixedPointSnprintf, LeavesToGlibcWhatItDoesNotWrite) {
  char text[64];
  EXPECT_EQ(fixed_point_text(text, sizeof text, std::nan(""), 6), -1);
  EXPECT_EQ(fixed_point_text(text, sizeof text, -INFINITY, 6), -1);
  EXPECT_EQ(fixed_point_text(text, sizeof text, 1.5, 41), -1);
  EXPECT_EQ(fixed_point_text(text, sizeof text, 1.5, -1), -1);
  // A decimal comma is glibc's to write (where the machine has such a locale).
  const std::string before = std::setlocale(LC_NUMERIC, nullptr);
  for (const char* comma : {"de_DE.UTF-8", "fr_FR.UTF-8", "ru_RU.UTF-8"})
    if (std::setlocale(LC_NUMERIC, comma)) {
      EXPECT_EQ(fixed_point_text(text, sizeof text, 1.5, 6), -1) << comma;
      break;
    }
  std::setlocale(LC_NUMERIC, before.c_str());
}

// The entry point itself, as cairo calls it: its three formats, and others passed on whole.
TEST(FixedPointSnprintf, TheEntryPointWritesCairosFormatsAndPassesOnTheRest) {
  char text[64];
  const char* volatile format = "%f";  // not folded by the compiler
  EXPECT_EQ(__snprintf_chk(text, sizeof text, 1, sizeof text, format, 2.0 / 3), 8);
  EXPECT_STREQ(text, "0.666667");
  format = "%.18f";
  __snprintf_chk(text, sizeof text, 1, sizeof text, format, 0.0078125);
  EXPECT_STREQ(text, "0.007812500000000000");
  format = "%.*f";
  __snprintf_chk(text, sizeof text, 1, sizeof text, format, 3, 0.0625);
  EXPECT_STREQ(text, "0.062");                                          // a tie, to even
  __snprintf_chk(text, sizeof text, 1, sizeof text, format, -1, 0.25);  // as if none: 6
  EXPECT_STREQ(text, "0.250000");
  format = "%s=%d %g";
  EXPECT_EQ(__snprintf_chk(text, sizeof text, 1, sizeof text, format, "n", 42, 1e-9), 10);
  EXPECT_STREQ(text, "n=42 1e-09");
  format = "%f";
  __snprintf_chk(text, sizeof text, 1, sizeof text, format, NAN);
  EXPECT_STREQ(text, "nan");
}

}  // namespace
}  // namespace curdle::app
