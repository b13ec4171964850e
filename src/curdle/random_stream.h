// The random stream: every random choice is a pure function of (seed, curd, stage, cell),
// drawn from Philox4x32-10 (Salmon et al., "Parallel random numbers: as easy as 1, 2, 3",
// SC 2011), so results do not depend on threads, field, window or standard library.
//
// Layout (locked by the golden tests; changing it changes every curd):
//   key     = { seed bits 0-31, seed bits 32-63 }
//   counter = { path bits 0-31, path bits 32-63, root code, tag }
//   tag     = curd << 28 | stage << 22 | kind << 20 | block      (curd < 16, stage < 64)
//   root code: E=1: rx;  E=2: rx | ry << 16;  E=3: rx | ry << 10 | rz << 20.
// Kinds:
//   0 survival bytes: keyed by the children's own paths, 16 to a draw, so that siblings of
//     neighbouring parents share one draw when b^E < 16: child path c reads byte c % 16 of
//     the draw with path c / 16, block 0, byte 4w + q being byte q (least significant first)
//     of output word w. The child survives when its byte is below the top byte of the
//     threshold, dies when above, and on a tie draws kind 1.
//   1 tie break: `path` is the child's path, block 0; the 56 bits (w0 << 32 | w1) >> 8 are
//     compared with the low 56 bits of the threshold. With kind 0 this makes
//     P(survive) = threshold / 2^64 exactly.
//   2 exact-mode keys: `path` is the parent's; block j gives keys of children 2j (w0 << 32 | w1)
//     and 2j + 1 (w2 << 32 | w3); the parent keeps the children with the smallest keys.
//   3 quota keys: `path` is the child's own, block 0, key w0 << 32 | w1.
// A path is the cell's position within its root at its stage (see cell_index.h).
#pragma once

#include <Random123/philox.h>

#include <cstdint>

namespace curdle {

enum class DrawKind : uint32_t { survival = 0, tie_break = 1, exact_key = 2, quota_key = 3 };

class RandomStream {
 public:
  using Block = r123::Philox4x32::ctr_type;

  explicit RandomStream(uint64_t seed)
      : key_{{static_cast<uint32_t>(seed), static_cast<uint32_t>(seed >> 32)}} {}

  static uint32_t tag(uint32_t curd, uint32_t stage, DrawKind kind, uint32_t block) {
    return curd << 28 | stage << 22 | static_cast<uint32_t>(kind) << 20 | block;
  }
  uint32_t key(int word) const { return key_[word]; }

  Block draw(uint64_t path, uint32_t root_code, uint32_t curd, uint32_t stage, DrawKind kind,
             uint32_t block) const {
    const uint32_t tag = RandomStream::tag(curd, stage, kind, block);
    const Block counter{
        {static_cast<uint32_t>(path), static_cast<uint32_t>(path >> 32), root_code, tag}};
    return philox_(counter, key_);
  }

  static uint64_t high_word(const Block& b) { return uint64_t{b[0]} << 32 | b[1]; }
  static uint64_t low_word(const Block& b) { return uint64_t{b[2]} << 32 | b[3]; }

 private:
  r123::Philox4x32::key_type key_;
  r123::Philox4x32 philox_;
};

}  // namespace curdle
