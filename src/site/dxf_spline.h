// A SPLINE entity's curve from its groups: by its knots and control points (weighted where it
// is rational), or, given by fit points alone, through them as CAD draws it (spline_fit.h).
#pragma once

#include <string>
#include <vector>

#include "site/curves.h"
#include "site/dxf_groups.h"

namespace curdle::site {

struct SplineReading {
  std::vector<Point> points;  // the curve as chords within the tolerance
  bool closed = false;
  bool fitted = false;  // drawn through its fit points
  bool flat = true;     // its points stand at one height
  // Why it cannot be drawn, as the rest of a sentence naming it ("is a closed spline given only
  // by fit points, ..."); empty when it can. Then `first` and `last` place it for a message.
  std::string why;
  Point first{0, 0}, last{0, 0};
};

// The curve of the SPLINE whose groups these are, within `tolerance` (drawing units); `numbers`
// reads its values strictly, naming the entity `name`.
SplineReading read_spline(const std::vector<DxfGroup>& groups, const DxfGroups& numbers,
                          const std::string& name, double tolerance);

}  // namespace curdle::site
