// What tile, paving and façade layouts share: modules on a grid with joints, laid from a corner
// (or centred), in stack or bond, cut at the surface's edges, its outline, openings and
// excluded zones, with the slivers checked. Each of them names its keys and its thickness.
#pragma once

#include <vector>

#include "layout/layout.h"
#include "recipe/layout_reader.h"

namespace curdle {

class GridKind : public LayoutKind {
 public:
  bool takes_zones() const override { return true; }
  std::vector<std::string> keys() const override;
  void read(reading::TableReader& r, Design& design, LayoutSpec& spec,
            bool field_given) const override;
  Layout build(const Design& design, const CurdField& field, const Box& view,
               const LayoutSpec& spec) const override;

 protected:
  // What the kind calls its element and its surface.
  virtual reading::SurfaceKeys surface() const = 0;
  // Keys of its own, read after the surface's and before the cut rules.
  virtual std::vector<std::string> own_keys() const { return {}; }
  virtual void read_own(reading::TableReader&, LayoutSpec&) const {}
  // Holes the surface has of itself (a façade's windows and doors), mm.
  virtual std::vector<Rect> openings(const LayoutSpec&) const { return {}; }
  // After the grid is laid, before its slivers are checked.
  virtual void after_laying(Layout&, const LayoutSpec&) const {}
};

}  // namespace curdle
