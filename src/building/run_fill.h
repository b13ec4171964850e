// How a run of a course, between the pieces fixed at its ends (the units turning corners, a
// free-standing wall's stopped ends), is filled as a bricklayer fills it, for each bond:
// - whole units from both ends with the cut in the middle (stretcher and stack bond);
// - on the course's phase, each course moved along by a third or a quarter of the pitch from
//   the one below, with a closer at each end where the phase needs one (third, quarter);
// - from each end in the bond's own order of headers, stretchers and queen closers, the cut in
//   the middle (English and Flemish bond).
// No cut is narrower than `min_cut` where any arrangement avoids it: a piece that would be is
// taken with its neighbour and the two laid as two halves. A run (or the gap left in its
// middle) within kJointTolerance of whole units takes the difference up in its joints, as a
// bricklayer does, and has no closer: a curved wall's chords leave each course a fraction of a
// millimetre short of whole pitches.
#pragma once

#include <cstdint>
#include <vector>

#include "building/coursing.h"

namespace curdle {

// One face piece a bond lays: its width on the face, its role, and how deep it runs into the
// wall (a header or queen closer its unit's length; 0: the wall's depth).
struct BondPiece {
  double width = 0;
  UnitRole role = UnitRole::stretcher;
  double depth = 0;
};

// The order a bond lays from one end of a run: its first pieces, then `cycle` over and over.
struct BondOrder {
  std::vector<BondPiece> first;
  std::vector<BondPiece> cycle;
};

// What every fill needs: the course, the unit's length `l`, the joint `j` and the narrowest
// cut; `sliver` is set where a run is shorter than the narrowest cut and laid as one piece.
// How far a run may be from whole units and be laid whole, its joints a little wider or
// narrower, mm over the run (a 10 mm joint is laid within about ±2 mm).
inline constexpr double kJointTolerance = 2.0;

struct RunFill {
  int64_t course = 0;
  double l = 0, j = 0, min_cut = 0;
  std::vector<CourseUnit>* out = nullptr;
  bool* sliver = nullptr;
};

// [s, e]: the run between the faces of the fixed pieces at its ends (their joints outside it).
void fill_whole_from_ends(const RunFill& f, double s, double e);
void fill_on_phase(const RunFill& f, double s, double e, double phase);
void fill_in_order(const RunFill& f, double s, double e, const BondOrder& from_start,
                   const BondOrder& from_end);

}  // namespace curdle
