#include "curdle/density.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace curdle {

double CellPlacement::shift_of_row(int64_t y) const {
  if (course_shift.empty()) return 0;
  const auto n = static_cast<int64_t>(course_shift.size());
  const int64_t i = ((row_sign * y + row_base) % n + n) % n;
  return course_shift[static_cast<size_t>(i)];
}

std::array<double, 3> CellPlacement::centre(const std::array<int64_t, 3>& cell,
                                            int dimension) const {
  std::array<double, 3> p{0, 0, 0};
  for (int d = 0; d < dimension; ++d)
    p[d] = origin[d] + scale[d] * (static_cast<double>(cell[d]) + 0.5);
  if (dimension >= 2) p[0] += shift_of_row(cell[1]);
  if (period > 0) p[0] -= std::floor(p[0] / period) * period;
  return p;
}

std::array<double, 2> CellPlacement::shift_range() const {
  if (course_shift.empty()) return {0, 0};
  const auto [lo, hi] = std::minmax_element(course_shift.begin(), course_shift.end());
  return {*lo, *hi};
}

namespace {

double blend(const std::array<double, 2>& values, double t) {
  return values[0] + (values[1] - values[0]) * t;
}

// The pixel a coordinate falls in along one axis of the picture, clamped to the picture.
int pixel_of(double at, double start, double length, int count) {
  const double f = std::floor((at - start) / length * count);
  return static_cast<int>(std::clamp(f, 0.0, static_cast<double>(count - 1)));
}

}  // namespace

double DensityField::at(const std::array<double, 3>& p) const {
  switch (kind) {
    case DensityKind::linear: {
      double along = 0, length2 = 0;
      for (int d = 0; d < dimension; ++d) {
        const double dir = to[d] - from[d];
        along += (p[d] - from[d]) * dir;
        length2 += dir * dir;
      }
      return blend(values, length2 > 0 ? std::clamp(along / length2, 0.0, 1.0) : 0.0);
    }
    case DensityKind::radial: {
      double d2 = 0;
      for (int d = 0; d < dimension; ++d) {
        // Round a ring the nearer way: across the closing corner as well as along the strip.
        const double delta = d == 0 && placement.period > 0
                                 ? std::remainder(p[d] - centre[d], placement.period)
                                 : p[d] - centre[d];
        d2 += delta * delta;
      }
      return blend(values, std::min(1.0, std::sqrt(d2) / radius));
    }
    case DensityKind::image: {
      if (!luminance || width <= 0 || height <= 0) return values[0];
      const int x = pixel_of(p[0], rect[0], rect[2], width);
      const int from_bottom = pixel_of(p[1], rect[1], rect[3], height);
      const auto i = static_cast<size_t>(height - 1 - from_bottom) * width + x;
      return blend(values, (*luminance)[i]);
    }
  }
  return 0;
}

double DensityField::most_in(const std::array<double, 3>& lo,
                             const std::array<double, 3>& hi) const {
  switch (kind) {
    case DensityKind::linear: {  // clamped and linear along the line: largest at a corner
      double most = 0;
      for (int corner = 0; corner < (1 << dimension); ++corner) {
        std::array<double, 3> p{0, 0, 0};
        for (int d = 0; d < dimension; ++d) p[d] = (corner >> d & 1) ? hi[d] : lo[d];
        most = std::max(most, at(p));
      }
      return most;
    }
    case DensityKind::radial: {  // monotonic in the distance: the nearest or farthest point
      std::array<double, 3> p{0, 0, 0};
      const bool falls = values[0] >= values[1];
      for (int d = 0; d < dimension; ++d)
        p[d] = falls ? std::clamp(centre[d], lo[d], hi[d])
                     : (std::abs(lo[d] - centre[d]) > std::abs(hi[d] - centre[d]) ? lo[d] : hi[d]);
      if (placement.period <= 0) return at(p);
      // Round a ring: the nearest (or farthest) point of the box to the centre taken round.
      double most = at(p);
      const double period = placement.period;
      for (const double x : {centre[0] - period, centre[0] + period, centre[0] + period / 2,
                             centre[0] - period / 2, lo[0], hi[0]}) {
        p[0] = std::clamp(x, lo[0], hi[0]);
        most = std::max(most, at(p));
      }
      return most;
    }
    case DensityKind::image: {  // the brightest or darkest pixel the box touches
      if (!luminance || width <= 0 || height <= 0) return values[0];
      const int x0 = pixel_of(lo[0], rect[0], rect[2], width);
      const int x1 = pixel_of(hi[0], rect[0], rect[2], width);
      const int y0 = height - 1 - pixel_of(hi[1], rect[1], rect[3], height);
      const int y1 = height - 1 - pixel_of(lo[1], rect[1], rect[3], height);
      const bool brighter = values[1] >= values[0];
      float best = brighter ? 0.0f : 1.0f;
      for (int y = y0; y <= y1; ++y) {
        const float* row = luminance->data() + static_cast<size_t>(y) * width;
        for (int x = x0; x <= x1; ++x)
          best = brighter ? std::max(best, row[x]) : std::min(best, row[x]);
      }
      return blend(values, best);
    }
  }
  return 0;
}

double DensityField::at_cell(const std::array<int64_t, 3>& cell) const {
  return at(placement.centre(cell, dimension));
}

double DensityField::survival(const Lattice& lattice, int stage, const std::array<int64_t, 3>& cell,
                              double survival_product) const {
  if (stage == 0) return 1;
  if (stage == lattice.stages) return std::min(1.0, survival_product * at_cell(cell));
  const auto side = static_cast<double>(lattice.side_in_cells(stage));
  std::array<double, 3> lo{0, 0, 0}, hi{0, 0, 0};
  for (int d = 0; d < dimension; ++d) {
    lo[d] = placement.origin[d] + placement.scale[d] * static_cast<double>(cell[d]) * side;
    hi[d] = placement.origin[d] + placement.scale[d] * (static_cast<double>(cell[d]) + 1) * side;
  }
  if (dimension >= 2) {  // a cell above the finest spans several courses: every shift they take
    const auto range = placement.shift_range();
    lo[0] += range[0];
    hi[0] += range[1];
  }
  if (placement.period > 0) {  // round a ring: the span taken round, in one or two parts
    const double period = placement.period, turns = std::floor(lo[0] / period) * period;
    lo[0] -= turns, hi[0] -= turns;
    if (hi[0] - lo[0] >= period) {
      lo[0] = 0, hi[0] = period;
    } else if (hi[0] > period) {
      std::array<double, 3> lo2 = lo, hi2 = hi;
      lo2[0] = 0, hi2[0] = hi[0] - period, hi[0] = period;
      return std::min(1.0, survival_product * std::max(most_in(lo, hi), most_in(lo2, hi2)));
    }
  }
  return std::min(1.0, survival_product * most_in(lo, hi));
}

namespace {

std::string number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

std::string point(const std::array<double, 3>& p, int dimension) {
  std::string s = "[";
  for (int d = 0; d < dimension; ++d) s += (d ? ", " : "") + number(p[d]);
  return s + "]";
}

}  // namespace

std::string describe(const DensityField& f) {
  const std::string a = number(f.values[0]), b = number(f.values[1]);
  switch (f.kind) {
    case DensityKind::linear:
      return "linear: " + a + " at " + point(f.from, f.dimension) + " to " + b + " at " +
             point(f.to, f.dimension);
    case DensityKind::radial:
      return "radial: " + a + " at " + point(f.centre, f.dimension) + " to " + b + " at " +
             number(f.radius);
    case DensityKind::image:
      return "image " + f.path + ": " + a + " black to " + b + " white";
  }
  return "";
}

Threshold threshold_of(double q) {
  if (!(q > 0)) return {0, false};
  if (q >= 1) return {UINT64_MAX, true};
  return {static_cast<uint64_t>(std::ldexp(q, 64)), false};
}

}  // namespace curdle
