#include "export/drawing/opening_dots.h"

#include "curdle/stop.h"

namespace curdle::sheet_drawing {

bool OpeningDots::takes(const Element& e) {
  return e.form == ElementForm::opening && (e.circle || (e.outline && !e.outline->circles.empty()));
}

void OpeningDots::add(const Element& e, const Rgb& c, const View& v) {
  auto add_one = [&](const Circle& circle) {
    centres_[{c.r, c.g, c.b, circle.d / v.scale}].push_back({v.x(circle.cx), v.y(circle.cy)});
  };
  if (e.circle) add_one(*e.circle);
  if (e.outline)
    for (const Circle& circle : e.outline->circles) add_one(circle);
}

void OpeningDots::draw(cairo_t* cr, double alpha) const {
  if (centres_.empty()) return;
  cairo_save(cr);
  if (alpha < 1) cairo_push_group(cr);
  cairo_set_line_cap(cr, CAIRO_LINE_CAP_ROUND);
  for (const auto& [key, centres] : centres_) {
    stop_point();
    const auto& [r, g, b, width] = key;
    colour(cr, Rgb{r, g, b});
    cairo_set_line_width(cr, width);
    cairo_new_path(cr);
    for (const auto& [x, y] : centres) cairo_move_to(cr, x, y), cairo_line_to(cr, x, y);
    cairo_stroke(cr);
  }
  if (alpha < 1) cairo_pop_group_to_source(cr), cairo_paint_with_alpha(cr, alpha);
  cairo_restore(cr);
}

}  // namespace curdle::sheet_drawing
