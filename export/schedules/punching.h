// punching.csv: a perforated surface's order list for the fabricator (CSV as schedule.h writes
// it): one row per fabrication sheet — its ID, material, thickness, the stock sheet it is cut
// from, its own area, the offcut (stock less the sheet's area), its open share, and the hits
// of each punch ("D12" the 12 mm punch; "outline" merged openings cut along their outline) —
// then its façade on a building, its blank (width and height; a sheet rolled to an arc developed
// at mid-thickness) and the inside radius it is rolled to (empty: flat); then a row "total"
// that sums them.
#pragma once

#include <ostream>

#include "layout/layout.h"

namespace curdle {

void write_punching_csv(std::ostream& out, const Layout& layout);

}  // namespace curdle
