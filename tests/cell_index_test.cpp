#include "curdle/cell_index.h"

#include <gtest/gtest.h>

#include <random>

namespace curdle {

struct IndexCase {
  int base, dimension, stages;
};

class CellIndexTest : public ::testing::TestWithParam<IndexCase> {};

TEST_P(CellIndexTest, FinestIndexAndDecodeAreInverse) {
  const auto [b, E, K] = GetParam();
  Lattice l{b, E, K, Mode::canonical};
  const int64_t side = static_cast<int64_t>(l.root_side());
  Box covered;
  for (int d = 0; d < E; ++d) covered.origin[d] = side, covered.size[d] = 2 * side + 3;
  const CellIndex index(l, covered);
  std::mt19937_64 rng(1);
  for (int trial = 0; trial < 2000; ++trial) {
    Coord c{0, 0, 0};
    for (int d = 0; d < E; ++d)
      c[d] = covered.origin[d] + static_cast<int64_t>(rng() % covered.size[d]);
    const uint64_t i = index.finest_index(c);
    EXPECT_EQ(index.decode(K, i), c);
  }
}

TEST_P(CellIndexTest, ChildrenAreConsecutiveBits) {
  const auto [b, E, K] = GetParam();
  Lattice l{b, E, K, Mode::canonical};
  const CellIndex index(l, Box{{0, 0, 0}, {static_cast<int64_t>(l.root_side()) * 2, 1, 1}});
  const uint64_t B = l.children();
  for (int k = 1; k <= K; ++k)
    for (uint64_t parent = 0;
         parent < std::min<uint64_t>(50, index.roots() * l.cells_per_root(k - 1)); ++parent) {
      const Coord p = index.decode(k - 1, parent);
      for (uint64_t t = 0; t < B; ++t) {
        const Coord c = index.decode(k, parent * B + t);
        for (int d = 0; d < E; ++d) EXPECT_EQ(c[d] / b, p[d]);
      }
    }
}

INSTANTIATE_TEST_SUITE_P(Lattices, CellIndexTest,
                         ::testing::Values(IndexCase{2, 1, 5}, IndexCase{3, 1, 4},
                                           IndexCase{2, 2, 5}, IndexCase{4, 2, 3},
                                           IndexCase{3, 2, 3}, IndexCase{8, 2, 2},
                                           IndexCase{2, 3, 4}, IndexCase{4, 3, 2},
                                           IndexCase{5, 3, 2}));

}  // namespace curdle
