// Fabrication schedules (CSV, RFC 4180, UTF-8 with a byte-order mark so that spreadsheets read
// non-ASCII names, header row), every length in mm to the micrometre:
//   schedule.csv    one row per piece as laid: ID, lot (or fabrication sheet), level (blocks),
//                   row, column; x, y, z, width, height (and depth for blocks: width and depth
//                   in plan, height the storey) of the piece's bounding box from the layout's
//                   bottom-left corner, x right, y up; its own area; the stock element it is
//                   cut from; value and a 0/1 column per curd; type, colour, material; cut;
//                   shape_wkt, the piece as laid in WKT (a POLYGON, a MULTIPOLYGON for a piece
//                   in parts; a circle within the chord tolerance), for every piece, so that
//                   GIS reads every row as a feature; an opening's centre and diameter;
//                   A building's (layout frames) adds facade, strip_x_mm and strip_y_mm: x, y, z
//                   are then the middle of the unit's outer face in the building (x east, y
//                   north, z up), and shape_wkt its outline on the unrolled strip;
//   quantities.csv  per element type, material, colour and stock size (diameter for openings):
//                   count, whole and cut, laid area, stock area, spare, count and area to buy,
//                   pack size and packs. Every piece takes one stock element;
//   lots.csv        the same per lot (per fabrication sheet for perforations, per level for
//                   blocks), in laying order.
#pragma once

#include <ostream>

#include "layout/layout.h"
#include "layout/piece_rows.h"

namespace curdle {

void write_schedule_csv(std::ostream& out, const Layout& layout);
void write_quantities_csv(std::ostream& out, const Layout& layout);
void write_lots_csv(std::ostream& out, const Layout& layout);

}  // namespace curdle
