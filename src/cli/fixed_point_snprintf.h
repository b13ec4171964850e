// A fast path for the one printf that layout.pdf leans on. cairo writes every coordinate of a
// PDF with snprintf("%f"), "%.18f" or "%.*f" (its _cairo_dtostr), built fortified, so through
// __snprintf_chk; glibc prints a double with arbitrary-precision arithmetic, and that was a
// tenth of the pavilion's whole run. Defined in fixed_point_snprintf.cpp and exported from the
// programs (CMakeLists.txt), __snprintf_chk comes before glibc's for every library: those three
// formats, of a finite number in a locale whose decimal point is '.', are written by
// std::to_chars, which rounds the exact binary value to nearest, ties to even, as glibc does, so
// the text is the same to the byte; every other call goes on to glibc.
#pragma once

#include <cstddef>

namespace curdle::cli {

// `value` with `precision` decimals as snprintf's "%.*f" writes it into `text` of `size` bytes
// (cut to fit, always ended by a NUL when size > 0): the length of the whole text, or -1 where
// glibc is to write it (not finite, a precision past 40, a decimal point other than '.').
int fixed_point_text(char* text, size_t size, double value, int precision);

}  // namespace curdle::cli
