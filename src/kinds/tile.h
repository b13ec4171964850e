// Tiles (Cirovic 2014, figs. 1, 3 and 7): a floor or wall of square or oblong tiles, the size
// given or what the field's cells fill.
#pragma once

#include "kinds/surface_kind.h"

namespace curdle {

class TileKind : public SurfaceKind {
 public:
  std::string_view name() const override { return "tile"; }
  std::string_view element_noun() const override { return "tile"; }
  char id_letter() const override { return 'T'; }
  double thickness(const LayoutSpec&) const override { return 10; }
  bool bedded() const override { return true; }

 protected:
  reading::SurfaceKeys surface() const override { return {"tile", "size", false, true, true}; }
};

}  // namespace curdle
