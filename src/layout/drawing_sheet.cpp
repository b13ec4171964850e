#include "layout/drawing_sheet.h"

#include <array>
#include <charconv>
#include <cmath>

namespace curdle {

std::optional<PaperSheet> paper_sheet(std::string_view name) {
  static const PaperSheet sheets[] = {
      {"A0", 841, 1189}, {"A1", 594, 841}, {"A2", 420, 594}, {"A3", 297, 420}, {"A4", 210, 297}};
  for (const PaperSheet& s : sheets)
    if (s.name == name) return s;
  return std::nullopt;
}

std::array<double, 2> drawing_area(const PaperSheet& sheet, bool landscape) {
  const double w = landscape ? sheet.long_side : sheet.short_side;
  const double h = landscape ? sheet.short_side : sheet.long_side;
  return {w - 20 - 10, h - 10 - 10 - 50};
}

const std::vector<double>& standard_scales() {
  static const std::vector<double> scales = [] {
    std::vector<double> s;
    for (double decade = 1; decade <= 1e8; decade *= 10)
      for (const double step : {1.0, 2.0, 2.5, 5.0})
        if (step != 2.5 || decade >= 10) s.push_back(step * decade);  // 1 : 2.5 is not standard
    s.push_back(1e9);
    return s;
  }();
  return scales;
}

SheetFit fit_to_sheet(double width, double height, const PaperSheet& sheet) {
  for (const double n : standard_scales())
    for (const bool landscape : {width >= height, width < height}) {
      const auto area = drawing_area(sheet, landscape);
      if (width / n <= area[0] + 1e-9 && height / n <= area[1] + 1e-9) return {n, landscape};
    }
  return {1e9, true};
}

std::string drawing_mm(double v) {
  // to_chars rounds as printf's "%.3f" does, without fmt's parsing of a format per number (a
  // screen's drawings write hundreds of thousands).
  std::array<char, 352> buffer;  // room for the largest double in fixed notation: never short
  char* end =
      std::to_chars(buffer.data(), buffer.data() + buffer.size(), v, std::chars_format::fixed, 3)
          .ptr;
  std::string s(buffer.data(), end);
  while (s.back() == '0') s.pop_back();
  if (s.back() == '.') s.pop_back();
  return s == "-0" ? "0" : s;
}

}  // namespace curdle
