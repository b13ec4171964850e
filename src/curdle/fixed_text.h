// Numbers in fixed notation, fast and exact. The files curdle writes print most of their
// numbers this way (a DXF's coordinates to 16 decimals, lengths to the micrometre, a PDF's
// coordinates through cairo's "%f"), and std::to_chars spends a general algorithm on each: a
// double's exact value is a 53-bit integer over a power of two, so for most numbers its
// decimals to 18 places come from one 128-bit product.
#pragma once

#include <charconv>

namespace curdle {

// What std::to_chars(first, last, value, std::chars_format::fixed, precision) writes, to the
// byte: the exact binary value rounded to `precision` decimals, to nearest with ties to even (as
// glibc's printf "%.*f" too), a '-' on every negative number and -0. Numbers of 2^64 or more,
// below 2^-64 in size but not 0, not finite, or a precision past 18 go to std::to_chars itself.
std::to_chars_result to_chars_fixed(char* first, char* last, double value, int precision);

}  // namespace curdle
