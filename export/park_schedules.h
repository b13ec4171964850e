// A park's schedules in landscape terms, for the contractor who orders and sets out from them
// (CSV as schedule.h writes it: UTF-8 with a byte-order mark, RFC 4180, lengths in mm):
//   planting.csv   every tree and shrub (a round object: its canopy): ID, the plant's name from
//                  the recipe, its centre to set out from, canopy diameter, value, zone;
//   furniture.csv  every other standing object (benches, bins): ID, item, centre, width and
//                  depth, value, zone;
//   surfaces.csv   the ground and surfaces per material and zone: area laid, pieces, cut.
// A zone is the first [[layout.zones]] whose polygon holds the element's centre ("" for none).
#pragma once

#include <ostream>

#include "layout/layout.h"

namespace curdle {

void write_planting_csv(std::ostream& out, const Layout& layout);
void write_furniture_csv(std::ostream& out, const Layout& layout);
void write_surfaces_csv(std::ostream& out, const Layout& layout);

}  // namespace curdle
