#include "layout/framed_sheet.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <unordered_map>

#include "layout/piece.h"
#include "layout/triangulation.h"
#include "layout/zone.h"

namespace curdle {
namespace {

using Point = std::array<double, 2>;
using Triangle = std::array<Point, 3>;

// A corner's hash from its coordinates' bits (+ 0.0: -0 and 0 are one corner, as == has them).
struct CornerHash {
  size_t operator()(const Point& p) const {
    const auto x = std::bit_cast<uint64_t>(p[0] + 0.0), y = std::bit_cast<uint64_t>(p[1] + 0.0);
    const uint64_t h = x * 0x9e3779b97f4a7c15ull;
    return static_cast<size_t>(h ^ (y + 0x9e3779b97f4a7c15ull + (h << 6) + (h >> 2)));
  }
};

Vec3 gltf_point(const BuildingPoint& p) {
  return {float(p[0] / 1000), float(p[2] / 1000), float(-p[1] / 1000)};
}

// The outward normal of the face at u.
std::array<double, 3> outward(const SurfaceFrame& f, double u) {
  const std::array<double, 2> d = frame_direction(f, u);
  return {d[1], -d[0], 0};  // the face lies right of its way
}

// A point of the strip on the chord of the face between strip positions `from` and `to` (at
// the same height), `inward` mm behind it square to the chord: where a flat piece across that
// span lays it.
BuildingPoint chord_point(const SurfaceFrame& f, double from, double to, double u, double v,
                          double inward) {
  const BuildingPoint a = frame_point(f, from, v, 0), b = frame_point(f, to, v, 0);
  const double dx = b[0] - a[0], dy = b[1] - a[1], len = std::hypot(dx, dy);
  if (len <= 0) return frame_point(f, u, v, inward);
  const double s = (u - from) / (to - from);
  return {a[0] + dx * s - inward * dy / len, a[1] + dy * s + inward * dx / len, a[2]};
}

// Where a sheet's points go: onto the frame, except the edges of the squares its tiles fill,
// which lie on the chord across each square as the flat tile does, so that the sheet and its
// tiles meet without a crack.
class SheetPlacer {
 public:
  SheetPlacer(const SurfaceFrame& frame, const std::vector<Ring>& squares) : frame_(frame) {
    for (const Ring& q : squares) {
      Box b{q[0][0], q[0][1], q[0][0], q[0][1]};
      for (const Point& p : q)
        b = {std::min(b.x0, p[0]), std::min(b.y0, p[1]), std::max(b.x1, p[0]),
             std::max(b.y1, p[1])};
      boxes_.push_back(b);
      widest_ = std::max(widest_, b.x1 - b.x0);
    }
    std::sort(boxes_.begin(), boxes_.end(), [](const Box& a, const Box& b) { return a.x0 < b.x0; });
  }
  BuildingPoint at(const Point& p, double inward) const {
    constexpr double kOn = 1e-7;  // mm: a point on a square's edge, after clipping's rounding
    auto it = std::upper_bound(boxes_.begin(), boxes_.end(), p[0] + kOn,
                               [](double u, const Box& b) { return u < b.x0; });
    while (it != boxes_.begin()) {
      const Box& b = *--it;
      if (b.x0 < p[0] - widest_ - kOn) break;
      if (p[0] <= b.x1 + kOn && p[1] >= b.y0 - kOn && p[1] <= b.y1 + kOn)
        return chord_point(frame_, b.x0, b.x1, p[0], p[1], inward);
    }
    return frame_point(frame_, p[0], p[1], inward);
  }

 private:
  struct Box {
    double x0, y0, x1, y1;
  };
  const SurfaceFrame& frame_;
  std::vector<Box> boxes_;  // by their left sides
  double widest_ = 0;
};

// The part of a polygon with lo <= u <= hi (Sutherland and Hodgman against two lines).
std::vector<Point> clip_slab(std::vector<Point> poly, double lo, double hi) {
  for (int side = 0; side < 2; ++side) {
    auto inside = [&](const Point& p) { return side == 0 ? p[0] >= lo : p[0] <= hi; };
    const double line = side == 0 ? lo : hi;
    std::vector<Point> out;
    for (size_t i = 0; i < poly.size(); ++i) {
      const Point& a = poly[i];
      const Point& b = poly[(i + 1) % poly.size()];
      if (inside(a)) out.push_back(a);
      if (inside(a) != inside(b)) {
        const double t = (line - a[0]) / (b[0] - a[0]);
        out.push_back({line, a[1] + t * (b[1] - a[1])});
      }
    }
    poly = std::move(out);
    if (poly.size() < 3) return {};
  }
  return poly;
}

// The triangles cut at the stations, each piece fanned from its first corner.
std::vector<Triangle> split_at(const std::vector<Triangle>& triangles,
                               const std::vector<double>& stations) {
  if (stations.empty()) return triangles;
  std::vector<Triangle> out;
  for (const Triangle& t : triangles) {
    const double lo = std::min({t[0][0], t[1][0], t[2][0]});
    const double hi = std::max({t[0][0], t[1][0], t[2][0]});
    auto first = std::upper_bound(stations.begin(), stations.end(), lo);
    if (first == stations.end() || *first >= hi) {
      out.push_back(t);
      continue;
    }
    double from = lo;
    for (auto s = first;; ++s) {
      const double to = s == stations.end() || *s >= hi ? hi : *s;
      const std::vector<Point> piece = clip_slab({t[0], t[1], t[2]}, from, to);
      for (size_t k = 1; k + 1 < piece.size(); ++k)
        out.push_back({piece[0], piece[k], piece[k + 1]});
      if (to >= hi) break;
      from = to;
    }
  }
  return out;
}

// The ring with a corner added wherever an edge crosses a station.
std::vector<Point> divided(const Ring& ring, const std::vector<double>& stations) {
  std::vector<Point> out;
  for (size_t i = 0; i < ring.size(); ++i) {
    const Point& a = ring[i];
    const Point& b = ring[(i + 1) % ring.size()];
    out.push_back(a);
    if (a[0] == b[0]) continue;
    const double lo = std::min(a[0], b[0]), hi = std::max(a[0], b[0]);
    std::vector<double> on;
    for (auto s = std::upper_bound(stations.begin(), stations.end(), lo);
         s != stations.end() && *s < hi; ++s)
      on.push_back(*s);
    if (b[0] < a[0]) std::reverse(on.begin(), on.end());
    for (const double u : on) out.push_back({u, a[1] + (u - a[0]) / (b[0] - a[0]) * (b[1] - a[1])});
  }
  return out;
}

// The walls along a ring (the material on its left, corners divided at the stations) from
// the outer face to `thickness` behind it. As add_walls does on a flat sheet, where the ring
// turns by less than 30 degrees (a round hole's chords) its faces share their corners and a
// normal between theirs. A wall faces right of its edge in the strip, and the strip's u, v and
// the face's outward normal are right-handed on any frame: each quad runs front, back, back,
// front.
void add_walls_along(const SurfaceFrame& frame, const std::vector<Point>& ring, double thickness,
                     FramedMesh& mesh) {
  const size_t m = ring.size();
  if (m < 2) return;
  const double smooth = std::cos(30 * 3.14159265358979323846 / 180);
  std::vector<Point> normal(m);  // of the edge from corner i to i + 1, in the strip
  for (size_t i = 0; i < m; ++i) {
    const Point &a = ring[i], &b = ring[(i + 1) % m];
    const double len = std::hypot(b[0] - a[0], b[1] - a[1]);
    normal[i] = len > 0 ? Point{(b[1] - a[1]) / len, -(b[0] - a[0]) / len} : Point{0, 0};
  }
  auto add_pair = [&](const Point& v, const Point& dir) {
    const double len = std::hypot(dir[0], dir[1]);
    const Point n2 = len > 0 ? Point{dir[0] / len, dir[1] / len} : Point{0, 0};
    const std::array<double, 2> d = frame_direction(frame, v[0]);
    const std::array<double, 3> out{n2[0] * d[0], n2[0] * d[1], n2[1]};
    const auto first = static_cast<uint32_t>(mesh.positions.size());
    mesh.positions.push_back(frame_point(frame, v[0], v[1], 0));
    mesh.positions.push_back(frame_point(frame, v[0], v[1], thickness));
    mesh.normals.push_back(out);
    mesh.normals.push_back(out);
    return first;
  };
  std::vector<uint32_t> leaving(m), arriving(m);
  for (size_t i = 0; i < m; ++i) {
    const Point &before = normal[(i + m - 1) % m], &after = normal[i];
    if (before[0] * after[0] + before[1] * after[1] >= smooth) {
      leaving[i] = arriving[i] = add_pair(ring[i], {before[0] + after[0], before[1] + after[1]});
    } else {
      arriving[i] = add_pair(ring[i], before);
      leaving[i] = add_pair(ring[i], after);
    }
  }
  for (size_t i = 0; i < m; ++i) {
    if (normal[i][0] == 0 && normal[i][1] == 0) continue;  // a corner given twice
    const uint32_t a = leaving[i], b = arriving[(i + 1) % m];
    mesh.indices.insert(mesh.indices.end(), {a, a + 1, b + 1, a, b + 1, b});
  }
}

}  // namespace

std::vector<double> roll_stations(const SurfaceFrame& frame, double from, double to,
                                  double tolerance) {
  const double radius = frame_radius(frame);
  if (radius <= 0 || to <= from) return {};
  // A chord of length c strays c^2 / (8 R) from its arc.
  const double step = std::max(1.0, std::sqrt(8 * radius * std::max(tolerance, 1e-3)));
  const auto n = static_cast<int64_t>(std::ceil((to - from) / step));
  std::vector<double> stations;
  for (int64_t k = 1; k < n; ++k) stations.push_back(from + (to - from) * k / n);
  return stations;
}

void add_framed_sheet(const SurfaceFrame& frame, const std::vector<Ring>& rings,
                      const std::vector<Ring>& squares, double thickness, FramedMesh& mesh) {
  double lo = 1e300, hi = -1e300;
  for (const Ring& ring : rings)
    for (const Point& p : ring) lo = std::min(lo, p[0]), hi = std::max(hi, p[0]);
  const std::vector<double> stations = roll_stations(frame, lo, hi, kRolledSheetRise);
  std::vector<Ring> cut = rings;
  cut.insert(cut.end(), squares.begin(), squares.end());
  const std::vector<Triangle> caps = split_at(triangulate(cut), stations);
  const SheetPlacer placer(frame, squares);
  auto& p = mesh.positions;
  auto& n = mesh.normals;
  auto& idx = mesh.indices;
  for (int face = 0; face < 2; ++face) {  // the outer face, then the back facing in
    const double inward = face ? thickness : 0;
    // A face's corners shared by its triangles, numbered as they first come.
    std::unordered_map<Point, uint32_t, CornerHash> corner(caps.size() * 2);
    for (const Triangle& t : caps)
      for (int k = 0; k < 3; ++k) {
        const Point& v = t[face ? 2 - k : k];
        const auto [it, added] = corner.try_emplace(v, static_cast<uint32_t>(p.size()));
        if (added) {
          p.push_back(placer.at(v, inward));
          std::array<double, 3> out = outward(frame, v[0]);
          if (face) out = {-out[0], -out[1], -out[2]};
          n.push_back(out);
        }
        idx.push_back(it->second);
      }
  }
  for (const Ring& ring : rings) add_walls_along(frame, divided(ring, stations), thickness, mesh);
}

void to_gltf_mesh(const FramedMesh& mesh, std::vector<Vec3>& positions,
                  std::vector<Vec3>& normals) {
  for (const BuildingPoint& p : mesh.positions) positions.push_back(gltf_point(p));
  for (const auto& n : mesh.normals) normals.push_back({float(n[0]), float(n[2]), float(-n[1])});
}

FramedScreen framed_screen(const Layout& layout) {
  std::vector<Ring> outlines;  // every sheet's rectangle, counter-clockwise
  for (const FabricationSheet& s : layout.sheets()) outlines.push_back(rect_polygon(s.area));
  const SheetTiles tiles = sheet_tiles(layout, outlines);
  // The sheet that holds a ring's first point: the sheets tile the strip, so it is in the
  // column that starts nearest before it (a few rows), or, on a column's edge, the one before.
  std::vector<size_t> by_x(layout.sheets().size());
  for (size_t k = 0; k < by_x.size(); ++k) by_x[k] = k;
  std::sort(by_x.begin(), by_x.end(), [&](size_t a, size_t b) {
    return layout.sheets()[a].area.x < layout.sheets()[b].area.x;
  });
  auto sheet_of = [&](const Ring& ring) {
    const auto& [x, y] = ring.front();
    auto it = std::upper_bound(by_x.begin(), by_x.end(), x,
                               [&](double u, size_t k) { return u < layout.sheets()[k].area.x; });
    for (int column = 0; column < 2 && it != by_x.begin(); ++column) {
      const double x0 = layout.sheets()[*std::prev(it)].area.x;
      while (it != by_x.begin() && layout.sheets()[*std::prev(it)].area.x == x0) {
        const Rect& a = layout.sheets()[*--it].area;
        if (x >= a.x && x <= a.right() && y >= a.y && y <= a.top()) return *it;
      }
    }
    return layout.sheets().size();
  };
  FramedScreen out;
  out.rings.resize(layout.sheets().size());
  out.squares.resize(layout.sheets().size());
  for (size_t k = 0; k < layout.sheets().size(); ++k) out.rings[k].push_back(outlines[k]);
  for (const Ring& h : tiles.holes)
    if (const size_t k = sheet_of(h); k < out.rings.size()) out.rings[k].push_back(h);
  for (const Ring& q : tiles.squares)
    if (const size_t k = sheet_of(q); k < out.squares.size()) out.squares[k].push_back(q);
  out.tiled.resize(layout.sheets().size());
  for (const size_t i : tiles.tiled)
    out.tiled[static_cast<size_t>(layout.elements[i].sheet)].push_back(i);
  return out;
}

namespace {

// The span of the face a tile covers, and its origin along it.
struct TileSpan {
  double from = 0, to = 0, origin = 0, v = 0;
};
TileSpan tile_span(const Element& e) {
  if (e.outline) {
    const std::array<double, 4> box = outline_box(e.outline->rings[0]);
    return {box[0], box[2], box[0], box[1]};
  }
  const Circle& c = *e.circle;
  return {c.cx - c.d / 2, c.cx + c.d / 2, c.cx, c.cy};
}

}  // namespace

FramedPose tile_pose(const Layout& layout, const Element& e) {
  const TileSpan s = tile_span(e);
  const SurfaceFrame& frame = *frame_at(layout.frames(), (s.from + s.to) / 2);
  const BuildingPoint a = frame_point(frame, s.from, s.v, 0), b = frame_point(frame, s.to, s.v, 0);
  const double len = std::hypot(b[0] - a[0], b[1] - a[1]);
  const std::array<double, 2> d =
      len > 0 ? std::array<double, 2>{(b[0] - a[0]) / len, (b[1] - a[1]) / len}
              : frame_direction(frame, s.from);
  // Its front on the chord across its square, where the sheet lays the square's edges.
  return {chord_point(frame, s.from, s.to, s.origin, s.v, layout.thickness), d};
}

OpeningTile tile_of(const Layout& layout, const Element& e) {
  if (e.outline) return outline_tile(e.outline->rings[0]);
  return opening_tile(e.circle->d, layout.chord_tolerance);
}

void add_tile_solid(bool upright, const OpeningTile& tile, double thickness,
                    std::vector<Vec3>& positions, std::vector<Vec3>& normals,
                    std::vector<uint32_t>& indices) {
  add_caps(upright, tile.triangles, 0, thickness, positions, normals, indices);
  add_walls(upright, {tile.hole}, 0, thickness, positions, normals, indices);
}

FramedPose opening_pose(const Layout& layout, const Element& e) {
  const Rect b = laid_bounds(e);
  const SurfaceFrame& f = *frame_at(layout.frames(), b.x + b.w / 2);
  const BuildingPoint p = frame_point(f, b.x, b.y, 0), q = frame_point(f, b.right(), b.y, 0);
  const double len = std::hypot(q[0] - p[0], q[1] - p[1]);
  return {p, {(q[0] - p[0]) / len, (q[1] - p[1]) / len}};
}

std::vector<int64_t> tile_shape(const Layout& layout, const Element& e) {
  const Ring hole = e.outline ? outline_tile_hole(e.outline->rings[0])
                              : opening_tile(e.circle->d, layout.chord_tolerance).hole;
  std::vector<int64_t> shape;
  for (const auto& [x, y] : hole)
    shape.push_back(std::llround(x * 1e6)), shape.push_back(std::llround(y * 1e6));
  return shape;
}

}  // namespace curdle
