#include "layout/gauge.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace curdle {
namespace {

constexpr double kEps = 1e-6;

bool within(double v, double lo, double hi) { return v >= lo - kEps && v <= hi + kEps; }

std::string mm_label(double v) { return fmt::format("{:g}", std::round(v * 10) / 10); }

}  // namespace

std::vector<GaugeMark> gauge_marks(const Layout& layout, const LayingExtents& extents,
                                   const Rect& window) {
  std::vector<GaugeMark> marks;
  const double lo = std::max(window.y, 0.0), hi = std::min(window.top(), layout.height);
  for (const auto& [row, extent] : extents.rows)
    if (within(extent.first, lo, hi)) marks.push_back({extent.first, mm_label(extent.first)});
  if (within(layout.height, lo, hi)) marks.push_back({layout.height, mm_label(layout.height)});
  const auto& d = layout.drawing;
  const std::vector<double> levels = storey_levels(d.storey, d.storeys, layout.height);
  for (size_t k = 0; levels.size() > 1 && k < levels.size(); ++k) {
    const double at = levels[k];
    if (within(at, lo, hi))
      marks.push_back({at, fmt::format("level {} {}{}", k, k ? "+" : "±", mm_label(at)), true});
  }
  std::stable_sort(marks.begin(), marks.end(), [](const GaugeMark& a, const GaugeMark& b) {
    return a.at != b.at ? a.at < b.at : a.level > b.level;
  });
  // The wall's top where a course's bed is already marked there.
  marks.erase(std::unique(marks.begin(), marks.end(),
                          [](const GaugeMark& a, const GaugeMark& b) {
                            return !a.level && !b.level && std::abs(a.at - b.at) < kEps;
                          }),
              marks.end());
  return marks;
}

std::vector<double> dimension_stops(const Layout& layout, const Rect& window) {
  const double lo = std::max(window.x, 0.0), hi = std::min(window.right(), layout.width);
  if (hi <= lo + kEps) return {};
  std::vector<double> stops{lo, hi};
  for (size_t i = 0; i < layout.openings_given && i < layout.openings.size(); ++i) {
    const Rect& o = layout.openings[i];
    if (o.top() <= window.y + kEps || o.y >= window.top() - kEps) continue;  // not on the sheet
    for (const double x : {o.x, o.right()})
      if (x > lo + kEps && x < hi - kEps) stops.push_back(x);
  }
  std::sort(stops.begin(), stops.end());
  stops.erase(std::unique(stops.begin(), stops.end(),
                          [](double a, double b) { return std::abs(a - b) < kEps; }),
              stops.end());
  return stops;
}

}  // namespace curdle
