#include "site/dxf_spline.h"

#include <fmt/format.h>

#include <cmath>
#include <optional>

#include "site/drawing.h"
#include "site/spline_fit.h"

namespace curdle::site {

SplineReading read_spline(const std::vector<DxfGroup>& groups, const DxfGroups& numbers,
                          const std::string& name, double tolerance) {
  SplineReading out;
  const int64_t flags = numbers.integer_of(groups, 70, 0, name);
  const int64_t degree = numbers.integer_of(groups, 71, 3, name);
  std::vector<double> knots, weights, heights;
  std::vector<Point> control, fit;
  std::optional<Point> start, end;
  for (size_t i = 0; i < groups.size(); ++i) {
    const DxfGroup& g = groups[i];
    auto pair = [&](int y_code) {
      const double x = numbers.real(g, name);
      const double y = i + 1 < groups.size() && groups[i + 1].code == y_code
                           ? numbers.real(groups[i + 1], name)
                           : 0;
      return Point{x, y};
    };
    if (knots.size() + control.size() + fit.size() > kMostVertices) break;
    if (g.code == 40) knots.push_back(numbers.real(g, name));
    if (g.code == 41) weights.push_back(numbers.real(g, name));
    if (g.code == 10) control.push_back(pair(20));
    if (g.code == 11) fit.push_back(pair(21));
    if (g.code == 12) start = pair(22);
    if (g.code == 13) end = pair(23);
    if (g.code == 30 || g.code == 31) heights.push_back(numbers.real(g, name));
  }
  for (double z : heights) out.flat = out.flat && std::fabs(z - heights.front()) <= kPlaneTolerance;
  if (!out.flat) return out;
  out.closed = flags & (1 | 2);
  if (!control.empty()) {
    bool weighted = false;
    for (double w : weights) weighted = weighted || w != 1;
    out.points = flatten_spline(static_cast<int>(degree), knots, control,
                                weighted ? weights : std::vector<double>{}, tolerance);
    out.first = control.front(), out.last = control.back();
  }
  if (out.points.empty() && fit.size() >= 2) {
    if (out.closed && fit.front() != fit.back()) {
      out.why =
          "is a closed spline given only by fit points, which curdle does not draw as CAD does; "
          "convert it to control vertices (SPLINEDIT, or save as DXF 2000 or later) or draw the "
          "edge as a polyline";
    } else if (const auto cubic = spline_through(fit, start, end, knot_spacing_of(flags))) {
      out.points = flatten_spline(3, cubic->knots, cubic->control, {}, tolerance);
      out.fitted = true;
    }
  }
  if (out.points.empty() && out.why.empty())
    out.why = fmt::format(
        "cannot be drawn: its {} knots, {} control points (degree {}) and {} fit points do not "
        "make a curve; redraw it or convert it to a polyline",
        knots.size(), control.size(), degree, fit.size());
  return out;
}

}  // namespace curdle::site
