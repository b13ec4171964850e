#include "layout/geometry.h"

#include <algorithm>

#include "layout/layout.h"

namespace curdle {
namespace {
constexpr double kEps = 1e-6;  // mm: far below any fabrication tolerance
}

Rect clip(const Rect& r, double width, double height) {
  const double x0 = std::max(0.0, r.x), y0 = std::max(0.0, r.y);
  const double x1 = std::min(width, r.right()), y1 = std::min(height, r.top());
  return Rect{x0, y0, std::max(0.0, x1 - x0), std::max(0.0, y1 - y0)};
}

std::vector<Rect> subtract(const Rect& a, const std::vector<Rect>& holes) {
  std::vector<Rect> relevant;
  for (const Rect& h : holes)
    if (overlaps(a, h)) relevant.push_back(h);
  if (relevant.empty()) return {a};
  // Cut `a` along every hole edge inside it, keep the grid cells no hole covers, then merge
  // cells back into rows of the widest rectangles.
  std::vector<double> xs{a.x, a.right()}, ys{a.y, a.top()};
  for (const Rect& h : relevant) {
    for (double x : {h.x, h.right()})
      if (x > a.x && x < a.right()) xs.push_back(x);
    for (double y : {h.y, h.top()})
      if (y > a.y && y < a.top()) ys.push_back(y);
  }
  std::sort(xs.begin(), xs.end());
  std::sort(ys.begin(), ys.end());
  xs.erase(std::unique(xs.begin(), xs.end()), xs.end());
  ys.erase(std::unique(ys.begin(), ys.end()), ys.end());
  std::vector<Rect> out;
  std::vector<Rect> across;  // the holes that meet this row: a few, where all may be thousands
  for (size_t j = 0; j + 1 < ys.size(); ++j) {
    const Rect row{a.x, ys[j], a.w, ys[j + 1] - ys[j]};
    across.clear();
    for (const Rect& h : relevant)
      if (overlaps(row, h)) across.push_back(h);
    Rect run{};
    bool open = false;
    for (size_t i = 0; i + 1 < xs.size(); ++i) {
      const Rect cell{xs[i], ys[j], xs[i + 1] - xs[i], ys[j + 1] - ys[j]};
      const bool covered = std::any_of(across.begin(), across.end(),
                                       [&](const Rect& h) { return overlaps(cell, h); });
      if (!covered && open) {
        run.w += cell.w;
      } else if (!covered) {
        run = cell;
        open = true;
      } else if (open) {
        out.push_back(run);
        open = false;
      }
    }
    if (open) out.push_back(run);
  }
  return out;
}

double Element::area() const {
  if (circle) return circle->area();
  if (outline) return outline->area;
  double a = 0;
  for (const Rect& r : shape) a += r.area();
  return a;
}

}  // namespace curdle

namespace curdle {

const std::vector<SurfaceFrame>& Layout::frames() const {
  static const std::vector<SurfaceFrame> none;
  return envelope ? envelope->frames : none;
}

const std::vector<FabricationSheet>& Layout::sheets() const {
  static const std::vector<FabricationSheet> none;
  return fabrication ? fabrication->sheets : none;
}

std::vector<Rect> Layout::holes() const {
  std::vector<Rect> all = openings;
  all.insert(all.end(), outside.begin(), outside.end());
  return all;
}

}  // namespace curdle
