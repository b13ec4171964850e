// Solids as glTF holds them: layout millimetres (x, y in the plane, up out of it) turned into
// glTF metres (y up; a floor's y runs to -z, a wall stands in x, y), and the faces of a prism
// over rings: its two caps and its walls, with outward normals.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "layout/layout.h"

namespace curdle {

using Vec3 = std::array<float, 3>;

// A point of the layout (mm) in glTF metres: standing (x, y in the wall) or lying (a floor, or
// a building's plan: x east, y north) with `up` out of its plane.
Vec3 to_gltf(bool upright, double x, double y, double up);
inline Vec3 to_gltf(const Layout& layout, double x, double y, double up) {
  return to_gltf(layout.kind->upright(), x, y, up);
}

// The two faces of a solid from `base` to `top` over `triangles` (counter-clockwise, layout
// mm): the top facing up and the bottom facing down, corners shared within a face.
void add_caps(bool upright, const std::vector<std::array<std::array<double, 2>, 3>>& triangles,
              double base, double top, std::vector<Vec3>& positions, std::vector<Vec3>& normals,
              std::vector<uint32_t>& indices);

// A wall from `base` to `top` along every edge of `rings`, facing away from the material on
// their left. Where a ring turns by less than 30 degrees (a round hole's chords) the faces share
// their corners and a normal between theirs, so that the wall reads round and takes half the
// corners; at a sharper turn each face keeps its own.
void add_walls(bool upright, const std::vector<Ring>& rings, double base, double top,
               std::vector<Vec3>& positions, std::vector<Vec3>& normals,
               std::vector<uint32_t>& indices);

// A solid from `base` to `top` over rings with the material on their left (outer rings
// counter-clockwise, islands clockwise, as union.h makes them): its caps (triangulated with
// CGAL) and its walls.
void add_prism(const Layout& layout, const std::vector<Ring>& rings, double base, double top,
               std::vector<Vec3>& positions, std::vector<Vec3>& normals,
               std::vector<uint32_t>& indices);

}  // namespace curdle
