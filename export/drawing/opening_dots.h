// Round openings drawn as dots: a stroke of zero length with round caps is a filled circle the
// width of the line, in cairo and in PDF alike (PDF 1.7, 8.5.3.2). That is four numbers in a
// PDF where an arc's curves take 26 and a merged opening's polygon some fifty, which were most
// of a perforated sheet's PDF; and a merged opening's arcs stay arcs, as the punch cuts them.
#pragma once

#include <cairo.h>

#include <array>
#include <cstdint>
#include <map>
#include <tuple>
#include <vector>

#include "export/drawing/sheet_drawing.h"
#include "layout/layout.h"

namespace curdle::sheet_drawing {

class OpeningDots {
 public:
  // Whether `e` is drawn as dots: a round opening, or a merged one with the circles it joins.
  static bool takes(const Element& e);
  // e's circles in colour c, placed on paper by v.
  void add(const Element& e, const Rgb& c, const View& v);
  // Every dot, one stroke per colour and diameter, painted opaque and, when alpha < 1, washed
  // out as one layer: the circles of a merged opening overlap, and their overlap must not come
  // out darker than the rest of it.
  void draw(cairo_t* cr, double alpha) const;

 private:
  using Key = std::tuple<uint8_t, uint8_t, uint8_t, double>;  // colour, width on paper
  std::map<Key, std::vector<std::array<double, 2>>> centres_;
};

}  // namespace curdle::sheet_drawing
