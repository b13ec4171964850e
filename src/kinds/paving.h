// Paving (Cirovic 2014, fig. 7): slabs or setts over a floor of a given size, in stack or
// running bond, around planters, drains and tree pits.
#pragma once

#include "kinds/surface_kind.h"

namespace curdle {

class PavingKind : public SurfaceKind {
 public:
  std::string_view name() const override { return "paving"; }
  std::string_view element_noun() const override { return "paving tile"; }
  char id_letter() const override { return 'P'; }
  double thickness(const LayoutSpec&) const override { return 30; }
  bool bedded() const override { return true; }
  bool outdoors() const override { return true; }

 protected:
  reading::SurfaceKeys surface() const override { return {"tile", "floor", true, true, true}; }
};

}  // namespace curdle
