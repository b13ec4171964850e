#include "layout/surface_frame.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "layout/contour.h"

namespace curdle {
namespace {

// The arc of a curved frame, from its plan ends and bulge.
Arc arc_of(const SurfaceFrame& f) {
  return arc_between(ContourVertex{f.from[0], f.from[1], f.bulge},
                     ContourVertex{f.to[0], f.to[1], 0});
}

}  // namespace

double frame_radius(const SurfaceFrame& f) { return f.bulge == 0 ? 0 : arc_of(f).radius; }

double frame_radius_behind(const SurfaceFrame& f, double inward) {
  if (f.bulge == 0) return 0;
  const Arc arc = arc_of(f);
  return arc.sweep > 0 ? arc.radius - inward : arc.radius + inward;  // as frame_point goes in
}

std::array<double, 2> frame_direction(const SurfaceFrame& f, double u) {
  if (f.bulge == 0) {
    const double dx = f.to[0] - f.from[0], dy = f.to[1] - f.from[1];
    const double n = std::hypot(dx, dy);
    return {dx / n, dy / n};
  }
  const Arc arc = arc_of(f);
  const double along = (u - f.start) / f.length;
  const double angle = arc.start_angle() + arc.sweep * along;
  const double s = arc.sweep > 0 ? 1 : -1;  // the tangent turns with the sweep
  return {-std::sin(angle) * s, std::cos(angle) * s};
}

BuildingPoint frame_point(const SurfaceFrame& f, double u, double v, double inward) {
  const double z = f.base + v;
  if (f.bulge == 0) {
    const std::array<double, 2> d = frame_direction(f, u);
    const double t = u - f.start;
    // The outer face lies on the right of the edge (the plan is anticlockwise): inward is left.
    return {f.from[0] + d[0] * t - d[1] * inward, f.from[1] + d[1] * t + d[0] * inward, z};
  }
  const Arc arc = arc_of(f);
  const double angle = arc.start_angle() + arc.sweep * (u - f.start) / f.length;
  // An anticlockwise arc bows outwards, its inside towards the centre; a clockwise one bows in.
  const double r = arc.sweep > 0 ? arc.radius - inward : arc.radius + inward;
  return {arc.centre[0] + r * std::cos(angle), arc.centre[1] + r * std::sin(angle), z};
}

const SurfaceFrame* frame_at(const std::vector<SurfaceFrame>& frames, double u) {
  if (frames.empty()) return nullptr;
  for (const SurfaceFrame& f : frames)
    if (u < f.start + f.length) return &f;
  return &frames.back();
}

double wrap_along(double u, double length) {
  if (length <= 0) return u;
  const double w = std::fmod(u, length);
  return w < 0 ? w + length : w;
}

std::vector<FramedSpan> framed_spans(const std::vector<SurfaceFrame>& frames, double length,
                                     double from, double to) {
  std::vector<FramedSpan> out;
  auto add = [&](double a, double b) {
    for (const SurfaceFrame& f : frames) {
      const double lo = std::max(a, f.start), hi = std::min(b, f.start + f.length);
      if (hi > lo + 1e-9) out.push_back({&f, lo, hi});
    }
  };
  if (to > length + 1e-9 && from < length) {
    add(from, length);
    add(0, to - length);
  } else {
    add(from, to);
  }
  return out;
}

}  // namespace curdle
