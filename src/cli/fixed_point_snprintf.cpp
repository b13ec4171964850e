// A fast path for the one printf that layout.pdf leans on. cairo writes every coordinate of a
// PDF with snprintf("%f"), "%.18f" or "%.*f" (its _cairo_dtostr), built fortified, so through
// __snprintf_chk; glibc prints a double with arbitrary-precision arithmetic, and that was a
// tenth of the pavilion's whole run. Defined here and exported from the programs
// (CMakeLists.txt), __snprintf_chk comes before glibc's for every library: those three formats
// are written by app::fixed_point_text, the same text to the byte; every other call, and any
// it leaves to glibc, goes on to glibc.
#include <cstdarg>
#include <cstddef>
#include <cstring>

#include "app/fixed_point_text.h"

extern "C" {
int __vsnprintf_chk(char* text, size_t size, int flag, size_t room, const char* format,
                    va_list args) noexcept;
}

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
      written = curdle::app::fixed_point_text(text, size, va_arg(fast, double), precision);
    va_end(fast);
  }
  if (written < 0) written = __vsnprintf_chk(text, size, flag, room, format, args);
  va_end(args);
  return written;
}
