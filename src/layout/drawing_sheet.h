// Drawings on ISO sheets at standard scales: the sheet a layout is drawn on (layout.paper,
// A0 to A4, A3 by default), the area left for the drawing inside its margins and the strip
// kept for the title block and legend, and the scale 1 : N, N one of 1, 2, 5, 10, 20, 25, 50,
// 100, 200, 250, 500, 1000, ... (the architect's scales), the largest drawing that fits in
// either orientation.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace curdle {

struct PaperSheet {
  std::string name;         // "A3"
  double short_side = 297;  // mm
  double long_side = 420;
};

// A0..A4; nullopt for any other name.
std::optional<PaperSheet> paper_sheet(std::string_view name);

// Millimetres as the drawings write them: 0.001 mm is below any tolerance and keeps files
// small; trailing zeros dropped.
std::string drawing_mm(double v);

// The drawing area inside the sheet, portrait or landscape: ISO 5457 margins (20 mm at the
// binding edge, 10 mm elsewhere) less a 50 mm strip along the bottom for the title block.
std::array<double, 2> drawing_area(const PaperSheet& sheet, bool landscape);

// The smallest standard N whose drawing of width x height mm fits the drawing area of the
// sheet in either orientation (at most 1 : 10^9), and which orientation it takes.
struct SheetFit {
  double scale = 1;
  bool landscape = true;
};
SheetFit fit_to_sheet(double width, double height, const PaperSheet& sheet);

// The standard scales 1 : N from 1 up to 10^9, smallest N first.
const std::vector<double>& standard_scales();

}  // namespace curdle
