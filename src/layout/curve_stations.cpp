#include "layout/curve_stations.h"

#include <algorithm>
#include <cmath>
#include <optional>

namespace curdle {
namespace {

constexpr double kMostTurn = 30 * 3.14159265358979323846 / 180;
constexpr size_t kFewestEdges = 4;
constexpr double kMostStations = 12;

struct Edge {
  double dx = 0, dy = 0;
  bool free = false;  // straight, along neither axis
};

// The turn from edge a to edge b, radians (0 straight on).
double turn(const Edge& a, const Edge& b) {
  return std::fabs(std::atan2(a.dx * b.dy - a.dy * b.dx, a.dx * b.dx + a.dy * b.dy));
}

// 100, 200, 250, 500 mm times a power of ten: the finest that gives at most kMostStations
// intervals over `extent`.
double round_step(double extent) {
  for (double scale = 100;; scale *= 10)
    for (const double m : {1.0, 2.0, 2.5, 5.0})
      if (extent / (m * scale) <= kMostStations) return m * scale;
}

// Where the run's chords cross the station line (x = s, or y = s): the first crossing.
std::optional<double> offset_at(const Contour& c, size_t first, size_t edges, bool along_x,
                                double s) {
  const size_t n = c.size();
  for (size_t k = 0; k < edges; ++k) {
    const ContourVertex& a = c[(first + k) % n];
    const ContourVertex& b = c[(first + k + 1) % n];
    const double a0 = along_x ? a.x : a.y, b0 = along_x ? b.x : b.y;
    const double a1 = along_x ? a.y : a.x, b1 = along_x ? b.y : b.x;
    if (s < std::min(a0, b0) || s > std::max(a0, b0) || a0 == b0) continue;
    return a1 + (b1 - a1) * (s - a0) / (b0 - a0);
  }
  return std::nullopt;
}

CurveStations stations_of(const Contour& c, size_t first, size_t edges) {
  CurveStations run;
  const size_t n = c.size();
  run.first = first, run.last = (first + edges) % n;
  double x0 = 1e300, x1 = -1e300, y0 = 1e300, y1 = -1e300;
  for (size_t k = 0; k <= edges; ++k) {
    const ContourVertex& v = c[(first + k) % n];
    x0 = std::min(x0, v.x), x1 = std::max(x1, v.x), y0 = std::min(y0, v.y), y1 = std::max(y1, v.y);
  }
  run.along_x = x1 - x0 >= y1 - y0;
  const double lo = run.along_x ? x0 : y0, hi = run.along_x ? x1 : y1;
  run.step = round_step(hi - lo);
  for (double s = std::ceil(lo / run.step) * run.step; s <= hi + 1e-9; s += run.step)
    if (const std::optional<double> o = offset_at(c, first, edges, run.along_x, s))
      run.points.push_back(run.along_x ? std::array<double, 2>{s, *o}
                                       : std::array<double, 2>{*o, s});
  return run;
}

}  // namespace

std::vector<CurveStations> curve_stations(const Contour& c) {
  const size_t n = c.size();
  std::vector<CurveStations> curves;
  if (n < kFewestEdges + 1) return curves;
  std::vector<Edge> edges(n);
  for (size_t i = 0; i < n; ++i) {
    const ContourVertex& a = c[i];
    const ContourVertex& b = c[(i + 1) % n];
    edges[i] = {b.x - a.x, b.y - a.y, a.bulge == 0 && a.x != b.x && a.y != b.y};
  }
  // Edge i continues the run of edge i - 1 when both are free and it turns gently.
  auto continues = [&](size_t i) {
    const size_t before = (i + n - 1) % n;
    return edges[i].free && edges[before].free && turn(edges[before], edges[i]) < kMostTurn;
  };
  // Start at an edge that begins a run (or none does: the whole contour is one curve, which
  // is left to its corners).
  size_t start = n;
  for (size_t i = 0; i < n && start == n; ++i)
    if (edges[i].free && !continues(i)) start = i;
  if (start == n) return curves;
  for (size_t k = 0; k < n;) {
    const size_t i = (start + k) % n;
    if (!edges[i].free || continues(i)) {
      ++k;
      continue;
    }
    size_t length = 1;
    while (length < n && continues((i + length) % n)) ++length;
    if (length >= kFewestEdges) curves.push_back(stations_of(c, i, length));
    k += length;
  }
  return curves;
}

bool inside_a_curve(const std::vector<CurveStations>& curves, size_t i, size_t n) {
  for (const CurveStations& c : curves) {
    const size_t from_first = (i + n - c.first) % n, span = (c.last + n - c.first) % n;
    if (from_first > 0 && from_first < span) return true;
  }
  return false;
}

}  // namespace curdle
