// How a run of a course, between the pieces fixed at its ends (the units turning corners, a
// free-standing wall's stopped ends), is filled as a bricklayer fills it, for each bond:
// - whole units from both ends with the cut in the middle (stretcher and stack bond);
// - on the course's phase, each course moved along by a third or a quarter of the pitch from
//   the one below, with a closer at each end where the phase needs one (third, quarter);
// - from each end in the bond's own order of headers, stretchers and queen closers, the cut in
//   the middle (English and Flemish bond).
// No cut is narrower than `min_cut` where any arrangement avoids it: a piece that would be is
// taken with its neighbour and the two laid as two halves. A run off whole units by no more
// than its joints can take up (joint_play) is laid whole, as a bricklayer gauges the perpends,
// with no closer: a curved wall's chords leave each course a fraction of a millimetre short of
// whole pitches, and a wall set out a joint off brick sizes is a joint long over its run.
#pragma once

#include <algorithm>
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
// narrower: each joint by at most kJointPlay (a 10 mm perpend laid 9 to 11 mm), the run by at
// most a joint's width, so that its perpends stay within half a joint of the half-lap over the
// course below; and a run of one or two joints, or the gap left in a bond's middle between two,
// by kJointTolerance.
inline constexpr double kJointTolerance = 2.0;
inline constexpr double kJointPlay = 1.0;

// How much a run of `joints` joints of width `joint` may take up, mm.
inline double joint_play(int64_t joints, double joint) {
  return std::max(kJointTolerance, std::min(static_cast<double>(joints) * kJointPlay, joint));
}

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
