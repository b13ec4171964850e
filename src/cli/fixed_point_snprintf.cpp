#include "cli/fixed_point_snprintf.h"

#include <langinfo.h>

#include <array>
#include <charconv>
#include <cmath>
#include <cstdarg>
#include <cstring>

#include "curdle/fixed_text.h"

extern "C" {
int __vsnprintf_chk(char* text, size_t size, int flag, size_t room, const char* format,
                    va_list args) noexcept;
}

namespace curdle::cli {

int fixed_point_text(char* text, size_t size, double value, int precision) {
  if (!std::isfinite(value) || precision < 0 || precision > 40) return -1;
  const char* point = nl_langinfo(RADIXCHAR);  // localeconv's, without copying its whole table
  if (point[0] != '.' || point[1] != '\0') return -1;
  std::array<char, 400> digits;  // DBL_MAX has 309 digits before the point
  const auto [end, error] =
      to_chars_fixed(digits.data(), digits.data() + digits.size(), value, precision);
  if (error != std::errc()) return -1;
  const auto length = static_cast<size_t>(end - digits.data());
  if (size > 0) {
    const size_t kept = length < size ? length : size - 1;
    std::memcpy(text, digits.data(), kept);
    text[kept] = '\0';
  }
  return static_cast<int>(length);
}

}  // namespace curdle::cli

namespace {

// The precision of cairo's three formats, reading "%.*f"'s from `args`; -1 for any other.
int fixed_point_precision(const char* format, va_list& args) {
  if (std::strcmp(format, "%f") == 0) return 6;
  if (std::strcmp(format, "%.18f") == 0) return 18;
  if (std::strcmp(format, "%.*f") == 0) return va_arg(args, int);
  return -1;
}

}  // namespace

extern "C" __attribute__((visibility("default"))) int __snprintf_chk(char* text, size_t size,
                                                                     int flag, size_t room,
                                                                     const char* format,
                                                                     ...) noexcept {
  va_list args;
  va_start(args, format);
  int written = -1;
  if (size <= room && format[0] == '%') {  // a size past the buffer is glibc's to refuse
    va_list fast;
    va_copy(fast, args);
    const int precision = fixed_point_precision(format, fast);
    if (precision >= 0)
      written = curdle::cli::fixed_point_text(text, size, va_arg(fast, double), precision);
    va_end(fast);
  }
  if (written < 0) written = __vsnprintf_chk(text, size, flag, room, format, args);
  va_end(args);
  return written;
}
