// Perforated sheets (Cirovic 2014, fig. 4): each curd is a round opening at an offset from the
// cell centre. Openings that overlap in a cell either become one larger opening of their summed
// area (mix, a + b = c) or are cut as their union (keep, a + b = ab). Then the fabrication rules:
// smallest diameter, least bridge between openings and to the sheet edge — reported, and fixed
// by dropping openings when the recipe asks. The sheet is cut into fabrication sheets.
#pragma once

#include <array>
#include <optional>
#include <vector>

#include "building/building.h"
#include "curdle/curd.h"
#include "kinds/surface_kind.h"
#include "layout/layout.h"

namespace curdle {

// The opening each curd makes in its cells.
struct HoleSpec {
  double diameter = 0;
  double offset_x = 0, offset_y = 0;  // from the cell centre, mm
};

enum class HoleFix {
  none,  // report violations of the fabrication rules, change nothing
  drop,  // drop holes that break a rule: too small, too near the edge, or the smaller of two
         // holes too close together
};

struct PerforationKeys : KindKeysOf<PerforationKeys> {
  std::vector<HoleSpec> holes;  // one per curd
  double thickness = 0;         // sheet thickness, mm
  double min_diameter = 0;      // smallest hole the tool cuts
  double min_bridge = 0;        // least material between two holes
  double edge_margin = 0;       // least material between a hole and the sheet edge
  HoleFix fix = HoleFix::none;
  double chord_tolerance = 0.05;                    // how far polygonised circles may stray, mm
  std::optional<std::array<double, 2>> sheet_size;  // fabrication sheets at most this size
  std::vector<double> punches;  // the tools' diameters: every opening is one of them; empty: any
  std::optional<std::array<double, 2>> open_area;  // [min, max] share each sheet must be open
  std::string sheet_material = "sheet metal";      // what the sheets are, for the order list
  // [layout.building]: the screen is a building's envelope (or a free-standing screen's path)
  // unrolled, its fabrication sheets cut within each façade and, on an arc, rolled to it.
  std::optional<BuildingKeys> building;
  std::optional<Envelope> envelope;
};

class PerforationKind : public SurfaceKind {
 public:
  std::string_view name() const override { return "perforation"; }
  std::string_view element_noun() const override { return "cell"; }
  std::string_view legend_unit() const override { return "opening"; }
  char id_letter() const override { return 'C'; }  // cells; their openings become "H-..."
  double thickness(const LayoutSpec& spec) const override;
  // A perforated screen stands: its sheet's y runs up in the model (+Y in glTF, z in IFC).
  bool upright() const override { return true; }
  const Envelope* envelope(const LayoutSpec& spec) const override;
  std::vector<std::string_view> own_outputs() const override { return {"punching.csv"}; }
  Finish finish() const override { return {0.9, 0.4}; }
  Ground ground() const override { return Ground::sheet; }
  Depiction depiction() const override { return Depiction::shapes; }
  bool laid_in_courses() const override { return false; }
  std::string size_line(const Layout& layout) const override;
  std::string laying_line(const Layout& layout) const override;
  std::unique_ptr<KindKeys> default_keys() const override;
  Layout build(const Design& design, const CurdField& field, const Box& view,
               const LayoutSpec& spec) const override;

 protected:
  reading::SurfaceKeys surface() const override { return {"cell", "sheet", true, false, false}; }
  bool laid_on_a_grid() const override { return false; }
  std::vector<std::string> own_keys() const override;
  void read_own(reading::TableReader& r, const Design& design, LayoutSpec& spec) const override;
  void replace_cells(Layout& layout, const Design& design, const LayoutSpec& spec) const override;
};

// Replaces the cells of `layout` (laid as elements on the sheet) by their openings.
void perforate(Layout& layout, const Design& design, const LayoutSpec& spec);

namespace reading {
// The kind's own keys: holes, thickness, fabrication rules, sheets, punches, open area.
void read_perforation(TableReader& r, const Design& design, LayoutSpec& spec);
// [layout.building] of a screen: its plan or path, height and arcs (building/building.h); the
// screen's size is the envelope's, its sheets cut within each façade.
void read_perforated_building(TableReader& r, LayoutSpec& spec);
}  // namespace reading

// The least material between two openings made of these circles (negative when they overlap).
double bridge(const std::vector<Circle>& a, const std::vector<Circle>& b);

}  // namespace curdle
