// What the kinds laid over a surface share: tile, paving and façade (modules on a grid with
// joints, in stack or bond, cut at the surface's edges, its outline, openings and zones, their
// slivers checked), and perforated sheets and parks (a grid of cells, each then replaced by
// what its curds place in it: openings, surfaces and objects). Each names its keys, reads its
// own, and says its facts; the reading and laying are here.
#pragma once

#include <string>
#include <vector>

#include "layout/layout.h"
#include "recipe/layout_reader.h"

namespace curdle {

class SurfaceKind : public LayoutKind {
 public:
  bool takes_zones() const override { return laid_on_a_grid(); }
  std::vector<std::string> keys() const override;
  void read(reading::TableReader& r, Design& design, LayoutSpec& spec,
            bool field_given) const override;
  Layout build(const Design& design, const CurdField& field, const Box& view,
               const LayoutSpec& spec) const override;

 protected:
  // What the kind calls its element and its surface.
  virtual reading::SurfaceKeys surface() const = 0;
  // Whether modules are laid with bond, shift, zones and checked slivers (tile, paving,
  // facade), or cells that are then replaced (perforation, park).
  virtual bool laid_on_a_grid() const { return true; }
  // Keys of its own, read after the surface's (and before a grid's bond, zones and shift).
  virtual std::vector<std::string> own_keys() const { return {}; }
  virtual void read_own(reading::TableReader&, const Design&, LayoutSpec&) const {}
  // Holes the surface has of itself (a façade's windows and doors), mm.
  virtual std::vector<Rect> openings(const LayoutSpec&) const { return {}; }
  // After the grid is laid, before its slivers are checked.
  virtual void after_laying(Layout&, const LayoutSpec&) const {}
  // After the legend is counted: the cells replaced by what the curds place in them.
  virtual void replace_cells(Layout&, const Design&, const LayoutSpec&) const {}
};

}  // namespace curdle
