#include "layout/laying_pattern.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "curdle/error.h"

namespace curdle {
namespace {

constexpr double kRoot2 = 1.41421356237309504880;
constexpr double kRoot3 = 1.73205080756887729353;

Ring rectangle(double x, double y, double w, double h) {
  return {{x, y}, {x + w, y}, {x + w, y + h}, {x, y + h}};
}

struct Extent {
  double x0 = 0, y0 = 0, x1 = 0, y1 = 0;
};

Extent extent_of(const Ring& ring) {
  Extent e{std::numeric_limits<double>::max(), std::numeric_limits<double>::max(),
           std::numeric_limits<double>::lowest(), std::numeric_limits<double>::lowest()};
  for (const auto& [x, y] : ring)
    e.x0 = std::min(e.x0, x), e.y0 = std::min(e.y0, y), e.x1 = std::max(e.x1, x),
    e.y1 = std::max(e.y1, y);
  return e;
}

// A unit whose extent meets the surface's inside (not only its edge) may be laid.
bool meets(const Ring& ring, double w, double h) {
  const Extent e = extent_of(ring);
  constexpr double kEps = 1e-6;
  return e.x0 < w - kEps && e.x1 > kEps && e.y0 < h - kEps && e.y1 > kEps;
}

// Pointy-top hexagons across the flats `a` over w x h, rows moved half a pitch every other row.
std::vector<PatternUnit> hexagons(double a, double joint, double w, double h) {
  const double pitch_x = a + joint, pitch_y = pitch_x * kRoot3 / 2, r = a / kRoot3;
  std::vector<PatternUnit> units;
  const auto rows = static_cast<int64_t>(std::ceil(h / pitch_y)) + 1;
  const auto columns = static_cast<int64_t>(std::ceil(w / pitch_x)) + 1;
  for (int64_t row = -1; row <= rows; ++row)
    for (int64_t column = -1; column <= columns; ++column) {
      const double cx = a / 2 + static_cast<double>(column) * pitch_x + (row & 1 ? pitch_x / 2 : 0);
      const double cy = r + static_cast<double>(row) * pitch_y;
      PatternUnit u;
      for (int k = 0; k < 6; ++k) {
        const double angle = (30.0 + 60.0 * k) * 3.14159265358979323846 / 180;
        u.ring.push_back({cx + r * std::cos(angle), cy + r * std::sin(angle)});
      }
      u.column = column, u.row = row, u.turn = 0;
      if (meets(u.ring, w, h)) units.push_back(std::move(u));
    }
  return units;
}

// Squares of n units, side `length`, turned a quarter in a chequer.
std::vector<PatternUnit> basketweave(double length, double width, double joint, double w,
                                     double h) {
  const int n = basketweave_units(length, width, joint);
  const double pitch = length + joint;
  std::vector<PatternUnit> units;
  for (int64_t k = 0; static_cast<double>(k) * pitch < h; ++k)
    for (int64_t i = 0; static_cast<double>(i) * pitch < w; ++i) {
      const double x = static_cast<double>(i) * pitch, y = static_cast<double>(k) * pitch;
      const bool along_x = (i + k) % 2 == 0;
      for (int m = 0; m < n; ++m) {
        const double step = m * (width + joint);
        PatternUnit u;
        u.ring =
            along_x ? rectangle(x, y + step, length, width) : rectangle(x + step, y, width, length);
        u.column = i, u.row = k, u.part = m + 1, u.turn = along_x ? 0 : 90;
        if (meets(u.ring, w, h)) units.push_back(std::move(u));
      }
    }
  return units;
}

// Herringbone of units `width` wide and two widths and a joint long: a unit along x and one
// standing on its left end, repeated a pitch up and along (the course) and two pitches along
// and down (the next course). At 45° the whole is turned so that the courses run along x.
std::vector<PatternUnit> herringbone(double width, double joint, double w, double h, bool turned) {
  const double p = width + joint, length = 2 * width + joint;
  // The pattern's frame to the surface's: turned by -45° at 45°.
  auto to_surface = [&](double x, double y) -> std::array<double, 2> {
    if (!turned) return {x, y};
    return {(x + y) / kRoot2, (y - x) / kRoot2};
  };
  auto to_pattern = [&](double x, double y) -> std::array<double, 2> {
    if (!turned) return {x, y};
    return {(x - y) / kRoot2, (x + y) / kRoot2};
  };
  // The courses and steps whose units can meet the surface, from its corners.
  double m_lo = 1e300, m_hi = -1e300, n_lo = 1e300, n_hi = -1e300;
  for (const double x : {0.0, w})
    for (const double y : {0.0, h}) {
      const auto [u, v] = to_pattern(x, y);
      const double m = (u + v) / (2 * p), n = (u - v) / (4 * p);
      m_lo = std::min(m_lo, m), m_hi = std::max(m_hi, m);
      n_lo = std::min(n_lo, n), n_hi = std::max(n_hi, n);
    }
  std::vector<PatternUnit> units;
  const auto n0 = static_cast<int64_t>(std::floor(n_lo)) - 2;
  const auto n1 = static_cast<int64_t>(std::ceil(n_hi)) + 2;
  const auto m0 = static_cast<int64_t>(std::floor(m_lo)) - 3;
  const auto m1 = static_cast<int64_t>(std::ceil(m_hi)) + 3;
  for (int64_t n = n0; n <= n1; ++n)
    for (int64_t m = m0; m <= m1; ++m)
      for (int t = 0; t < 2; ++t) {
        const double ox = p * static_cast<double>(m + 2 * n),
                     oy = p * static_cast<double>(m - 2 * n);
        const Ring local = t == 0 ? rectangle(ox, oy, length, width)
                                  : rectangle(ox, oy + width + joint, width, length);
        PatternUnit u;
        for (const auto& [x, y] : local) u.ring.push_back(to_surface(x, y));
        u.column = m, u.row = 2 * -n + t;
        u.turn = (t == 0 ? 0.0 : 90.0) - (turned ? 45.0 : 0.0);
        if (meets(u.ring, w, h)) units.push_back(std::move(u));
      }
  return units;
}

}  // namespace

std::string_view pattern_name(LayingPattern pattern) {
  switch (pattern) {
    case LayingPattern::grid:
      return "grid";
    case LayingPattern::herringbone:
      return "herringbone";
    case LayingPattern::herringbone_45:
      return "herringbone-45";
    case LayingPattern::basketweave:
      return "basketweave";
    case LayingPattern::hexagon:
      return "hexagon";
    case LayingPattern::hexagon_flat:
      return "hexagon-flat";
  }
  return "grid";
}

std::optional<LayingPattern> pattern_named(std::string_view name) {
  for (const LayingPattern p :
       {LayingPattern::grid, LayingPattern::herringbone, LayingPattern::herringbone_45,
        LayingPattern::basketweave, LayingPattern::hexagon, LayingPattern::hexagon_flat})
    if (pattern_name(p) == name) return p;
  if (name == "herringbone-90") return LayingPattern::herringbone;
  if (name == "hexagon-pointy") return LayingPattern::hexagon;
  return std::nullopt;
}

int basketweave_units(double length, double width, double joint) {
  for (int n = 2; n <= 4; ++n)
    if (std::fabs(n * width + (n - 1) * joint - length) <= 0.5) return n;
  return 0;
}

std::vector<PatternUnit> pattern_units(LayingPattern pattern, double length, double width,
                                       double joint, double surface_w, double surface_h) {
  // Bounded before anything is made: the units over the surface and a border of two units.
  const double reach = 2 * (length + joint);
  const double estimate =
      (surface_w + 2 * reach) * (surface_h + 2 * reach) /
      std::max(
          length * width *
              (pattern == LayingPattern::hexagon || pattern == LayingPattern::hexagon_flat ? 0.866
                                                                                           : 1.0),
          1e-9);
  if (pattern != LayingPattern::grid && !(estimate <= static_cast<double>(kMaxPatternUnits)))
    throw ResourceLimitError(fmt::format(
        "a {} pattern of {:g} x {:g} mm units over {:g} x {:g} mm is about {:.3g} units, above "
        "the limit of {}; use larger units or a smaller surface",
        pattern_name(pattern), length, width, surface_w, surface_h, estimate, kMaxPatternUnits));
  std::vector<PatternUnit> units;
  switch (pattern) {
    case LayingPattern::grid:
      return {};
    case LayingPattern::herringbone:
    case LayingPattern::herringbone_45:
      units =
          herringbone(width, joint, surface_w, surface_h, pattern == LayingPattern::herringbone_45);
      break;
    case LayingPattern::basketweave:
      units = basketweave(length, width, joint, surface_w, surface_h);
      break;
    case LayingPattern::hexagon:
      units = hexagons(length, joint, surface_w, surface_h);
      break;
    case LayingPattern::hexagon_flat:
      // Pointy-top hexagons over the surface turned about its diagonal: x and y swap, and so
      // do columns and rows (each ring reversed to run counter-clockwise again).
      units = hexagons(length, joint, surface_h, surface_w);
      for (PatternUnit& u : units) {
        for (auto& v : u.ring) std::swap(v[0], v[1]);
        std::reverse(u.ring.begin(), u.ring.end());
        std::swap(u.column, u.row);
        u.turn = 90;
      }
      break;
  }
  if (units.empty()) return units;
  int64_t c0 = units[0].column, r0 = units[0].row;
  for (const PatternUnit& u : units) c0 = std::min(c0, u.column), r0 = std::min(r0, u.row);
  for (PatternUnit& u : units) u.column -= c0, u.row -= r0;
  return units;
}

std::array<double, 2> pattern_cell_pitch(LayingPattern pattern, double length, double width,
                                         double joint) {
  switch (pattern) {
    case LayingPattern::herringbone:
    case LayingPattern::herringbone_45:
      return {(width + joint) * kRoot2, (width + joint) * kRoot2};
    case LayingPattern::basketweave:
      return {length + joint, length + joint};
    case LayingPattern::hexagon:
      return {length + joint, (length + joint) * kRoot3 / 2};
    case LayingPattern::hexagon_flat:
      return {(length + joint) * kRoot3 / 2, length + joint};
    case LayingPattern::grid:
      break;
  }
  return {length + joint, width + joint};
}

std::array<int64_t, 2> pattern_cells(const std::vector<PatternUnit>& units) {
  std::array<int64_t, 2> cells{0, 0};
  for (const PatternUnit& u : units)
    cells = {std::max(cells[0], u.column + 1), std::max(cells[1], u.row + 1)};
  return cells;
}

}  // namespace curdle
