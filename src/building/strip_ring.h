// The field round a closed envelope as a ring: whole root cells of the lattice laid round the
// building, each field cell a fixed share of the strip, so that the strip's last cell meets its
// first as any two cells across a root boundary do and the closing corner is a corner like the
// others. The ring is turned (its phase) so that no corner falls on or near a boundary of the
// coarse stages, where two neighbours are as unalike as two independent units: a corner then
// continues the rhythm as a line anywhere in a façade does. A free-standing wall has two ends
// and no ring.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace curdle {

struct StripRing {
  int64_t columns = 1;   // field cells round the building: whole root cells
  double cell = 1;       // mm of the strip a field cell takes
  int64_t phase = 0;     // the field column at the strip's start
  int quiet_stages = 0;  // coarse stages (from the root down) whose boundaries no corner is near
};

// The ring for a strip of `length` mm whose units' pitch is `pitch` mm, the lattice's root cell
// being `root` field cells: as many whole root cells as come nearest to one cell a unit
// (at least one), each cell length / columns mm.
StripRing ring_round(double length, double pitch, int64_t root);

// The phase, from 0 to root - 1, that keeps `corners` (mm along the strip) at least a cell from
// the boundaries of as many coarse stages as it can, from the root down (base^stages cells a
// root); of those, the one that keeps them farthest from the next stage's, then the smallest
// (of at most 4,096 phases spread over a larger root).
// `given` fixes it instead (the recipe's layout.building.phase).
void turn_ring(StripRing& ring, const std::vector<double>& corners, int base, int stages,
               std::optional<int64_t> given);

// The field column under the point `u` mm along the strip (any u: taken round the ring).
int64_t ring_column(const StripRing& ring, double u);

// "the field wraps round the building: 9 root cells of 32 cells, 222.2 mm a cell along the
// strip, turned 5 cells ..." for the notes.
std::string ring_note(const StripRing& ring, double pitch, int64_t root, bool given);

}  // namespace curdle
