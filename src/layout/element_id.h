// Element IDs: one type, formatted in one place, so that schedule.csv, layout.svg, layout.glb,
// install.svg and the DXF files name every piece the same way.
//
//   P-R03-C04      a paving tile in row 3, column 4 of the laying order (T tile, F panel,
//                  C a perforation or park cell, B a bay of a line)
//   H-R03-C04-2    the second opening cut in that cell; K-R03-C04-tree a park element in it
//   R-R00-C05      the fin in bay 5;  B-L01-R02-C03 a block on level 1
#pragma once

#include <cstdint>
#include <optional>
#include <string>

namespace curdle {

struct ElementId {
  char kind = 'E';
  int digits = 2;  // zero-padded width of the numbers
  std::optional<int64_t> level;
  int64_t row = 0, column = 0;
  std::string part;  // what a cell holds: an opening's number, a park element's name

  std::string text() const;
  // The same place, another kind of piece: an opening or an element within this cell.
  ElementId within(char piece_kind, std::string piece) const;
  ElementId as(char piece_kind) const;
};

}  // namespace curdle
