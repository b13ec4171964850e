// The façade kind: windows and doors as rectangles in millimetres, or a mask image, cut out of
// the wall's grid; its open share reported. With [layout.building] the wall is a building's
// envelope unrolled (src/building), laid in courses round its corners instead of on the grid.
#include "kinds/facade.h"

#include <fmt/format.h>

#include <cmath>

#include "building/coursing.h"
#include "building/envelope_layout.h"
#include "curdle/overlay.h"
#include "layout/builder.h"
#include "layout/cut_rules.h"

namespace curdle {

std::unique_ptr<KindKeys> FacadeKind::default_keys() const {
  return std::make_unique<FacadeKeys>();
}

bool FacadeKind::take_opening(LayoutSpec& spec, const std::array<double, 4>& r) const {
  spec.own<FacadeKeys>().openings.push_back(Rect{r[0], r[1], r[2], r[3]});
  return true;
}

std::vector<Rect> FacadeKind::openings(const LayoutSpec& spec) const {
  return spec.own<FacadeKeys>().openings;
}

void FacadeKind::after_laying(Layout& layout, const LayoutSpec& spec) const {
  // The façade's own openings come first in layout.openings, as far as they lie on the wall.
  size_t on_wall = 0;
  for (const Rect& o : spec.own<FacadeKeys>().openings)
    on_wall += clip(o, layout.width, layout.height).area() > 0;
  report_open_area(layout, on_wall);
}

double FacadeKind::thickness(const LayoutSpec& spec) const {
  const FacadeKeys& keys = spec.own<FacadeKeys>();
  if (!keys.envelope) return 20;
  return keys.envelope->solid ? spec.module_w : keys.envelope->depth;  // one brick, or a leaf
}

namespace {

// Round a closed envelope the field is a ring of whole root cells, turned to keep the corners
// off the coarse stages' boundaries (strip_ring.h); a field the recipe sizes itself is laid as
// given, its closing seam where the strip's ends meet.
void wrap_round(reading::TableReader& r, Design& design, LayoutSpec& spec, bool field_given) {
  FacadeKeys& keys = spec.own<FacadeKeys>();
  if (!keys.envelope || !keys.envelope->closed) return;
  const Envelope& env = *keys.envelope;
  if (field_given) {
    if (keys.building->phase)
      r.fail("building.phase",
             "turns the field round the building, which curdle sizes itself: leave field.cells "
             "out, or choose the segment with field.window");
    return;
  }
  const auto root = static_cast<int64_t>(design.lattice.root_side());
  const double pitch = spec.module_w + spec.joint;
  StripRing ring = ring_round(env.length, pitch, root);
  // A root cell much longer than the strip would make the ring's cells far smaller than the
  // units, and the curd's clusters with them: laid a cell a unit instead, with its seam.
  if (ring.cell < 0.75 * pitch || ring.cell > 1.5 * pitch) {
    if (keys.building->phase)
      r.fail("building.phase",
             fmt::format("turns the field round the building, but a root cell of {} cells is too "
                         "long for a ring of {:.0f} units: the strip is laid from its start",
                         root, env.length / pitch));
    return;
  }
  if (keys.building->phase && *keys.building->phase >= ring.columns)
    r.fail("building.phase", fmt::format("must be a field column round the building, from 0 to {}",
                                         ring.columns - 1));
  std::vector<double> corners{0};  // the closing corner, where the strip begins
  for (const SurfaceFrame& f : env.facades) corners.push_back(f.start + f.length);
  turn_ring(ring, corners, design.lattice.base, design.lattice.stages, keys.building->phase);
  design.field.size[0] = ring.columns;
  keys.ring = ring;
}

}  // namespace

CellPlacement FacadeKind::cell_placement(const LayoutSpec& spec, const Box& view) const {
  CellPlacement p = SurfaceKind::cell_placement(spec, view);
  const FacadeKeys& keys = spec.own<FacadeKeys>();
  if (!keys.ring || !keys.envelope) return p;
  const StripRing& ring = *keys.ring;
  p.scale[0] = ring.cell;
  p.origin[0] = -static_cast<double>(ring.phase + view.origin[0]) * ring.cell;
  p.period = static_cast<double>(ring.columns) * ring.cell;
  p.course_shift.clear();  // a unit takes the ring cell under its middle, bond and all
  return p;
}

std::optional<std::array<int64_t, 2>> FacadeKind::own_cells(const LayoutSpec& spec) const {
  const FacadeKeys& keys = spec.own<FacadeKeys>();
  if (!keys.ring || !keys.envelope) return std::nullopt;
  return std::array<int64_t, 2>{keys.ring->columns, keys.envelope->courses};
}

void FacadeKind::read(reading::TableReader& r, Design& design, LayoutSpec& spec,
                      bool field_given) const {
  SurfaceKind::read(r, design, spec, field_given);
  FacadeKeys& keys = spec.own<FacadeKeys>();
  if (!keys.building) return;
  if (spec.origin != Corner::bottom_left)
    r.fail("origin",
           "a building's strip starts at its start corner, bottom left: give "
           "layout.building.start instead");
  if (!r.get("bond"))
    keys.bond = CourseBond::stretcher;
  else if (!spec.header_bond.empty())
    keys.bond = spec.header_bond == "english" ? CourseBond::english : CourseBond::flemish;
  else if (spec.bond == 0)
    keys.bond = CourseBond::stack;
  else
    keys.bond = spec.bond == 0.5  ? CourseBond::stretcher
                : spec.bond < 0.3 ? CourseBond::quarter
                                  : CourseBond::third;
  // A queen closer is half a header less half a joint: a header no wider than a few joints
  // leaves none to cut.
  if ((keys.bond == CourseBond::english || keys.bond == CourseBond::flemish) && keys.envelope) {
    const double queen = queen_closer(keys.envelope->depth, spec.joint);
    if (queen < 20)
      r.fail(
          "bond",
          fmt::format("\"{}\" bond needs a queen closer, half a header less half a joint: "
                      "{:g} mm with units {:g} mm deep and {:g} mm joints; it needs units at "
                      "least {:g} mm deep (layout.building.depth)",
                      spec.header_bond, queen, keys.envelope->depth, spec.joint, 40 + spec.joint));
  }
  wrap_round(r, design, spec, field_given);
  // The storeys mark the coursed sheets' levels and the model's building storeys.
  if (spec.drawing.storey == 0 && spec.drawing.storeys.empty()) {
    spec.drawing.storey = keys.building->storey;
    spec.drawing.storeys = keys.building->storeys;
  }
}

Layout FacadeKind::build(const Design& design, const CurdField& field, const Box& view,
                         const LayoutSpec& spec) const {
  const FacadeKeys& keys = spec.own<FacadeKeys>();
  if (!keys.envelope) return SurfaceKind::build(design, field, view, spec);
  const Envelope& env = *keys.envelope;
  Layout layout = lay_surface(view, spec, env.openings);
  lay_envelope(layout, env, course_envelope(env, spec, keys.bond), values_in(field, view), spec,
               keys.ring);
  if (keys.ring) {
    layout.notes.push_back(ring_note(*keys.ring, spec.module_w + spec.joint,
                                     static_cast<int64_t>(design.lattice.root_side()),
                                     keys.building->phase.has_value()));
  }
  report_open_area(layout, layout.openings_given);
  count_values(layout, design, spec);
  const std::vector<std::string> grid = corner_grid_notes(layout, design, keys.ring);
  layout.notes.insert(layout.notes.end(), grid.begin(), grid.end());
  return layout;
}

void FacadeKind::read_own(reading::TableReader& r, const Design&, LayoutSpec& spec) const {
  using namespace reading;
  if (r.get("building")) {
    for (const char* key :
         {"wall", "openings", "mask", "outline", "site", "zones", "pattern", "shift"})
      if (r.get(key))
        r.fail(key,
               "does not go with [layout.building]: the wall is the building's envelope, "
               "its openings are [[layout.building.openings]]");
    FacadeKeys& keys = spec.own<FacadeKeys>();
    ReadBuilding read = read_building(r, spec);
    keys.building = std::move(read.keys);
    keys.envelope = std::move(read.envelope);
    if (!keys.building->site_summary.empty()) spec.site_summary = keys.building->site_summary;
    spec.size = std::array<double, 2>{keys.envelope->length, keys.envelope->height};
    return;
  }
  if (const toml::node* n = r.get("openings")) {
    const toml::array* a = n->as_array();
    if (!a) r.fail("openings", "must be an array of [x, y, width, height] in millimetres");
    for (size_t i = 0; i < a->size(); ++i) {
      const toml::array* o = a->get(i)->as_array();
      const std::string path = "layout.openings." + std::to_string(i);
      std::array<double, 4> v{};
      bool ok = o && o->size() == 4;
      for (size_t k = 0; ok && k < 4; ++k) {
        const auto x = finite_number(o->get(k));
        ok = x && std::isfinite(*x) && (k < 2 ? *x >= 0 : *x > 0);
        if (ok) v[k] = *x;
      }
      if (!ok)
        r.fail_node(*a->get(i), path,
                    "must be [x, y, width, height] in millimetres from the wall's bottom-left "
                    "corner, sizes above 0");
      const Rect rect{v[0], v[1], v[2], v[3]};
      if (rect.right() > (*spec.size)[0] + 1e-6 || rect.top() > (*spec.size)[1] + 1e-6)
        r.fail_node(*a->get(i), path,
                    "lies outside the wall of " +
                        std::to_string(static_cast<int>((*spec.size)[0])) + " x " +
                        std::to_string(static_cast<int>((*spec.size)[1])) + " mm");
      spec.own<FacadeKeys>().openings.push_back(rect);
    }
  }
  spec.own<FacadeKeys>().mask = read_string(r, "mask", "the path of an image").value_or("");
}

const Envelope* FacadeKind::envelope(const LayoutSpec& spec) const {
  const std::optional<Envelope>& e = spec.own<FacadeKeys>().envelope;
  return e ? &*e : nullptr;
}

}  // namespace curdle
