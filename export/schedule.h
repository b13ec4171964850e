// Fabrication schedules (CSV, RFC 4180, UTF-8, header row), streamed row by row:
//   schedule.csv    one row per element: ID, lot, row, column, position and size in mm from the
//                   layout origin (bottom-left corner, x right, y up; z up for blocks), value, a
//                   0/1 column per curd, type, colour and material, cut size, opening centre and
//                   diameter;
//   quantities.csv  per element type and colour: count, area in m2, the spare share, the count
//                   with spare, the pack size and the packs to order.
#pragma once

#include <ostream>
#include <string>

#include "curdle/curd.h"
#include "layout/layout.h"

namespace curdle {

// The lot an element belongs to, counted from 1 in laying order.
int64_t lot_of(const Element& element, size_t index, const LayoutSpec& spec);

void write_schedule_csv(std::ostream& out, const Layout& layout);
void write_quantities_csv(std::ostream& out, const Layout& layout);

}  // namespace curdle
