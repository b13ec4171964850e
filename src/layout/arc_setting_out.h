// The arcs a setter-out needs from the drawings: each arc of the outline and of the zones by its
// centre, radius and end points, a whole circle (a round tree pit) by its centre and radius, in
// mm from the datum. The drawing set draws and lists them instead of every chord's corner.
#pragma once

#include <string>
#include <vector>

#include "layout/contour.h"

namespace curdle {

struct SetOutArc {
  std::string name;  // "A1" for the outline's arcs, the zone's name (and A1, A2) for a zone's
  Arc arc;
  bool circle = false;  // a whole circle: two half turns round one centre
  std::string line;     // "A1: centre (9000, 21000), radius 13000, from (14000, 9000) to ..."
};

std::vector<SetOutArc> arcs_to_set_out(const Layout& layout);

// The corners a contour is set out by: its vertices, and the centre of each arc that lies on the
// surface (not the chords' ends).
std::vector<std::array<double, 2>> set_out_points(const Contour& contour, double width,
                                                  double height);

}  // namespace curdle
