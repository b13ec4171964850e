#include "kinds/park_placing.h"

#include <Random123/philox.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace curdle {
namespace {

// The axis bearing of a direction: the larger of its components wins (x on a tie).
int square_bearing(double dx, double dy) {
  if (std::fabs(dx) >= std::fabs(dy)) return dx >= 0 ? 90 : 270;
  return dy >= 0 ? 0 : 180;
}

// The point of r nearest p.
std::array<double, 2> nearest_in(const Rect& r, const std::array<double, 2>& p) {
  return {std::clamp(p[0], r.x, r.right()), std::clamp(p[1], r.y, r.top())};
}

}  // namespace

std::array<double, 4> placing_draws(uint64_t seed, int64_t cell_x, int64_t cell_y, uint32_t member,
                                    uint32_t attempt) {
  // A key of its own: the seed's words crossed with fixed odd constants.
  const r123::Philox4x32::key_type key{
      {static_cast<uint32_t>(seed) ^ 0x9e3779b9u, static_cast<uint32_t>(seed >> 32) ^ 0x7f4a7c15u}};
  const r123::Philox4x32::ctr_type counter{
      {static_cast<uint32_t>(cell_x), static_cast<uint32_t>(cell_y), member, attempt}};
  const r123::Philox4x32::ctr_type out = r123::Philox4x32()(counter, key);
  std::array<double, 4> u{};
  for (int i = 0; i < 4; ++i) u[i] = out[i] * 0x1p-32;  // [0, 1)
  return u;
}

std::optional<int> bearing_towards(const std::array<double, 2>& from,
                                   const std::vector<Rect>& targets) {
  double best = std::numeric_limits<double>::infinity();
  std::optional<int> bearing;
  for (const Rect& r : targets) {
    const auto [nx, ny] = nearest_in(r, from);
    const double dx = nx - from[0], dy = ny - from[1], d = std::hypot(dx, dy);
    if (d >= best) continue;
    best = d;
    if (d > 1e-9) {
      bearing = square_bearing(dx, dy);
    } else {  // inside: towards the edge it is nearest leaving by, across the target
      const double left = from[0] - r.x, right = r.right() - from[0];
      const double down = from[1] - r.y, up = r.top() - from[1];
      const double m = std::min({left, right, down, up});
      bearing = m == left ? 90 : m == right ? 270 : m == down ? 0 : 180;
    }
  }
  return bearing;
}

std::optional<int> bearing_towards(const std::array<double, 2>& from, const Polygon& zone) {
  if (zone.size() < 3) return std::nullopt;
  bool inside = false;
  double best = std::numeric_limits<double>::infinity(), cx = 0, cy = 0;
  std::array<double, 2> nearest{};
  for (size_t i = 0, j = zone.size() - 1; i < zone.size(); j = i++) {
    const auto& a = zone[j];
    const auto& b = zone[i];
    cx += b[0], cy += b[1];
    if ((b[1] > from[1]) != (a[1] > from[1]) &&
        from[0] < (a[0] - b[0]) * (from[1] - b[1]) / (a[1] - b[1]) + b[0])
      inside = !inside;
    const double ex = b[0] - a[0], ey = b[1] - a[1], len2 = ex * ex + ey * ey;
    const double t =
        len2 > 0 ? std::clamp(((from[0] - a[0]) * ex + (from[1] - a[1]) * ey) / len2, 0.0, 1.0)
                 : 0.0;
    const std::array<double, 2> p{a[0] + t * ex, a[1] + t * ey};
    if (const double d = std::hypot(p[0] - from[0], p[1] - from[1]); d < best)
      best = d, nearest = p;
  }
  const double n = static_cast<double>(zone.size());
  if (inside) return square_bearing(cx / n - from[0], cy / n - from[1]);
  return square_bearing(nearest[0] - from[0], nearest[1] - from[1]);
}

}  // namespace curdle
