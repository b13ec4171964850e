#include "curdle/packed_values.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cstring>
#include <vector>

#include "curdle/view_cells.h"

namespace curdle {

int value_bits(size_t curds) {
  for (int bits : {1, 2, 4, 8})
    if (curds <= static_cast<size_t>(bits)) return bits;
  return 16;
}

namespace {

// Values of `bits` each (a divisor of 64), lowest first, gathered into a word and stored eight
// bytes at a time: no byte is read back.
class BitWriter {
 public:
  BitWriter(uint8_t* out, unsigned bits) : out_(out), bits_(bits) {}
  void put(uint64_t value) {
    word_ |= value << filled_;
    filled_ += bits_;
    if (filled_ == 64) {
      std::memcpy(out_, &word_, 8);  // little-endian, as the page reads it
      out_ += 8;
      word_ = 0;
      filled_ = 0;
    }
  }
  void finish() { std::memcpy(out_, &word_, (filled_ + 7) / 8); }

 private:
  uint8_t* out_;
  unsigned bits_;
  uint64_t word_ = 0;
  unsigned filled_ = 0;
};

// Packs rows [first, end) of the view (rows run over y, then z) from `out` on; `value(i)` is
// the value of finest cell i.
template <class Value>
void pack_rows(const ViewCells& cells, const Box& view, int64_t first, int64_t end, unsigned bits,
               uint8_t* out, const Value& value) {
  BitWriter writer(out, bits);
  for (int64_t r = first; r < end; ++r) {
    const uint64_t row = cells.row(r % view.size[1], r / view.size[1]);
    for (int64_t x = 0; x < view.size[0]; ++x) writer.put(value(cells.at(row, x)));
  }
  writer.finish();
}

}  // namespace

PackedValues pack_values(const CurdField& field, const Box& view) {
  PackedValues out;
  out.bits = value_bits(field.curds.size());
  const unsigned bits = static_cast<unsigned>(out.bits);
  const int64_t rows = view.size[1] * view.size[2];
  out.bytes.resize((view.cells() * bits + 7) / 8);
  auto* bytes = reinterpret_cast<uint8_t*>(out.bytes.data());
  const ViewCells cells(field, view);
  // CurdField::value_of, with each curd's words' address held here: through the field, every
  // byte the writer stores might move them, and they were loaded again each cell (2048 x 2048:
  // 14 % slower for one curd, 4-8 % for two).
  std::vector<const uint64_t*> finest;
  for (size_t c = 0; c < field.curds.size(); ++c) finest.push_back(field.finest(c).words.data());
  // Blocks of rows that start on a whole byte (a multiple of 8 rows always does), so that no
  // two blocks write to one byte.
  constexpr int64_t kBlock = 64;
  tbb::parallel_for(tbb::blocked_range<int64_t>(0, (rows + kBlock - 1) / kBlock),
                    [&](const tbb::blocked_range<int64_t>& blocks) {
                      for (int64_t b = blocks.begin(); b < blocks.end(); ++b) {
                        const int64_t first = b * kBlock, end = std::min(rows, first + kBlock);
                        uint8_t* at =
                            bytes + static_cast<uint64_t>(first * view.size[0]) * bits / 8;
                        if (finest.size() == 1) {  // the page's usual field: no loop
                          const uint64_t* words = finest[0];
                          pack_rows(cells, view, first, end, bits, at,
                                    [words](uint64_t i) { return words[i >> 6] >> (i & 63) & 1; });
                        } else {
                          pack_rows(cells, view, first, end, bits, at, [&finest](uint64_t i) {
                            uint64_t v = 0;
                            for (size_t c = 0; c < finest.size(); ++c)
                              v |= (finest[c][i >> 6] >> (i & 63) & 1) << c;
                            return v;
                          });
                        }
                      }
                    });
  return out;
}

}  // namespace curdle
