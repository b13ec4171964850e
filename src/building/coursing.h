// Courses round an envelope as a bricklayer sets them out: level all round, a unit turning
// every corner (at an outer corner its stretcher on one face and its header on the other,
// changing sides course by course, so that stretcher bond laps by half a unit; at an inner
// corner one face's unit runs through behind the other's), stopped ends of a free-standing wall
// with a half unit on alternate courses, and each run between them filled with whole units from
// its ends, the cut needed to fit put in its middle (one closer, or two where one would be a
// sliver). At an outer corner sharper than a right angle the header reaches as far as the
// backs' mitre, a special cut to the angle. A bend of less than 15 degrees (an arc meeting its
// tangent) is no corner: the run goes on round it.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "building/building.h"

namespace curdle {

enum class UnitRole {
  stretcher,  // a whole unit of a run, its length on the face
  header,     // a whole unit of a run showing its end, its length into the wall
  closer,     // cut to fit the run, or a queen closer beside a header at a corner
  corner,     // turns a corner: counted once, on both façades
  end,        // a stopped end's half unit
};

// The bonds a building's courses are laid in: every course alike (stack); moved along by a half
// (stretcher), a third or a quarter of a unit from the course below; English (courses of
// stretchers and of headers by turns); Flemish (a header and a stretcher by turns in each course).
enum class CourseBond { stack, stretcher, third, quarter, english, flemish };

// One unit on the strip: its course and extent along the strip, mm. The unit at the closing
// corner of a building runs past the strip's end (`to` > the strip's length) and on from its
// start: one unit, in two parts on the unrolled strip.
struct CourseUnit {
  int64_t course = 0;
  double from = 0, to = 0;
  UnitRole role = UnitRole::stretcher;
  int corner = -1;   // the corner it turns: the end of facades[corner]
  double depth = 0;  // into the wall, mm: a header's or queen closer's unit length; 0: the wall's
};

struct Coursing {
  CourseBond bond = CourseBond::stretcher;  // what the units were laid in
  std::vector<CourseUnit> units;            // course by course, along the strip
  std::vector<std::string> notes;           // how each corner is built, and what had to be cut
};

// Units of `length` (the spec's module_w) and `depth` (a header's width on the face), with the
// spec's joint, in `bond`.
Coursing course_envelope(const Envelope& env, const LayoutSpec& spec, CourseBond bond);

// Throws InputError (key `plan` or `path`) where a façade is too short for the units that turn
// the corners at its ends, in either course of the bond, or a corner is too sharp for a unit
// to turn (its header would reach past the unit's length to the mitre).
void check_corner_room(const Envelope& env, const LayoutSpec& spec);

// A queen closer's width: half a header (the unit's `depth` on the face) less half a joint.
inline double queen_closer(double depth, double joint) { return (depth - joint) / 2; }

// What a corner is: "outer", "inner" or "bend" (no corner), by its turn in degrees.
const char* corner_kind(double turn);

}  // namespace curdle
