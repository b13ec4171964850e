#include "app/fixed_point_text.h"

#include <langinfo.h>

#include <array>
#include <charconv>
#include <cmath>
#include <cstring>

#include "curdle/fixed_text.h"

namespace curdle::app {

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

}  // namespace curdle::app
