#include "curdle/packed_values.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>

#include "curdle/overlay.h"

namespace curdle {

int value_bits(size_t curds) {
  for (int bits : {1, 2, 4, 8})
    if (curds <= static_cast<size_t>(bits)) return bits;
  return 16;
}

PackedValues pack_values(const CurdField& field, const Box& view) {
  PackedValues out;
  out.bits = value_bits(field.curds.size());
  const uint64_t bits = static_cast<uint64_t>(out.bits);
  const int64_t width = view.size[0], height = view.size[1], rows = height * view.size[2];
  out.bytes.assign((view.cells() * bits + 7) / 8, '\0');
  auto* bytes = reinterpret_cast<uint8_t*>(out.bytes.data());
  // Blocks of rows that start on a whole byte (a multiple of 8 rows always does), so that no
  // two blocks write to one byte; a block may run over two z slices.
  constexpr int64_t kBlock = 64;
  tbb::parallel_for(tbb::blocked_range<int64_t>(0, (rows + kBlock - 1) / kBlock),
                    [&](const tbb::blocked_range<int64_t>& blocks) {
                      for (int64_t b = blocks.begin(); b < blocks.end(); ++b) {
                        int64_t r = b * kBlock;
                        const int64_t end = std::min(rows, r + kBlock);
                        while (r < end) {
                          const int64_t z = r / height, y = r % height;
                          const int64_t n = std::min(end - r, height - y);
                          Box part = view;
                          part.origin[1] += y;
                          part.origin[2] += z;
                          part.size[1] = n;
                          part.size[2] = 1;
                          uint64_t at = static_cast<uint64_t>(r * width) * bits;  // in bits
                          scan_rows(field, part,
                                    [&](int64_t, int64_t, std::span<const uint16_t> values) {
                                      for (const uint16_t v : values) {
                                        if (bits == 16) {
                                          bytes[at / 8] = static_cast<uint8_t>(v & 0xff);
                                          bytes[at / 8 + 1] = static_cast<uint8_t>(v >> 8);
                                        } else {
                                          bytes[at / 8] |= static_cast<uint8_t>(v << (at % 8));
                                        }
                                        at += bits;
                                      }
                                    });
                          r += n;
                        }
                      }
                    });
  return out;
}

}  // namespace curdle
