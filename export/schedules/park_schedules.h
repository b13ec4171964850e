// A park's schedules in landscape terms, for the contractor who orders and sets out from them
// (CSV as schedule.h writes it: UTF-8 with a byte-order mark, RFC 4180, lengths in mm):
//   planting.csv   every tree and shrub (a round object: its canopy): ID, the plant's name from
//                  the recipe and its species, its centre to set out from, canopy diameter, stem
//                  girth (cm at 1 m), root ball, the tree pit to dig, value, zone;
//   furniture.csv  every other standing object (benches, bins): ID, item, product, centre, width
//                  and depth, the bearing of its long side from x (0 or 90), value, zone;
//   surfaces.csv   the ground and surfaces per material and zone: area laid, pieces, cut, and
//                  the edging to order (edging.h: the edge where another material, the site's
//                  edge or a hole meets it, in m).
// Empty cells are what the recipe did not give. A zone is the first [[layout.zones]] whose
// polygon holds the element's centre ("" for none).
#pragma once

#include <ostream>

#include "layout/layout.h"

namespace curdle {

void write_planting_csv(std::ostream& out, const Layout& layout);
void write_furniture_csv(std::ostream& out, const Layout& layout);
void write_surfaces_csv(std::ostream& out, const Layout& layout);

}  // namespace curdle
