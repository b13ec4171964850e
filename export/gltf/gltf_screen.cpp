// layout.glb's sheets of a screen on a building (framed_sheet.h).
#include "export/gltf/gltf_screen.h"

#include <fmt/format.h>
#include <tiny_gltf.h>

#include <cmath>
#include <map>

#include "curdle/stop.h"
#include "export/gltf/gltf_model.h"
#include "layout/framed_sheet.h"

namespace curdle {

std::vector<int> add_screen_sheets(ModelBuilder& b, const Layout& layout, int metal) {
  const double t = layout.thickness;
  const FramedScreen screen = framed_screen(layout);
  std::map<std::vector<int64_t>, int> tile_meshes;  // by shape
  std::vector<std::vector<int>> tile_nodes(layout.sheets().size());
  for (const std::vector<size_t>& on_sheet : screen.tiled)
    for (const size_t i : on_sheet) {
      stop_point();
      const Element& e = layout.elements[i];
      auto [it, added] = tile_meshes.try_emplace(tile_shape(layout, e), 0);
      if (added) {
        std::vector<Vec3> tp, tn;
        std::vector<uint32_t> ti;
        add_tile_solid(true, tile_of(layout, e), t, tp, tn, ti);
        it->second = b.add_mesh(fmt::format("sheet round opening {}", tile_meshes.size()),
                                {b.primitive(tp, tn, ti, metal)});
      }
      // The tile's thickness runs out of the face from the sheet's back.
      const FramedPose pose = tile_pose(layout, e);
      const double turn = std::atan2(pose.along[1], pose.along[0]);
      tinygltf::Node part;
      part.mesh = it->second;
      part.translation = {pose.origin[0] / 1000, pose.origin[2] / 1000, -pose.origin[1] / 1000};
      part.rotation = {0, std::sin(turn / 2), 0, std::cos(turn / 2)};
      tile_nodes[static_cast<size_t>(e.sheet)].push_back(b.add_node(std::move(part)));
    }
  std::vector<int> sheets;
  for (size_t k = 0; k < layout.sheets().size(); ++k) {
    const FabricationSheet& s = layout.sheets()[k];
    FramedMesh mesh;
    add_framed_sheet(*frame_at(layout.frames(), s.area.x + s.area.w / 2), screen.rings[k],
                     screen.squares[k], t, mesh);
    std::vector<Vec3> p, n;
    to_gltf_mesh(mesh, p, n);
    tinygltf::Node node;
    node.name = s.id;
    node.mesh = b.add_mesh("sheet " + s.id, {b.primitive(p, n, mesh.indices, metal)});
    node.children = std::move(tile_nodes[k]);
    sheets.push_back(b.add_node(std::move(node)));
  }
  return sheets;
}

}  // namespace curdle
