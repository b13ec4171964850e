// Façades: a wall of panels or bricks in stack or stretcher bond (a building also in English or
// Flemish), standing upright, with its
// windows and doors given as rectangles or as the dark pixels of a mask image.
#pragma once

#include <string>
#include <vector>

#include "building/building.h"
#include "building/coursing.h"
#include "building/strip_ring.h"
#include "kinds/surface_kind.h"

namespace curdle {

struct FacadeKeys : KindKeysOf<FacadeKeys> {
  std::vector<Rect> openings;  // windows and doors, mm from the wall's origin
  std::string mask;            // image whose dark pixels are openings (read by the application)
  // [layout.building]: the wall is the building's envelope unrolled (building/), laid in
  // courses round its corners in layout.bond (stretcher bond unless given).
  std::optional<BuildingKeys> building;
  std::optional<Envelope> envelope;
  CourseBond bond = CourseBond::stretcher;
  std::optional<StripRing> ring;  // the field round a closed envelope (strip_ring.h)
};

class FacadeKind : public SurfaceKind {
 public:
  std::string_view name() const override { return "facade"; }
  std::string_view element_noun() const override { return "panel"; }
  char id_letter() const override { return 'F'; }
  double thickness(const LayoutSpec& spec) const override;
  bool upright() const override { return true; }
  const Envelope* envelope(const LayoutSpec& spec) const override;
  std::unique_ptr<KindKeys> default_keys() const override;
  bool take_opening(LayoutSpec& spec, const std::array<double, 4>& rect) const override;
  std::optional<std::array<int64_t, 2>> own_cells(const LayoutSpec& spec) const override;
  // Round a ring, each field cell a ring cell of the strip, turned by its phase and taken
  // round: a density field in mm lies where it says on the building.
  CellPlacement cell_placement(const LayoutSpec& spec, const Box& view) const override;
  void read(reading::TableReader& r, Design& design, LayoutSpec& spec,
            bool field_given) const override;
  Layout build(const Design& design, const CurdField& field, const Box& view,
               const LayoutSpec& spec) const override;

 protected:
  reading::SurfaceKeys surface() const override { return {"panel", "wall", true, true, true}; }
  std::vector<std::string> own_keys() const override { return {"openings", "mask", "building"}; }
  void read_own(reading::TableReader& r, const Design& design, LayoutSpec& spec) const override;
  std::vector<Rect> openings(const LayoutSpec& spec) const override;
  void after_laying(Layout& layout, const LayoutSpec& spec) const override;
};

}  // namespace curdle
