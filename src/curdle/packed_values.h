// The values of a view's cells packed into as few bits as their curds need: one bit a cell for
// one curd, two for two, four for three or four, a byte up to eight, two bytes beyond. The page
// draws the curd from these (its canvas unpacks them on the GPU), so that a 2048 x 2048 field
// of one curd is 512 KB to send, not 4 MB.
#pragma once

#include <cstddef>
#include <string>

#include "curdle/curd.h"

namespace curdle {

// Bits a cell for `curds` curds (bit planes): 1, 2, 4, 8 or 16.
int value_bits(size_t curds);

// Cells in row-major order (x fastest, then y, then z); cell i's value at bits
// [i * bits % 8, ...) of byte i * bits / 8, lowest bits first (two bytes little-endian at 16).
// Rows are packed in parallel.
struct PackedValues {
  int bits = 1;
  std::string bytes;
};
PackedValues pack_values(const CurdField& field, const Box& view);

}  // namespace curdle
