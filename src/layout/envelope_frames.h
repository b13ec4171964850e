// A surface laid round a building or along a wall's path (its own record on the layout): the
// strip's façades, each a frame that places its part of the strip in the building; `closed`
// round a building (the strip's end meets its start), else a free-standing wall. A building's
// wall (src/building) adds its bond's name, its openings' kinds and names, and, one unit
// thick, the backing behind its face.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "layout/surface_frame.h"

namespace curdle {

// A one-brick wall's backing: behind each face unit that does not run through the wall, a
// backing unit of `material`, counted in quantities.csv and lots.csv.
struct WallBacking {
  std::string material;
  double from = 0;  // mm behind the face: the face units' depth and the collar joint
};

struct EnvelopeFrames {
  std::vector<SurfaceFrame> frames;
  bool closed = false;
  std::string bond_name;  // a building's bond where the share says too little ("Flemish")
  std::vector<std::string> opening_kinds;  // per own opening: "window" or "door"
  std::vector<std::string> opening_names;  // and its name: "W-12", "D-1"
  std::optional<WallBacking> backing;
};

}  // namespace curdle
