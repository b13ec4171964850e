// A piece as every file that names it describes it: its ID, lot, type, stock size, colour and
// material in the same words, and its box, area and shape as laid (schedule.csv's row, which
// layout.ifc, layout.gpkg, the drawings and the Python module read as numbers).
#pragma once

#include <cmath>
#include <cstdint>
#include <optional>
#include <string>

#include "curdle/curd.h"
#include "layout/layout.h"

namespace curdle {

// The lot an element belongs to, counted from 1 in laying order.
int64_t lot_of(const Element& element, size_t index, const OrderingKeys& ordering);
// What the schedules call an element, its stock size ("600 x 300", "D12") and its lot ("1",
// or the fabrication sheet "S-R1-C2"): the same words in every file that names the piece.
std::string element_type_of(const Layout& layout, const Element& element);
// Whether a one-brick wall has a backing unit behind this face piece: all but those that run
// through it (headers, queen closers, and the cuts of header courses).
bool needs_backing(const Layout& layout, const Element& element);
std::string stock_size_of(const Layout& layout, const Element& element);
std::string lot_text(const Layout& layout, const Element& element, size_t index);

// One row of schedule.csv as numbers and words: what the CSV prints, and what a program or the
// Python module reads without parsing it. Lengths in mm, unrounded.
struct ScheduleRow {
  std::string id, lot;
  std::optional<int64_t> level;  // blocks: the storey from the view's lowest
  int64_t row = 0, column = 0;
  double x = 0, y = 0, z = 0, width = 0, height = 0;  // bounding box of the piece as laid
  std::optional<double> depth;                        // blocks: depth in plan
  double area = 0;                                    // mm², its own
  std::optional<double> stock_width, stock_height;    // what it is cut from, when bought
  uint32_t value = 0;
  std::string element_type, colour, material;  // colour as "#rrggbb"
  bool cut = false;
  std::vector<Outline> outlines;  // the piece as laid, for shape_wkt: every piece has one
  std::optional<double> opening_x, opening_y, opening_diameter;
  // A building's unit: its façade, and where it lies on the unrolled strip (its bounding box's
  // corner there); x, y, z are then the middle of its outer face in the building, mm.
  std::string facade;
  std::optional<double> strip_x, strip_y;
};
ScheduleRow schedule_row(const Layout& layout, size_t index);
// A piece's area in m² as the schedules give it: to the mm², so that schedule.csv's rows add up
// to quantities.csv's and lots.csv's laid areas exactly.
inline double area_m2(double area_mm2) { return std::round(area_mm2) / 1e6; }

}  // namespace curdle
