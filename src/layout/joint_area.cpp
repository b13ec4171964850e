#include "layout/joint_area.h"

#include <vector>

#include "curdle/stop.h"
#include "layout/builder.h"
#include "layout/union.h"

namespace curdle {

namespace {

// The part of r laid: on the surface, off its `holes` (layout.holes(), gathered once).
double laid_area(const Layout& layout, const std::vector<Rect>& holes, const Rect& r) {
  double area = 0;
  const Rect c = clip(r, layout.width, layout.height);
  if (c.area() > 0)
    for (const Rect& piece : subtract(c, holes))
      area += piece.area() - area_within(piece, layout.cut_away);
  return area;
}

// Under a bond the vertical joints move from course to course: each course's own, as high as
// the course, beside the horizontal joints between courses.
double bonded_joint_area(const Layout& layout) {
  const bool right = from_right(layout.origin), top = from_top(layout.origin);
  const double pitch_w = layout.module_w + layout.joint, pitch_h = layout.module_h + layout.joint;
  const std::vector<Rect> holes = layout.holes();
  double area = 0;
  for (int64_t r = 0; r < layout.rows; ++r) {
    const double up = r * pitch_h - layout.shift[1];
    const double y = top ? layout.height - up - layout.module_h : up;
    for (int64_t c = 0; c < layout.columns; ++c) {
      stop_point();
      const double along = c * pitch_w + layout.module_w - layout.shift[0] -
                           course_offset(layout.bond, layout.module_w + layout.joint, r);
      area += laid_area(layout, holes,
                        Rect{right ? layout.width - along - layout.joint : along, y, layout.joint,
                             layout.module_h});
    }
    if (r + 1 < layout.rows) {
      const double joint_up = up + layout.module_h;
      area += laid_area(layout, holes,
                        Rect{0, top ? layout.height - joint_up - layout.joint : joint_up,
                             layout.width, layout.joint});
    }
  }
  return area;
}

}  // namespace

double joint_area(const Layout& layout) {
  if (layout.joint <= 0) return 0;
  if (layout.pattern != LayingPattern::grid) {  // what of the surface the units leave
    double area = 0;
    for (const Outline& o :
         surfaced(Rect{0, 0, layout.width, layout.height}, layout.holes(), layout.cut_away))
      area += o.area;
    for (const Element& e : layout.elements) area -= e.area();
    return area;
  }
  const bool right = from_right(layout.origin);
  const bool top = from_top(layout.origin);
  // Joints follow each module, counted from the origin corner.
  std::vector<Rect> vertical, horizontal;
  if (layout.bond > 0) return bonded_joint_area(layout);
  for (int64_t c = 0; c + 1 < layout.columns; ++c) {
    const double along = c * (layout.module_w + layout.joint) + layout.module_w - layout.shift[0];
    vertical.push_back(
        Rect{right ? layout.width - along - layout.joint : along, 0, layout.joint, layout.height});
  }
  for (int64_t r = 0; r + 1 < layout.rows; ++r) {
    const double up = r * (layout.module_h + layout.joint) + layout.module_h - layout.shift[1];
    horizontal.push_back(
        Rect{0, top ? layout.height - up - layout.joint : up, layout.width, layout.joint});
  }
  const std::vector<Rect> holes = layout.holes();
  auto laid = [&](const Rect& r) { return laid_area(layout, holes, r); };
  double area = 0;
  for (const Rect& v : vertical) area += laid(v);
  for (const Rect& h : horizontal) area += laid(h);
  for (const Rect& v : vertical)  // crossings were counted twice
    for (const Rect& h : horizontal) area -= laid(Rect{v.x, h.y, layout.joint, layout.joint});
  return area;
}

}  // namespace curdle
