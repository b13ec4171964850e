// Parks (Cirovic 2014, figs. 5a and 5b): each curd places one kind of element in its cells —
// a surface (grey paving) or an object (a tree, a bench); cells where no surface survived keep
// the ground (white paving). Elements that share a cell all stay (a + b = ab): surfaces split
// the cell in strips, objects stand in slots along its longer side, clear of each other and of
// the cell's edge by the recipe's clearance, each where the cell's own random stream puts it
// in its slot (park_placing.h); a tree pit may reach past the cell into laid ground no other
// object or pit holds, and a bench stands at its slot's edge facing the path or zone named.
#pragma once

#include <string>
#include <vector>

#include "curdle/curd.h"
#include "kinds/surface_kind.h"
#include "layout/layout.h"
#include "layout/planting_spec.h"

namespace curdle {

// What each curd places in its cells (Cirovic 2014, fig. 5).
struct ParkElement {
  std::string type;      // "tree", "bench", "grey paving", ...
  bool surface = false;  // fills its share of the cell (paving), or stands in it (object)
  bool round = false;    // objects: a circle of diameter size[0] (a canopy), or a rectangle
  double w = 0, h = 0;   // objects: footprint, mm
  Rgb colour;
  PlantingSpec order;  // objects: species, girth, root ball and pit
  // A rectangular object (a bench): the surface type or zone it turns to face; empty: the
  // ground, where no surface survived (the path people walk on).
  std::string faces;
};

struct ParkKeys : KindKeysOf<ParkKeys> {
  std::vector<ParkElement> elements;  // one per curd (Cirovic 2014, fig. 5)
  ParkElement ground{"white paving", true, false, 0, 0, Rgb{242, 240, 234}};  // no surface
  double clearance = 0;  // between objects, and from objects to the cell's edge
};

class ParkKind : public SurfaceKind {
 public:
  std::string_view name() const override { return "park"; }
  std::string_view element_noun() const override { return "cell"; }
  std::string_view legend_unit() const override { return "cell"; }
  char id_letter() const override { return 'C'; }  // cells; their elements become "K-..."
  double thickness(const LayoutSpec&) const override { return 30; }
  Ground ground() const override { return Ground::paper; }
  bool outdoors() const override { return true; }
  std::vector<std::string_view> own_outputs() const override {
    return {"planting.csv", "furniture.csv", "surfaces.csv"};
  }
  Depiction depiction() const override { return Depiction::objects; }
  std::string size_line(const Layout& layout) const override;
  std::unique_ptr<KindKeys> default_keys() const override;
  // Zones on a park: a play area kept free, a lawn of one value; its schedules name them.
  bool takes_zones() const override { return true; }

 protected:
  reading::SurfaceKeys surface() const override { return {"cell", "area", false, false, false}; }
  bool laid_on_a_grid() const override { return false; }
  std::vector<std::string> own_keys() const override {
    return {"elements", "ground", "clearance", "outline", "zones"};
  }
  void read_own(reading::TableReader& r, const Design& design, LayoutSpec& spec) const override;
  void replace_cells(Layout& layout, const Design& design, const LayoutSpec& spec) const override;
};

// Replaces the cells of `layout` by their surfaces and objects.
void plant(Layout& layout, const Design& design, const LayoutSpec& spec);

// The slots objects stand in when `count` share a cell of w x h: inside the clearance, split
// along the longer side.
std::vector<Rect> object_slots(const Rect& cell, size_t count, double clearance);

namespace reading {
// The kind's own keys: the elements per curd, the ground and the clearance.
void read_park(TableReader& r, const Design& design, LayoutSpec& spec);
// Each object's `faces` names a surface's type or a zone (read after the zones).
void check_park_faces(TableReader& r, const LayoutSpec& spec);
}  // namespace reading

}  // namespace curdle
