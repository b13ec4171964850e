#include "layout/framed_corner.h"

#include <cmath>

#include "layout/surface_frame.h"

namespace curdle {
namespace {

using P = std::array<double, 2>;
constexpr double kEps = 1e-6;

P plus(P a, P b, double s = 1) { return {a[0] + b[0] * s, a[1] + b[1] * s}; }
double cross(P a, P b) { return a[0] * b[1] - a[1] * b[0]; }
P unit(P a, P b) {
  const double n = std::hypot(b[0] - a[0], b[1] - a[1]);
  return {(b[0] - a[0]) / n, (b[1] - a[1]) / n};
}
P left(P d) { return {-d[1], d[0]}; }  // inward: the plan is anticlockwise, its outside right

// Where the line through p along d meets the line through q along e; none when parallel.
std::optional<P> meet(P p, P d, P q, P e) {
  const double den = cross(d, e);
  if (std::fabs(den) < 1e-12) return std::nullopt;
  return plus(p, d, cross({q[0] - p[0], q[1] - p[1]}, e) / den);
}

P plan(const BuildingPoint& b) { return {b[0], b[1]}; }

// The footprint without repeated or collinear points; empty when it is not a simple,
// anticlockwise polygon (a reach too short for the corner's angle).
std::vector<P> tidy_footprint(const std::vector<P>& in) {
  std::vector<P> out;
  for (const P& p : in)
    if (out.empty() || std::hypot(p[0] - out.back()[0], p[1] - out.back()[1]) > kEps)
      out.push_back(p);
  while (out.size() > 1 && std::hypot(out[0][0] - out.back()[0], out[0][1] - out.back()[1]) <= kEps)
    out.pop_back();
  for (size_t k = 0; out.size() > 2 && k < out.size();) {
    const P& a = out[(k + out.size() - 1) % out.size()];
    const P& c = out[(k + 1) % out.size()];
    const P& b = out[k];
    if (std::fabs(cross({b[0] - a[0], b[1] - a[1]}, {c[0] - b[0], c[1] - b[1]})) < kEps)
      out.erase(out.begin() + static_cast<std::ptrdiff_t>(k));
    else
      ++k;
  }
  double area = 0;
  for (size_t k = 0; k < out.size(); ++k) area += cross(out[k], out[(k + 1) % out.size()]);
  int reflex = 0;
  for (size_t k = 0; k < out.size(); ++k) {
    const P& a = out[(k + out.size() - 1) % out.size()];
    const P& b = out[k];
    const P& c = out[(k + 1) % out.size()];
    reflex += cross({b[0] - a[0], b[1] - a[1]}, {c[0] - b[0], c[1] - b[1]}) < 0;
  }
  if (out.size() < 3 || area <= 0 || reflex > 1) return {};
  return out;
}

}  // namespace

std::optional<FramedPrism> framed_corner(const Layout& layout, const Element& e, double t) {
  const std::vector<SurfaceFrame>& frames = layout.frames();
  if (e.corner < 0 || static_cast<size_t>(e.corner) >= frames.size()) return std::nullopt;
  if (std::fabs(e.area() - e.nominal.w * e.nominal.h) > kEps) return std::nullopt;  // cut
  const SurfaceFrame& f = frames[static_cast<size_t>(e.corner)];
  const SurfaceFrame& g = frames[(static_cast<size_t>(e.corner) + 1) % frames.size()];
  if (f.bent || g.bent) return std::nullopt;  // a bent unit is laid in facets
  const double at = f.start + f.length;
  const double a = at - e.nominal.x, b = e.nominal.right() - at;  // reach back, and on
  const P v = plan(frame_point(f, at, 0, 0));
  // Each face's outer edge as the chord the unit lies on (a unit on a curve is straight).
  const P back = plan(frame_point(f, at - a, 0, 0)), on = plan(frame_point(g, g.start + b, 0, 0));
  const P dk = a > kEps ? unit(back, v) : frame_direction(f, at);
  const P dn = b > kEps ? unit(v, on) : frame_direction(g, g.start);
  const P ik = left(dk), in = left(dn);
  const auto inner = meet(plus(v, ik, t), dk, plus(v, in, t), dn);  // the backs' mitre
  if (!inner) return std::nullopt;
  std::vector<P> ring;
  if (f.turn_at_end > 0) {  // outer: the arris at v, the backs meeting at the mitre
    ring = {back, v, on, plus(on, in, t), *inner, plus(back, ik, t)};
  } else if (a > kEps) {  // inner, running through along f to the back of g's wall
    const auto through = meet(v, dk, plus(v, in, t), dn);
    if (!through) return std::nullopt;
    ring = {back, v, *through, *inner, plus(back, ik, t)};
  } else {  // inner, running through along g from the back of f's wall
    const auto through = meet(v, dn, plus(v, ik, t), dk);
    if (!through) return std::nullopt;
    ring = {v, on, plus(on, in, t), *inner, *through};
  }
  FramedPrism p;
  p.footprint = tidy_footprint(ring);
  if (p.footprint.empty()) return std::nullopt;
  p.base = f.base + e.nominal.y;
  p.height = e.nominal.h;
  return p;
}

std::vector<std::array<size_t, 3>> footprint_triangles(const std::vector<P>& fp) {
  const size_t n = fp.size();
  size_t from = 0;
  for (size_t k = 0; k < n; ++k) {
    const P& a = fp[(k + n - 1) % n];
    const P& b = fp[k];
    const P& c = fp[(k + 1) % n];
    if (cross({b[0] - a[0], b[1] - a[1]}, {c[0] - b[0], c[1] - b[1]}) < 0) from = k;
  }
  std::vector<std::array<size_t, 3>> out;
  for (size_t k = 1; k + 1 < n; ++k) out.push_back({from, (from + k) % n, (from + k + 1) % n});
  return out;
}

}  // namespace curdle
