// The rhythm kind (a 1-D curd as architecture): a line of bays (fins, mullions, bays of a
// colonnade) whose element widths and colours follow the values.
#include "kinds/rhythm.h"

#include <fmt/format.h>

#include <cmath>

#include "curdle/overlay.h"
#include "curdle/stop.h"
#include "layout/builder.h"
#include "layout/drawing_sheet.h"
#include "recipe/layout_reader.h"

namespace curdle {

std::string RhythmKind::size_line(const Layout& layout) const {
  return fmt::format("{} x {} mm: {} bays of {} mm, {} fins", drawing_mm(layout.width),
                     drawing_mm(layout.height), layout.columns, drawing_mm(layout.module_w),
                     layout.elements.size());
}

std::vector<std::string> RhythmKind::keys() const {
  return {"sheet", "bay", "height", "length", "widths", "origin", "building"};
}

std::unique_ptr<KindKeys> RhythmKind::default_keys() const {
  return std::make_unique<RhythmKeys>();
}

CellPlacement RhythmKind::cell_placement(const LayoutSpec&, const Box&) const {
  return {};  // the bays take their widths from the values: cells are the line's units
}

namespace {

// [layout.building] of a line of fins: the line is the envelope unrolled, the fins its height.
void read_fins_round(reading::TableReader& r, Design& design, LayoutSpec& spec, bool field_given) {
  using namespace reading;
  for (const char* key : {"length", "height", "origin"})
    if (r.get(key))
      r.fail(key,
             "does not go with [layout.building]: the fins run along its plan or path from its "
             "start corner, as high as layout.building.height");
  const toml::table* building = r.get("building")->as_table();
  if (!building)
    r.fail("building", "must be a table: [layout.building] with plan (or path) and height");
  const toml::table& t = *building;
  for (const char* key : {"wall", "backing", "depth", "phase", "openings", "windows", "elevations",
                          "coursed_openings", "heights", "storeys"})
    if (const toml::node* n = t.get(key))
      r.fail_node(*n, r.key_path("building") + "." + key,
                  "is not a key of fins on a building: they take plan (or path, or site), "
                  "height, storey, base, start and arcs");
  // The fins are the building's height: one course of it.
  const auto height = t.get("height") ? finite_number(t.get("height")) : std::nullopt;
  if (height && *height >= 1 && *height <= 1e6) spec.module_h = *height;
  RhythmKeys& keys = spec.own<RhythmKeys>();
  // A fin on an arc stands square to it, a plate of its own: no joints to close behind it, as
  // there would be behind units bent to it (read so; stand_round stands them straight).
  ReadBuilding read = read_building(r, spec, true);
  keys.building = std::move(read.keys);
  keys.envelope = std::move(read.envelope);
  if (!keys.building->site_summary.empty()) spec.site_summary = keys.building->site_summary;
  spec.size = std::array<double, 2>{keys.envelope->length, keys.envelope->height};
  const auto bays = static_cast<int64_t>(std::ceil(keys.envelope->length / spec.module_w - 1e-9));
  if (field_given && design.field.size[0] < bays)
    r.fail("building", fmt::format("needs {} bays round the building but field.cells is {}; "
                                   "leave field.cells out, or make it at least that large",
                                   bays, design.field.size[0]));
  if (!field_given) design.field.size[0] = bays;
}

}  // namespace

void RhythmKind::read(reading::TableReader& r, Design& design, LayoutSpec& spec,
                      bool field_given) const {
  using namespace reading;
  const size_t values = size_t{1} << design.curds.size();
  read_value_colours(r, design, spec);
  read_drawing_scale(r, spec);
  spec.module_w = read_mm(r, "bay", 600, 1);
  spec.module_h = read_mm(r, "height", 3000, 1);
  const auto origin =
      read_string(r, "origin", "\"bottom-left\" or \"bottom-right\"").value_or("bottom-left");
  if (origin != "bottom-left" && origin != "bottom-right")
    r.fail("origin", "must be \"bottom-left\" or \"bottom-right\" for a line");
  spec.origin = origin == "bottom-left" ? Corner::bottom_left : Corner::bottom_right;

  const toml::node* n = r.get("widths");
  const toml::array* a = n ? n->as_array() : nullptr;
  if (!a || a->size() != values)
    r.fail("widths", "must give one element width in mm per value (" + std::to_string(values) +
                         "), value 0 first; 0 leaves a bay empty");
  for (size_t v = 0; v < a->size(); ++v) {
    const auto x = finite_number(a->get(v));
    if (!x || *x < 0 || *x > spec.module_w)
      r.fail_node(*a->get(v), "layout.widths." + std::to_string(v),
                  "must be a width from 0 to the bay (" +
                      std::to_string(static_cast<int>(spec.module_w)) + " mm)");
    spec.own<RhythmKeys>().widths.push_back(*x);
  }
  if (r.get("building")) {
    read_fins_round(r, design, spec, field_given);
    return;
  }
  if (r.get("length")) {
    const double length = read_mm(r, "length", 0, 1);
    spec.size = std::array<double, 2>{length, spec.module_h};
    const int64_t bays = static_cast<int64_t>(std::ceil(length / spec.module_w - 1e-9));
    // A larger field is a curd from which a segment of `bays` becomes the line.
    if (field_given && design.field.size[0] < bays)
      r.fail("length", "needs " + std::to_string(bays) + " bays but field.cells is " +
                           std::to_string(design.field.size[0]) +
                           "; leave field.cells out, or make it at least that large");
    if (!field_given) design.field.size[0] = bays;
  }
}

Layout RhythmKind::build(const Design& design, const CurdField& field, const Box& view,
                         const LayoutSpec& spec) const {
  Layout layout = lay_grid(design, field, view, spec, {});
  count_values(layout, design, spec);
  set_rhythm(layout, spec);
  if (const auto& envelope = spec.own<RhythmKeys>().envelope) stand_round(layout, *envelope);
  return layout;
}

void stand_round(Layout& layout, const Envelope& envelope) {
  EnvelopeFrames& frames = layout.envelope.emplace();
  frames.frames = envelope.facades;
  for (SurfaceFrame& f : frames.frames) f.bent = false;  // a fin is a straight plate
  frames.closed = envelope.closed;
  // A fin stands on one face: one whose bay would take it round a corner (or past a path's
  // end) is left out, and said.
  std::vector<Element> fins;
  size_t turning = 0;
  for (Element& e : layout.elements) {
    const Rect& r = e.shape.front();
    const SurfaceFrame* f = frame_at(layout.frames(), r.x + r.w / 2);
    if (!f || r.x < f->start - 1e-9 || r.right() > f->start + f->length + 1e-9) {
      ++turning;
      continue;
    }
    fins.push_back(std::move(e));
  }
  layout.elements = std::move(fins);
  if (envelope.closed)
    layout.notes.push_back(
        "round the plan the fins' field is laid from its start corner, its seam where the "
        "strip's end meets its start (layout.building.start moves it)");
  if (turning)
    layout.notes.push_back(
        fmt::format("{} {} at a corner (or past the end) left out: a fin stands on one face",
                    turning, turning == 1 ? "fin that would turn" : "fins that would turn"));
}

void set_rhythm(Layout& layout, const LayoutSpec& spec) {
  std::vector<Element> bays = std::move(layout.elements);
  layout.elements.clear();
  layout.element_type = "fin";
  for (LegendEntry& e : layout.legend) e.count = 0;
  for (Element& e : bays) {
    stop_point();
    const double w = spec.own<RhythmKeys>().widths[e.value];
    ++layout.legend[e.value].count;  // bays of each value, as the report counts cells
    if (w <= 0) continue;
    const Rect bay = e.nominal;
    e.shape = {Rect{bay.x + (bay.w - w) / 2, bay.y, w, bay.h}};
    e.stock_w = w, e.stock_h = bay.h;
    e.cut = false;
    e.key = e.key.as('R');
    e.id = e.key.text();
    layout.elements.push_back(std::move(e));
  }
}

const Envelope* RhythmKind::envelope(const LayoutSpec& spec) const {
  const std::optional<Envelope>& e = spec.own<RhythmKeys>().envelope;
  return e ? &*e : nullptr;
}

}  // namespace curdle
