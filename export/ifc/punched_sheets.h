// A flat perforated surface's fabrication sheets as layout.ifc models them: each sheet as
// punched, its openings holes in its own profile, so that no reader has a Boolean operation to
// run (ifc.cpp draws each opening again as an annotation of its sheet, by opening_rings).
#pragma once

#include <vector>

#include "layout/layout.h"

namespace curdle {

// An opening's rings as layout.ifc draws them: a round one as the polygon ifc_circle_ring
// makes within `chord_tolerance`, else the outer ring of each part of its outline.
std::vector<Ring> opening_rings(const Element& e, double chord_tolerance);

// Each of layout.sheets() as punched, by index: its rectangle, or each part of its outline,
// with the rings of the openings cut in it (in the order of the elements) inside the part that
// holds them; then the islands merged openings leave standing, as parts of their own.
std::vector<std::vector<Outline>> punched_sheets(const Layout& layout);

}  // namespace curdle
