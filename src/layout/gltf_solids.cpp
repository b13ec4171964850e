#include "layout/gltf_solids.h"

#include <cmath>
#include <unordered_map>

#include "layout/triangulation.h"

namespace curdle {

Vec3 to_gltf(bool upright, double x, double y, double up) {
  if (upright) return {float(x / 1000), float(y / 1000), float(up / 1000)};
  return {float(x / 1000), float(up / 1000), float(-y / 1000)};
}

void add_caps(bool upright, const std::vector<std::array<std::array<double, 2>, 3>>& triangles,
              double base, double top, std::vector<Vec3>& p, std::vector<Vec3>& n,
              std::vector<uint32_t>& idx) {
  // The caps share their corners between triangles (one normal a face): a perforated
  // sheet's 8,000 openings took a third more bytes with three corners a triangle.
  struct CornerHash {
    size_t operator()(const std::array<double, 2>& v) const {
      return std::hash<double>()(v[0]) * 31 + std::hash<double>()(v[1]);
    }
  };
  for (int face = 0; face < 2; ++face) {  // top, then bottom facing down
    std::unordered_map<std::array<double, 2>, uint32_t, CornerHash> corner;
    corner.reserve(triangles.size() * 2);
    auto index_of = [&](const std::array<double, 2>& v) {
      const auto [it, added] = corner.try_emplace(v, static_cast<uint32_t>(p.size()));
      if (added) {
        p.push_back(to_gltf(upright, v[0], v[1], face ? base : top));
        n.push_back(to_gltf(upright, 0, 0, face ? -1000 : 1000));  // out of the plane
      }
      return it->second;
    };
    for (const auto& tri : triangles)
      for (int k = 0; k < 3; ++k) idx.push_back(index_of(tri[face ? 2 - k : k]));
  }
}

void add_walls(bool upright, const std::vector<Ring>& rings, double base, double top,
               std::vector<Vec3>& p, std::vector<Vec3>& n, std::vector<uint32_t>& idx) {
  const double smooth = std::cos(30 * 3.14159265358979323846 / 180);
  for (const Ring& given : rings) {
    Ring ring;
    for (const auto& v : given)
      if (ring.empty() || v != ring.back()) ring.push_back(v);
    while (ring.size() > 1 && ring.front() == ring.back()) ring.pop_back();
    const size_t m = ring.size();
    if (m < 2) continue;
    std::vector<std::array<double, 2>> normal(m);  // of the edge from corner i to i + 1
    for (size_t i = 0; i < m; ++i) {
      const auto a = ring[i], c = ring[(i + 1) % m];
      const double dx = c[0] - a[0], dy = c[1] - a[1], len = std::hypot(dx, dy);
      normal[i] = {dy / len, -dx / len};
    }
    // The first of the corner's pair (bottom, top) for the edge leaving it and the one
    // arriving at it.
    std::vector<uint32_t> leaving(m), arriving(m);
    auto add_pair = [&](const std::array<double, 2>& v, std::array<double, 2> dir) {
      const double len = std::hypot(dir[0], dir[1]);
      const Vec3 nv = to_gltf(upright, dir[0] / len * 1000, dir[1] / len * 1000, 0);
      const uint32_t first = static_cast<uint32_t>(p.size());
      p.push_back(to_gltf(upright, v[0], v[1], base));
      p.push_back(to_gltf(upright, v[0], v[1], top));
      n.push_back(nv);
      n.push_back(nv);
      return first;
    };
    for (size_t i = 0; i < m; ++i) {
      const auto& before = normal[(i + m - 1) % m];
      const auto& after = normal[i];
      if (before[0] * after[0] + before[1] * after[1] >= smooth) {
        leaving[i] = arriving[i] = add_pair(ring[i], {before[0] + after[0], before[1] + after[1]});
      } else {
        arriving[i] = add_pair(ring[i], before);
        leaving[i] = add_pair(ring[i], after);
      }
    }
    for (size_t i = 0; i < m; ++i) {
      const uint32_t a = leaving[i], c = arriving[(i + 1) % m];
      idx.insert(idx.end(), {a, c, c + 1, a, c + 1, a + 1});
    }
  }
}

void add_prism(const Layout& layout, const std::vector<Ring>& rings, double base, double top,
               std::vector<Vec3>& p, std::vector<Vec3>& n, std::vector<uint32_t>& idx) {
  add_caps(layout.kind->upright(), triangulate(rings), base, top, p, n, idx);
  add_walls(layout.kind->upright(), rings, base, top, p, n, idx);
}

}  // namespace curdle
