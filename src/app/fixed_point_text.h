// What the programs' snprintf writes for cairo's "%f", "%.18f" and "%.*f" (src/cli/
// fixed_point_snprintf.cpp): glibc prints a double with arbitrary-precision arithmetic, and
// cairo writes every coordinate of layout.pdf that way; to_chars_fixed gives the same text.
#pragma once

#include <cstddef>

namespace curdle::app {

// `value` with `precision` decimals as snprintf's "%.*f" writes it into `text` of `size` bytes
// (cut to fit, always ended by a NUL when size > 0): the length of the whole text, or -1 where
// glibc is to write it (not finite, a precision past 40, a decimal point other than '.').
int fixed_point_text(char* text, size_t size, double value, int precision);

}  // namespace curdle::app
