#include "layout/framed_boxes.h"

#include <algorithm>
#include <cmath>

#include "layout/layout_kind.h"
#include "layout/piece.h"

namespace curdle {
namespace {
// How far a bent unit's facets may lie inside its arc, mm: well within a panel's tolerance.
constexpr double kBentRise = 0.25;

// The chords a span of `length` mm of frame f is laid on: one on a straight frame; on an arc,
// chords of at most `longest`, and where units are bent to it, facets rising at most kBentRise.
int facets(const SurfaceFrame& f, double length, double longest) {
  if (f.bulge == 0) return 1;
  int pieces = std::max(1, static_cast<int>(std::ceil(length / longest)));
  if (f.bent) {
    const double facet = 2 * std::sqrt(2 * frame_radius(f) * kBentRise);
    pieces = std::max(pieces, static_cast<int>(std::ceil(length / facet)));
  }
  return pieces;
}
}  // namespace

std::vector<FramedBox> framed_boxes(const Layout& layout, const Rect& r, double inward0,
                                    double inward1, double longest) {
  std::vector<FramedBox> out;
  const double depth = inward1 - inward0;
  for (const FramedSpan& s : framed_spans(layout.frames(), layout.width, r.x, r.right())) {
    const SurfaceFrame& f = *s.frame;
    const int pieces = facets(f, s.to - s.from, longest);
    for (int k = 0; k < pieces; ++k) {
      const double a = s.from + (s.to - s.from) * k / pieces;
      const double b = s.from + (s.to - s.from) * (k + 1) / pieces;
      // A chord between the outer face's points: a brick on a curved wall is straight.
      const BuildingPoint p = frame_point(f, a, r.y, 0), q = frame_point(f, b, r.y, 0);
      const double dx = q[0] - p[0], dy = q[1] - p[1];
      const double length = std::hypot(dx, dy);
      const std::array<double, 2> d{dx / length, dy / length};
      const double middle = inward0 + depth / 2;  // inward is the left of the chord
      FramedBox box;
      box.centre = {(p[0] + q[0]) / 2 - d[1] * middle, (p[1] + q[1]) / 2 + d[0] * middle,
                    p[2] + r.h / 2};
      box.along = d;
      box.length = length;
      box.height = r.h;
      box.depth = depth;
      out.push_back(box);
    }
  }
  return out;
}

namespace {

// How far short of an outer corner turning `turn` degrees a backing from `set_back` to `depth`
// behind one face stops, for its end to lie `set_back` behind the other face.
double backing_trim(double turn, double set_back, double depth) {
  if (turn < 15) return 0;  // an inner corner or a bend: the other face is not in front of it
  const double a = turn * 3.14159265358979323846 / 180;
  return std::max(set_back - set_back * std::cos(a), set_back - depth * std::cos(a)) / std::sin(a);
}

}  // namespace

std::vector<FramedBox> framed_backing(const Layout& layout, const Rect& r, double set_back,
                                      double depth, double longest) {
  std::vector<FramedBox> out;
  const std::vector<SurfaceFrame>& frames = layout.frames();
  for (size_t k = 0; k < frames.size(); ++k) {
    const SurfaceFrame& f = frames[k];
    const bool after_corner = layout.envelope->closed || k > 0;
    const double from =
        f.start + (after_corner
                       ? backing_trim(frames[(k + frames.size() - 1) % frames.size()].turn_at_end,
                                      set_back, depth)
                       : 0);
    const double to =
        f.start + f.length - (f.last_of_path ? 0 : backing_trim(f.turn_at_end, set_back, depth));
    const double lo = std::max(r.x, from), hi = std::min(r.right(), to);
    if (hi <= lo + 1e-9) continue;
    const std::vector<FramedBox> more =
        framed_boxes(layout, Rect{lo, r.y, hi - lo, r.h}, set_back, depth, longest);
    out.insert(out.end(), more.begin(), more.end());
  }
  return out;
}

namespace {

// The extent of a piece's laid face on the strip, u from and to, and v's middle: a part that
// lies before its nominal start is the closing corner unit's part at the strip's start,
// measured round the seam.
struct LaidFace {
  double from = 0, to = 0, v = 0;
};
LaidFace laid_face(const Element& e, double length) {
  if (e.form == ElementForm::opening) {  // a screen's opening: its own box, not its cell's
    const Rect b = laid_bounds(e);
    return {b.x, b.right(), b.y + b.h / 2};
  }
  if (e.shape.empty()) return {e.nominal.x, e.nominal.right(), e.nominal.y + e.nominal.h / 2};
  double lo = 1e300, hi = -1e300, bottom = 1e300, top = -1e300;
  for (const Rect& r : e.shape) {
    const double shift = carried_round_the_seam(e, r) ? length : 0;
    lo = std::min(lo, r.x + shift), hi = std::max(hi, r.right() + shift);
    bottom = std::min(bottom, r.y), top = std::max(top, r.top());
  }
  return {lo, hi, (bottom + top) / 2};
}

}  // namespace

std::array<double, 2> framed_depth(const Layout& layout, const Element& e) {
  if (layout.kind && layout.kind->stands_off()) return {-layout.thickness, 0};
  return {0, e.depth > 0 ? e.depth : layout.thickness};
}

Rect framed_strip_bounds(const Layout& layout, const Element& e) {
  const LaidFace f = laid_face(e, layout.width);
  const Rect b = laid_bounds(e);
  return {f.from, b.y, f.to - f.from, b.h};
}

BuildingPoint framed_centre(const Layout& layout, const Element& e) {
  const LaidFace f = laid_face(e, layout.width);
  const double face = framed_depth(layout, e)[0];
  const double middle = wrap_along((f.from + f.to) / 2, layout.width);
  // On the chord of the face the middle lies on, as the 3-D writers lay it: a straight unit on
  // a curve lies inside the arc.
  for (const FramedSpan& s : framed_spans(layout.frames(), layout.width, f.from, f.to)) {
    if (middle < s.from - 1e-9 || middle > s.to + 1e-9) continue;
    // On the chord (or, bent, the facet) that holds it, as the writers lay it.
    const int n = facets(*s.frame, s.to - s.from, 1e300);
    const int k = std::clamp(static_cast<int>((middle - s.from) / (s.to - s.from) * n), 0, n - 1);
    const double lo = s.from + (s.to - s.from) * k / n, hi = s.from + (s.to - s.from) * (k + 1) / n;
    const BuildingPoint a = frame_point(*s.frame, lo, f.v, 0);
    const BuildingPoint b = frame_point(*s.frame, hi, f.v, 0);
    const double t = (middle - lo) / (hi - lo);
    // A fin's edge stands off the chord square to it, as framed_boxes stands it.
    const double len = std::hypot(b[0] - a[0], b[1] - a[1]);
    const double ox = len > 0 ? (b[1] - a[1]) / len * -face : 0;
    const double oy = len > 0 ? -(b[0] - a[0]) / len * -face : 0;
    return {a[0] + (b[0] - a[0]) * t + ox, a[1] + (b[1] - a[1]) * t + oy, a[2]};
  }
  return frame_point(*frame_at(layout.frames(), middle), middle, f.v, face);
}

const SurfaceFrame* framed_facade(const Layout& layout, const Element& e) {
  const LaidFace f = laid_face(e, layout.width);
  return frame_at(layout.frames(), wrap_along((f.from + f.to) / 2, layout.width));
}

}  // namespace curdle
