// What every installer's sheet of layout.pdf reads from the whole layout, worked out once for
// the set: the pieces each holds (by their centres) with their rows, columns and key, and what
// each sheet's view may show. Drawing every sheet from every element made a set's time grow
// with the square of its size (a million tiles: 195 s).
#pragma once

#include <cstddef>
#include <cstdint>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "layout/installer_sheets.h"
#include "layout/layout.h"
#include "layout/piece.h"

namespace curdle {

// What one installer's sheet holds: its pieces (those whose centre it shows) and their rows
// and columns.
struct SheetContents {
  size_t pieces = 0;
  int64_t row0 = INT64_MAX, row1 = INT64_MIN, column0 = INT64_MAX, column1 = INT64_MIN;
  // The key: the elements whose centre the sheet shows, by what they are made of, as drawn.
  struct KeyLine {
    std::vector<Rgb> swatch;  // one colour, or keep mode's stripes; each look side by side
    std::vector<std::vector<Rgb>> looks;  // the looks in the swatch
    uint32_t value = 0;                   // its hatch on a coursed set
    size_t count = 0;
  };
  std::map<std::pair<std::string, uint32_t>, KeyLine> key;  // by material, then value
  size_t backing = 0;  // a one-brick wall's backing units behind the pieces it holds
};

struct InstallerDrawing {
  const InstallerPlan& plan;
  LayingExtents extents;
  std::vector<SheetContents> contents;
  // Per sheet, by index: the layout's elements and the plan's pieces its view may show (as
  // sheet_drawing::View::shows counts it, edges included), and the labels set on it.
  std::vector<std::vector<uint32_t>> elements_on, pieces_on, labels_on;
  std::vector<std::string> title;  // title_lines(layout)
};

InstallerDrawing installer_set(const Layout& layout, const InstallerPlan& plan);

}  // namespace curdle
