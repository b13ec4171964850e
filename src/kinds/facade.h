// Façades: a wall of panels or bricks in stack or stretcher bond, standing upright, with its
// windows and doors given as rectangles or as the dark pixels of a mask image.
#pragma once

#include <string>
#include <vector>

#include "kinds/surface_kind.h"

namespace curdle {

struct FacadeKeys : KindKeysOf<FacadeKeys> {
  std::vector<Rect> openings;  // windows and doors, mm from the wall's origin
  std::string mask;            // image whose dark pixels are openings (read by the application)
};

class FacadeKind : public SurfaceKind {
 public:
  std::string_view name() const override { return "facade"; }
  std::string_view element_noun() const override { return "panel"; }
  char id_letter() const override { return 'F'; }
  double thickness(const LayoutSpec&) const override { return 20; }
  bool upright() const override { return true; }
  std::unique_ptr<KindKeys> default_keys() const override;
  bool take_opening(LayoutSpec& spec, const std::array<double, 4>& rect) const override;

 protected:
  reading::SurfaceKeys surface() const override { return {"panel", "wall", true, true, true}; }
  std::vector<std::string> own_keys() const override { return {"openings", "mask"}; }
  void read_own(reading::TableReader& r, const Design& design, LayoutSpec& spec) const override;
  std::vector<Rect> openings(const LayoutSpec& spec) const override;
  void after_laying(Layout& layout, const LayoutSpec& spec) const override;
};

}  // namespace curdle
