// Tests of edging.h: the edge a material needs edging along is where no piece of it lies
// against another, whatever the pieces' orientation or how the shared edge is split.
#include "layout/edging.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>

namespace curdle {
namespace {

Ring square(double x, double y, double w, double h) {
  return {{x, y}, {x + w, y}, {x + w, y + h}, {x, y + h}};
}

double total(const std::vector<double>& v) { return std::accumulate(v.begin(), v.end(), 0.0); }

TEST(Edging, PiecesOfOneMaterialJoinWithoutAnEdge) {
  // Two 2 x 1 m slabs side by side: a 4 x 1 m strip, edged all round.
  const std::vector<EdgedPiece> same{{{square(0, 0, 2000, 1000)}, 0},
                                     {{square(2000, 0, 2000, 1000)}, 0}};
  const std::vector<double> lengths = unshared_edge_lengths(same);
  EXPECT_NEAR(lengths[0], 5000, 1e-6);
  EXPECT_NEAR(lengths[1], 5000, 1e-6);
  // Of two materials, the edge between them is edged on both sides.
  const std::vector<EdgedPiece> two{{{square(0, 0, 2000, 1000)}, 0},
                                    {{square(2000, 0, 2000, 1000)}, 1}};
  EXPECT_NEAR(total(unshared_edge_lengths(two)), 12000, 1e-6);
}

TEST(Edging, SharedEdgesSplitUnevenlyAndReversedStillJoin) {
  // A 3 m cell of one material in strips that do not line up with the row below, one ring
  // clockwise, coordinates as a division leaves them.
  const double third = 3000.0 / 3;
  Ring clockwise = square(0, 0, 3000, 1000);
  std::reverse(clockwise.begin(), clockwise.end());
  std::vector<EdgedPiece> pieces{{{clockwise}, 0}};
  for (int i = 0; i < 3; ++i) pieces.push_back({{square(i * third, 1000, third, 1000)}, 0});
  pieces.push_back({{square(3000, 0, 500, 2000)}, 1});  // another material on the right
  const std::vector<double> lengths = unshared_edge_lengths(pieces);
  // Material 0 is a 3 x 2 m block: 10 m edge; material 1's strip 5 m.
  EXPECT_NEAR(lengths[0] + lengths[1] + lengths[2] + lengths[3], 10000, 1e-6);
  EXPECT_NEAR(lengths[4], 5000, 1e-6);
}

TEST(Edging, AHoleIsEdgedAndAPieceOfSeveralRectanglesJoinsItself) {
  // A 3 x 3 m square with a 1 x 1 m hole in the middle, as one outline: 12 m + 4 m.
  Ring hole = square(1000, 1000, 1000, 1000);
  std::reverse(hole.begin(), hole.end());
  EXPECT_NEAR(unshared_edge_lengths({{{square(0, 0, 3000, 3000), hole}, 0}})[0], 16000, 1e-6);
  // An L of two rectangles of one piece (piece_rings): its own joint is no edge.
  Element l;
  l.shape = {{0, 0, 2000, 1000}, {0, 1000, 1000, 1000}};
  EXPECT_NEAR(unshared_edge_lengths({{piece_rings(l), 0}})[0], 8000, 1e-6);
}

}  // namespace
}  // namespace curdle
