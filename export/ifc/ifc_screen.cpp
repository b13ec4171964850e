// layout.ifc's bodies of a screen's sheets (framed_sheet.h).
#include "export/ifc/ifc_screen.h"

namespace curdle {

int64_t IfcScreenSheets::body(size_t k, const Rgb& colour) {
  if (screen_.rings.empty()) screen_ = framed_screen(l_);
  const FabricationSheet& s = l_.sheets()[k];
  FramedMesh mesh;
  add_framed_sheet(*frame_at(l_.frames(), s.area.x + s.area.w / 2), screen_.rings[k],
                   screen_.squares[k], l_.thickness, mesh);
  std::vector<int64_t> items{
      g_.mapped(g_.representation_map(g_.triangles(mesh.positions, mesh.indices, colour)),
                {0, 0, 0}, {1, 0})};
  for (const size_t i : screen_.tiled[k]) {
    const Element& e = l_.elements[i];
    auto [it, added] = tile_maps_.try_emplace(tile_shape(l_, e), 0);
    if (added) {
      std::vector<Vec3> p, n;
      std::vector<uint32_t> idx;
      add_tile_solid(true, tile_of(l_, e), l_.thickness, p, n, idx);
      std::vector<std::array<double, 3>> mm;
      for (const Vec3& v : p) mm.push_back({v[0] * 1000.0, v[1] * 1000.0, v[2] * 1000.0});
      it->second = g_.representation_map(g_.triangles(mm, idx, colour));
    }
    const FramedPose pose = tile_pose(l_, e);
    items.push_back(g_.mapped(it->second, pose.origin, pose.along));
  }
  return g_.mapped_body(items);
}

}  // namespace curdle
