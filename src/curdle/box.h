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
  // Largest origin or size a box may have: far beyond any field, and sums of two stay exact.
  static constexpr int64_t kLimit = int64_t{1} << 40;
  // Origins from 0 and sizes from 1, both at most kLimit: what every caller-given box must be.
  bool well_formed() const {
    for (int d = 0; d < 3; ++d)
      if (origin[d] < 0 || origin[d] > kLimit || size[d] < 1 || size[d] > kLimit) return false;
    return true;
  }
  // Written without sums that could overflow, for boxes that are not yet checked.
  bool contains(const Box& inner) const {
    for (int d = 0; d < 3; ++d)
      if (inner.size[d] < 1 || inner.origin[d] < origin[d] || inner.size[d] > size[d] ||
          inner.origin[d] - origin[d] > size[d] - inner.size[d])
        return false;
    return true;
  }
  bool operator==(const Box&) const = default;
};

}  // namespace curdle
