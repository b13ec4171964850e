// Tests of strip_ring.h: whole root cells round the building, a cell a fixed share of the strip,
// turned so that the corners keep off the coarse stages' boundaries.
#include "building/strip_ring.h"

#include <gtest/gtest.h>

#include <cmath>

namespace curdle {
namespace {

// The pavilion: 64 m of strip, 225 mm a brick, root cells of 32 cells (base 2, 5 stages).
const std::vector<double> kCorners = {0, 20000, 26000, 34000, 40000, 52000};

double from_boundary(double cell, double size) {
  const double within = cell - size * std::floor(cell / size);
  return std::min(within, size - within);
}

TEST(StripRingTest, WholeRootCellsNearestToACellABrick) {
  const StripRing ring = ring_round(64000, 225, 32);
  EXPECT_EQ(ring.columns, 288);  // 64000 / 225 = 284.4 cells, 8.9 root cells: 9
  EXPECT_DOUBLE_EQ(ring.cell, 64000.0 / 288);
  EXPECT_EQ(ring_round(3000, 225, 729).columns, 729);  // at least one root cell
}

TEST(StripRingTest, TurnedToKeepEveryCornerACellOffTheCoarseBoundaries) {
  StripRing ring = ring_round(64000, 225, 32);
  turn_ring(ring, kCorners, 2, 5, std::nullopt);
  EXPECT_GE(ring.quiet_stages, 3);
  for (double u : kCorners) {
    const double cell = u / ring.cell + static_cast<double>(ring.phase);
    for (int k = 0; k < ring.quiet_stages; ++k)
      EXPECT_GE(from_boundary(cell, 32 >> k), 1 - 1e-9) << u << " at stage " << k;
  }
  // Unturned, the strip's start (the closing corner) is on a root boundary: no stage is quiet.
  StripRing fixed = ring_round(64000, 225, 32);
  turn_ring(fixed, kCorners, 2, 5, 0);
  EXPECT_EQ(fixed.phase, 0);
  EXPECT_EQ(fixed.quiet_stages, 0);
}

TEST(StripRingTest, AColumnIsTakenRoundTheRing) {
  StripRing ring = ring_round(64000, 225, 32);
  ring.phase = 5;
  EXPECT_EQ(ring_column(ring, 0), 5);
  EXPECT_EQ(ring_column(ring, 64000 - 1), 4);  // the last cell, beside the first
  EXPECT_EQ(ring_column(ring, 64000 + 1), 5);
  EXPECT_EQ(ring_column(ring, -1), 4);
}

TEST(StripRingTest, TheNoteSaysTheRingAndItsTurn) {
  StripRing ring = ring_round(64000, 225, 32);
  turn_ring(ring, kCorners, 2, 5, std::nullopt);
  const std::string note = ring_note(ring, 225, 32, false);
  EXPECT_NE(note.find("9 root cells of 32 cells, 222.2 mm a cell along the strip"),
            std::string::npos)
      << note;
  EXPECT_NE(note.find("(layout.building.phase fixes it)"), std::string::npos) << note;
}

}  // namespace
}  // namespace curdle
