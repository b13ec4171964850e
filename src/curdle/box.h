// An axis-aligned box of finest cells. Axes beyond the lattice's dimension have origin 0 and
// size 1, so 1-, 2- and 3-D boxes share one type.
#pragma once

#include <array>
#include <cstdint>

namespace curdle {

// Division rounding towards minus infinity: which root or stage cell a coordinate falls in.
inline int64_t floor_div(int64_t a, int64_t b) { return a >= 0 ? a / b : -((-a + b - 1) / b); }

struct Box {
  std::array<int64_t, 3> origin{0, 0, 0};
  std::array<int64_t, 3> size{1, 1, 1};

  uint64_t cells() const {
    return static_cast<uint64_t>(size[0]) * static_cast<uint64_t>(size[1]) *
           static_cast<uint64_t>(size[2]);
  }
  bool contains(const Box& inner) const {
    for (int d = 0; d < 3; ++d)
      if (inner.origin[d] < origin[d] || inner.origin[d] + inner.size[d] > origin[d] + size[d])
        return false;
    return true;
  }
  bool operator==(const Box&) const = default;
};

}  // namespace curdle
