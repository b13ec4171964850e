// Blocks (a 3-D curd as architecture): a stack of voxels of module_w x module_h in plan and
// voxel_h a storey, drawn as a plan and an elevation side by side.
#pragma once

#include "layout/layout.h"

namespace curdle {

struct BlocksKeys : KindKeysOf<BlocksKeys> {
  double voxel_h = 3000;
};

class BlocksKind : public LayoutKind {
 public:
  std::string_view name() const override { return "blocks"; }
  std::string_view element_noun() const override { return "block"; }
  std::string_view legend_unit() const override { return "voxel"; }
  char id_letter() const override { return 'B'; }  // "B-L..-R..-C.."
  int dimension() const override { return 3; }
  double thickness(const LayoutSpec& spec) const override;
  Ground ground() const override { return Ground::paper; }
  Depiction depiction() const override { return Depiction::views; }
  bool laid_in_courses() const override { return false; }
  bool laid_from_corner() const override { return false; }
  std::string size_line(const Layout& layout) const override;
  std::vector<std::string> keys() const override;
  std::unique_ptr<KindKeys> default_keys() const override;
  void read(reading::TableReader& r, Design& design, LayoutSpec& spec,
            bool field_given) const override;
  Layout build(const Design& design, const CurdField& field, const Box& view,
               const LayoutSpec& spec) const override;
  CellPlacement cell_placement(const LayoutSpec& spec, const Box& view) const override;
  std::array<double, 2> drawing_extent(const LayoutSpec& spec, const Box& view) const override;
};

}  // namespace curdle
