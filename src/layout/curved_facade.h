// What a setter-out and a bricklayer need of a curved façade, from its frame: the arc's centre,
// radius and ends in plan, how each unit sits on it (straight on a chord, or bent), how its
// joints taper from the face to the back, and the offsets from the chord between its ends to
// the arc at regular stations, to peg the face out on site. Sheet 1 draws and lists it; the
// coursed sheets name it.
#pragma once

#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "layout/layout.h"

namespace curdle {

// An offset of the arc from its chord: `along` mm from the chord's start, `offset` mm square to
// it, towards the arc.
struct ChordOffset {
  double along = 0, offset = 0;
};

struct CurvedFacade {
  const SurfaceFrame* frame = nullptr;
  std::array<double, 2> centre{0, 0}, from{0, 0}, to{0, 0};
  double radius = 0;      // at the outer face, mm
  double sweep = 0;       // degrees, positive anticlockwise
  double chord = 0;       // between its ends, mm
  double unit_chord = 0;  // a unit's chord (bent) or its length (straight on a chord), mm
  double inside = 0;      // a straight unit's middle inside the arc (the sagitta), mm
  double joint_back = 0;  // a joint's width at the back of a straight unit, mm
  bool convex = true;     // the face outside the curve
  std::vector<ChordOffset> offsets;
  std::string line;   // "SE: radius 12000 mm, centre (0, 12000), from (0, 0) to ..."
  std::string units;  // "215 mm bricks on chords, 0.48 mm inside the arc; joints 10 mm ..."
  // Both again, short, for a sheet's notes: "façade SE: radius 12000 round centre (0, 12000)"
  // and "chord 215 mm a unit; joints 10 mm face, 8.1 mm back".
  std::array<std::string, 2> brief;
};

// How a straight unit `l` mm long sits on a chord of an arc of radius `r` at the face, with
// joints `j` mm wide there: its middle `inside` mm inside the arc (its chord's sagitta), and
// each joint `joint_back` mm wide `depth` mm behind the face (narrower behind a convex face,
// wider behind a concave one).
struct ChordFit {
  double inside = 0, joint_back = 0;
};
ChordFit chord_fit(double r, double l, double j, double depth, bool convex);

// The chord a unit `l` mm long spans when bent to a radius of `r` mm.
inline double bent_chord(double r, double l) { return 2 * r * std::sin(l / (2 * r)); }

// Every curved façade of a building's layout, with the offsets at stations `step` mm apart
// along its chord (0: a round step giving 4 to 10 stations).
std::vector<CurvedFacade> curved_facades(const Layout& layout, double step = 0);

}  // namespace curdle
