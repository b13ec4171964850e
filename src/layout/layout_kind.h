// A layout kind (tile, paving, façade, perforated sheet, park, rhythm, blocks, or one a library
// user adds): one unit that owns its recipe keys and their reader, its builder, and the facts
// the exporters need of it. Exporters ask the kind, or read the built elements; they never
// name a kind. The built-in kinds live in src/kinds/, one file pair each, registered in one
// table (kinds/registry.h), as outputs are (app/outputs.h).
#pragma once

#include <algorithm>
#include <array>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "curdle/curd.h"
#include "curdle/density.h"

namespace curdle {

struct Layout;
struct LayoutSpec;
namespace reading {
class TableReader;
}

// What a kind alone takes beyond the keys every kind has; each kind derives its own record.
struct KindKeys {
  virtual ~KindKeys() = default;
  virtual std::unique_ptr<KindKeys> clone() const = 0;
};
// The clone every record needs, written once.
template <class Self>
struct KindKeysOf : KindKeys {
  std::unique_ptr<KindKeys> clone() const override {
    return std::make_unique<Self>(static_cast<const Self&>(*this));
  }
};

// What shows between and behind the elements on a drawing.
enum class Ground {
  joints,  // the joint colour (or, with no joints, the most common value's: no seams show)
  sheet,   // the elements are openings in a sheet of metal
  paper,   // lines, objects and blocks stand on white
};

// How a drawing shows the elements.
enum class Depiction {
  grid,     // modules on a grid, neighbours of one value merged into larger shapes
  shapes,   // each element its own shape (openings, fins)
  objects,  // surfaces and objects, each in its own colour (parks)
  views,    // a plan and an elevation of voxels (blocks)
};

// The finish of the kind's material in 3-D (glTF's metallic-roughness).
struct Finish {
  double metallic = 0, roughness = 0.8;
};

struct Envelope;  // building/building.h: a plan unrolled into façades

class LayoutKind {
 public:
  virtual ~LayoutKind() = default;

  // What it is called: `layout.kind` in recipes, and the class of layout.svg's layout group.
  virtual std::string_view name() const = 0;
  // One element as the drawings name it: "tile", "paving tile", "panel", "cell", "bay".
  virtual std::string_view element_noun() const = 0;
  // What a legend counts: the cells of a sheet or park, the bays of a line, the voxels of a
  // stack; empty: the elements as laid (Layout::element_type).
  virtual std::string_view legend_unit() const { return {}; }
  // The first letter of its elements' IDs.
  virtual char id_letter() const { return 'E'; }
  // The lattice dimension it lays out: 1 a line, 2 a surface, 3 voxels.
  virtual int dimension() const { return 2; }

  // In 3-D: how thick what is laid stands (mm), whether it stands upright (a wall), whether it
  // lies in a bed that shows in the joints, and its finish.
  virtual double thickness(const LayoutSpec& spec) const = 0;
  virtual bool upright() const { return false; }
  virtual bool bedded() const { return false; }
  virtual Finish finish() const { return {}; }
  // On a building: whether what is laid stands off the wall's face by its thickness (fins),
  // rather than in the wall behind it (bricks, panels, sheets).
  virtual bool stands_off() const { return false; }
  // Whether its pieces are known to be outside (IFC's IsExternal): what stands upright (a
  // façade, a screen, fins), a paving and a park are; a tile floor or blocks may be either.
  virtual bool outdoors() const { return upright(); }
  // The building it was laid round ([layout.building]: the envelope unrolled into its strip);
  // null where it was laid on a surface of its own.
  virtual const Envelope* envelope(const LayoutSpec&) const { return nullptr; }
  // The outputs only this kind writes (a park's schedules, a perforation's order list), by
  // their names in the outputs' registry.
  virtual std::vector<std::string_view> own_outputs() const { return {}; }
  bool owns_output(std::string_view output) const {
    const std::vector<std::string_view> own = own_outputs();
    return std::find(own.begin(), own.end(), output) != own.end();
  }

  // On drawings: what shows behind the elements, how they are drawn, whether they are laid in
  // numbered rows and columns from a start corner, and the title block's line on its size.
  virtual Ground ground() const { return Ground::joints; }
  virtual Depiction depiction() const { return Depiction::grid; }
  virtual bool laid_in_courses() const { return true; }
  virtual bool laid_from_corner() const { return true; }  // the start corner is drawn
  // The title block's lines on the surface and its elements, and on how it is laid.
  virtual std::string size_line(const Layout& layout) const;
  virtual std::string laying_line(const Layout& layout) const;

  // The [layout] keys it takes beyond those every kind takes (kind, colours, materials, scale,
  // dpi, paper, spare, pack, lot_size, lot_rows), in the order messages list them.
  virtual std::vector<std::string> keys() const = 0;
  // Its own keys' record, at their defaults (none for a kind with no keys of its own).
  virtual std::unique_ptr<KindKeys> default_keys() const { return nullptr; }
  // Reads the [layout] keys it takes into `spec` (whose kind and keys are already this kind's);
  // a fixed surface sizes design.field when `field_given` is false, and must fit in it when
  // true. Keys present that it does not read are refused after it returns.
  virtual void read(reading::TableReader& r, Design& design, LayoutSpec& spec,
                    bool field_given) const = 0;
  // The layout of `view`, a segment of the field exactly as large as the surface needs.
  virtual Layout build(const Design& design, const CurdField& field, const Box& view,
                       const LayoutSpec& spec) const = 0;

  // The field cells the surface takes where the kind sizes its field itself (the ring round a
  // building, building/strip_ring.h); absent: a cell a unit (builder.h's elements_to_cover).
  virtual std::optional<std::array<int64_t, 2>> own_cells(const LayoutSpec&) const {
    return std::nullopt;
  }
  // Where it lays each lattice cell, for density fields in millimetres (curdle/density.h).
  virtual CellPlacement cell_placement(const LayoutSpec& spec, const Box& view) const;
  // The drawing's extent in mm before anything is laid, for size checks (layout.png's pixels).
  virtual std::array<double, 2> drawing_extent(const LayoutSpec& spec, const Box& view) const;
  // Whether zones and search targets in millimetres apply: a surface laid on a grid.
  virtual bool takes_zones() const { return false; }
  // Takes a rectangular opening read from a drawing (layout.site) as its own, as a façade takes
  // a window, and says so; one it does not take becomes an excluded zone.
  virtual bool take_opening(LayoutSpec&, const std::array<double, 4>& /*x, y, w, h*/) const {
    return false;
  }
};

}  // namespace curdle
