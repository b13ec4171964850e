// A perforated sheet on a building (a screen round a plan or along a path): its solid laid on
// its façade's frame, rolled to an arc where the façade is one. The sheet is laid flat in the
// strip's millimetres, as the flat screen is (sheet_tiles.h: its rings, and the squares its
// tiles fill); here its caps are cut into strips narrow enough that each lies within the chord
// tolerance of the arc, its edges divided at the same stations, and every corner placed by the
// frame, so the 3-D writers learn nothing of arcs.
#pragma once

#include <array>
#include <cstdint>
#include <map>
#include <vector>

#include "layout/gltf_solids.h"
#include "layout/layout.h"
#include "layout/sheet_tiles.h"
#include "layout/surface_frame.h"

namespace curdle {

// Triangles in the building's millimetres (x east, y north, z up), counter-clockwise seen from
// outside, each corner with its outward normal.
struct FramedMesh {
  std::vector<BuildingPoint> positions;
  std::vector<std::array<double, 3>> normals;
  std::vector<uint32_t> indices;
};

// The mesh in glTF's metres and axes (+Y up, -Z north), as the 3-D writers take it.
void to_gltf_mesh(const FramedMesh& mesh, std::vector<Vec3>& positions, std::vector<Vec3>& normals);

// The strip positions between `from` and `to` where an arc frame's sheet is cut so that each
// strip lies within `tolerance` mm of the arc (none on a straight frame).
std::vector<double> roll_stations(const SurfaceFrame& frame, double from, double to,
                                  double tolerance);

// How far a rolled sheet's strips may lie inside its arc, mm: as a bent unit's facets
// (framed_boxes.h), well within a sheet's tolerance, and the model a quarter of the size it
// would be at the cutting tolerance.
inline constexpr double kRolledSheetRise = 0.25;

// Adds the solid of a sheet `thickness` mm deep behind the frame's outer face: over `rings`
// (its outline counter-clockwise, the holes it keeps clockwise, strip mm) less `squares`
// (clockwise, their tiles drawn apart), caps and walls with outward normals; on an arc, in
// strips rising at most kRolledSheetRise.
void add_framed_sheet(const SurfaceFrame& frame, const std::vector<Ring>& rings,
                      const std::vector<Ring>& squares, double thickness, FramedMesh& mesh);

// A screen's sheets as the 3-D writers draw them: each sheet's rings (its rectangle and the
// openings it keeps as holes) and the squares its tiles fill, and the openings drawn as tiles
// (sheet_tiles.h), by sheet.
struct FramedScreen {
  std::vector<std::vector<Ring>> rings, squares;
  std::vector<std::vector<size_t>> tiled;  // indices in layout.elements, by sheet
};
FramedScreen framed_screen(const Layout& layout);

// Where a tile stands (a small flat piece round an opening): its local x along the chord of the
// face across the opening, y up and z out of the face, its origin at the opening's centre (a
// round one) or its box's lower-left corner (a merged one), on the sheet's back. The origin in
// the building, mm, and the chord's way in plan.
struct FramedPose {
  BuildingPoint origin{0, 0, 0};
  std::array<double, 2> along{1, 0};
};
FramedPose tile_pose(const Layout& layout, const Element& opening);

// The tile of an opening (sheet_tiles.h) from its pose's origin.
OpeningTile tile_of(const Layout& layout, const Element& opening);

// An opening's tile's shape to a nanometre, from its ring alone (tile_of triangulates a merged
// opening's, which only the first of a shape needs): openings alike share one mesh (glTF) or
// map (IFC).
std::vector<int64_t> tile_shape(const Layout& layout, const Element& opening);

// A tile as a solid `thickness` deep out of its plane: its face both sides and the hole's
// wall (gltf_solids.h: `upright`, standing; else lying).
void add_tile_solid(bool upright, const OpeningTile& tile, double thickness,
                    std::vector<Vec3>& positions, std::vector<Vec3>& normals,
                    std::vector<uint32_t>& indices);

// Where an opening's outline is drawn: its box's lower-left corner on the outer face, on the
// chord across the box, and the chord's way in plan.
FramedPose opening_pose(const Layout& layout, const Element& opening);

}  // namespace curdle
