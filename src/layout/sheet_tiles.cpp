#include "layout/sheet_tiles.h"

#include <algorithm>
#include <cmath>

#include "curdle/stop.h"
#include "layout/triangulation.h"
#include "layout/zone.h"

namespace curdle {
namespace {

constexpr double kPi = 3.14159265358979323846;

struct Square {
  double x0, y0, x1, y1;
};

Square square_of(const Circle& c) {
  const double r = c.d / 2;
  return {c.cx - r, c.cy - r, c.cx + r, c.cy + r};
}

// A merged opening's box: the least rectangle round its one ring, grown by kTileMargin on every
// side. A union of polygonised circles runs along its least box at its extremes, where the
// tile's triangulation could not tell the ring from the box; grown, the ring never touches it.
Square box_of(const Ring& ring) {
  Square s{ring[0][0], ring[0][1], ring[0][0], ring[0][1]};
  for (const auto& [x, y] : ring)
    s = {std::min(s.x0, x), std::min(s.y0, y), std::max(s.x1, x), std::max(s.y1, y)};
  return {s.x0 - kTileMargin, s.y0 - kTileMargin, s.x1 + kTileMargin, s.y1 + kTileMargin};
}

// An opening drawn as a tile: a round one, or a merged one of a single ring.
bool tileable(const Element& e) {
  if (e.outline) return e.outline->rings.size() == 1 && e.outline->rings[0].size() >= 3;
  return e.circle && e.circle->d > 0;
}

// Whether the segment a-b meets the square grown by `gap` (Liang-Barsky clipping).
bool segment_meets(const std::array<double, 2>& a, const std::array<double, 2>& b, const Square& s,
                   double gap) {
  double t0 = 0, t1 = 1;
  const double d[2] = {b[0] - a[0], b[1] - a[1]};
  const double lo[2] = {s.x0 - gap, s.y0 - gap}, hi[2] = {s.x1 + gap, s.y1 + gap};
  for (int k = 0; k < 2; ++k) {
    if (d[k] == 0) {
      if (a[k] < lo[k] || a[k] > hi[k]) return false;
      continue;
    }
    double ta = (lo[k] - a[k]) / d[k], tb = (hi[k] - a[k]) / d[k];
    if (ta > tb) std::swap(ta, tb);
    t0 = std::max(t0, ta);
    t1 = std::min(t1, tb);
    if (t0 > t1) return false;
  }
  return true;
}

Ring clockwise_square(const Square& s) {
  return {{s.x0, s.y0}, {s.x0, s.y1}, {s.x1, s.y1}, {s.x1, s.y0}};
}

}  // namespace

SheetTiles sheet_tiles(const Layout& layout, const std::vector<Ring>& sheet) {
  SheetTiles out;
  std::vector<size_t> candidates;     // candidates, by the left of their squares or boxes
  std::vector<const Ring*> edges_of;  // rings whose edges a tile's square must keep clear of
  for (const Ring& r : sheet) edges_of.push_back(&r);
  for (size_t i = 0; i < layout.elements.size(); ++i) {
    const Element& e = layout.elements[i];
    if (tileable(e)) {
      candidates.push_back(i);
    } else if (e.outline) {
      for (const Ring& r : e.outline->rings) {
        edges_of.push_back(&r);
        out.holes.push_back(r);
        std::reverse(out.holes.back().begin(), out.holes.back().end());
      }
    }
  }
  auto square = [&](size_t i) {
    const Element& e = layout.elements[i];
    return e.outline ? box_of(e.outline->rings[0]) : square_of(*e.circle);
  };
  std::sort(candidates.begin(), candidates.end(),
            [&](size_t a, size_t b) { return square(a).x0 < square(b).x0; });
  // A gap a little over the coordinates' rounding keeps squares from sharing an edge, which
  // would leave the sheet's face a polygon whose holes touch.
  const double gap = 1e-6 * std::max({layout.width, layout.height, 1.0});
  std::vector<char> clear(candidates.size(), 1);
  for (size_t a = 0; a < candidates.size(); ++a) {
    stop_point();
    const Square sa = square(candidates[a]);
    for (size_t b = a + 1; b < candidates.size(); ++b) {
      const Square sb = square(candidates[b]);
      if (sb.x0 > sa.x1 + gap) break;
      if (sb.y0 <= sa.y1 + gap && sa.y0 <= sb.y1 + gap) clear[a] = clear[b] = 0;
    }
  }
  // Each edge against the squares its x range spans, found by bisection on their left sides.
  std::vector<double> lefts(candidates.size());
  double most = 0;
  for (size_t k = 0; k < candidates.size(); ++k) {
    const Square s = square(candidates[k]);
    lefts[k] = s.x0;
    most = std::max(most, s.x1 - s.x0);
  }
  for (const Ring* ring : edges_of)
    for (size_t i = 0; i < ring->size(); ++i) {
      const auto& p = (*ring)[i];
      const auto& q = (*ring)[(i + 1) % ring->size()];
      const double x0 = std::min(p[0], q[0]) - gap - most, x1 = std::max(p[0], q[0]) + gap;
      for (size_t k = std::lower_bound(lefts.begin(), lefts.end(), x0) - lefts.begin();
           k < candidates.size() && lefts[k] <= x1; ++k)
        if (clear[k] && segment_meets(p, q, square(candidates[k]), gap)) clear[k] = 0;
    }
  for (size_t k = 0; k < candidates.size(); ++k) {
    const Element& e = layout.elements[candidates[k]];
    if (clear[k]) {
      out.squares.push_back(clockwise_square(square(candidates[k])));
      out.tiled.push_back(candidates[k]);
      continue;
    }
    if (e.outline) {  // a merged opening that is not a tile: its ring, clockwise
      out.holes.push_back(e.outline->rings[0]);
      std::reverse(out.holes.back().begin(), out.holes.back().end());
      continue;
    }
    const OpeningTile tile = opening_tile(e.circle->d, layout.chord_tolerance);
    Ring hole = tile.hole;
    for (auto& v : hole) v = {v[0] + e.circle->cx, v[1] + e.circle->cy};
    out.holes.push_back(std::move(hole));
  }
  std::sort(out.tiled.begin(), out.tiled.end());
  return out;
}

OpeningTile opening_tile(double d, double tolerance) {
  const double r = d / 2;
  const double step = tolerance >= r ? kPi / 2 : 2 * std::acos(1 - tolerance / r);
  // A multiple of four corners, so that one lies where the circle touches each side.
  const int quarter = std::max(2, static_cast<int>(std::ceil(kPi / 2 / step)));
  const int n = 4 * quarter;
  Ring ccw;
  for (int i = 0; i < n; ++i) {
    const double a = 2 * kPi * i / n;
    // The touching points exactly on the square's sides, whatever cos and sin round to.
    ccw.push_back(i % quarter ? std::array<double, 2>{r * std::cos(a), r * std::sin(a)}
                              : std::array<double, 2>{(i == 0)             ? r
                                                      : (i == 2 * quarter) ? -r
                                                                           : 0,
                                                      (i == quarter)       ? r
                                                      : (i == 3 * quarter) ? -r
                                                                           : 0});
  }
  OpeningTile tile;
  for (int q = 0; q < 4; ++q) {
    const std::array<double, 2> corner{(q == 0 || q == 3) ? r : -r, q < 2 ? r : -r};
    for (int i = q * quarter; i < (q + 1) * quarter; ++i) {
      const auto& a = ccw[i];
      const auto& b = ccw[(i + 1) % n];
      // Corner, then the later point, then the earlier: counter-clockwise round the corner.
      tile.triangles.push_back({corner, b, a});
    }
  }
  tile.hole.assign(ccw.rbegin(), ccw.rend());
  return tile;
}

Ring outline_tile_hole(const Ring& ring) {
  const Square box = box_of(ring);
  Ring hole;
  for (const auto& [x, y] : ring) hole.push_back({x - box.x0, y - box.y0});
  if (signed_area(hole) > 0) std::reverse(hole.begin(), hole.end());
  return hole;
}

OpeningTile outline_tile(const Ring& ring) {
  const Square box = box_of(ring);
  OpeningTile tile;
  tile.hole = outline_tile_hole(ring);
  const Ring square{
      {0, 0}, {box.x1 - box.x0, 0}, {box.x1 - box.x0, box.y1 - box.y0}, {0, box.y1 - box.y0}};
  tile.triangles = triangulate({square, tile.hole});
  return tile;
}

std::array<double, 4> outline_box(const Ring& ring) {
  const Square box = box_of(ring);
  return {box.x0, box.y0, box.x1, box.y1};
}

}  // namespace curdle
