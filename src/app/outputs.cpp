#include "app/outputs.h"

#include <algorithm>
#include <filesystem>
#include <sstream>

#include "app/generated_run.h"
#include "curdle/error.h"
#include "export/drawing/cairo_on_demand.h"
#include "export/drawing/drawing_set.h"
#include "export/drawing/install.h"
#include "export/drawing/layout_png.h"
#include "export/drawing/svg.h"
#include "export/dxf/cutting.h"
#include "export/dxf/layout_dxf.h"
#include "export/gis/gpkg.h"
#include "export/gltf/gltf.h"
#include "export/ifc/ifc.h"
#include "export/report/cells_csv.h"
#include "export/report/preview_png.h"
#include "export/report/report_json.h"
#include "export/report/report_table.h"
#include "export/schedules/park_schedules.h"
#include "export/schedules/punching.h"
#include "export/schedules/schedule.h"
#include "kinds/registry.h"

namespace fs = std::filesystem;

namespace curdle::app {
namespace {

// Runs a step with progress shown, when there is an observer.
template <class F>
auto with_progress(RunObserver* observer, const std::string& what, F&& step) {
  std::unique_ptr<ProgressTask> task = observer ? observer->begin(what) : nullptr;
  return step([&](double f) {
    if (task) task->update(f);
  });
}

uint64_t view_cells(const Run& run) { return run.view.cells(); }

// Rough bytes an element costs in each writer's structures, measured: layout.glb keeps its nodes
// as JSON text (export/gltf/gltf_json.h) and adds 0.52 GB to a million tiles' run for a 262 MB
// file.
constexpr uint64_t kGltfBytesPerElement = 800;
// layout.gpkg holds every feature (its attributes as text, its rings in metres) before GDAL
// writes it: 1.2 KB an element measured (4,489 to 40,000 pavers), with room.
constexpr uint64_t kGpkgBytesPerElement = 1536;
constexpr uint64_t kLayoutPngBytesPerPixel = 15;

void write_report(const OutputContext& c, OutputSink& sink) {
  sink.write("report.json", [&](std::ostream& o) {
    const auto j = c.layout ? report_to_json(c.report, *c.layout) : report_to_json(c.report);
    o << j.dump(2) << "\n";
  });
}

void write_cells(const OutputContext& c, OutputSink& sink) {
  with_progress(c.observer, "writing cells.csv", [&](const auto& progress) {
    sink.write("cells.csv", [&](std::ostream& o) {
      write_cells_csv(o, c.run.recipe.design, c.field, c.run.view, progress);
    });
  });
}

void write_preview(const OutputContext& c, OutputSink& sink) {
  const PreviewImage image = with_progress(c.observer, "drawing preview.png", [&](const auto& p) {
    return render_preview(c.run.recipe.design, c.field, c.run.view, p);
  });
  const std::string png = encode_png(image);
  sink.write("preview.png", [&](std::ostream& o) { o << png; });
}

void write_layout_svg_output(const OutputContext& c, OutputSink& sink) {
  sink.write("layout.svg", [&](std::ostream& o) { write_layout_svg(o, *c.layout); });
}

void write_layout_png(const OutputContext& c, OutputSink& sink) {
  const std::string png = layout_sheet_png(*c.layout, c.installer_plan());
  sink.write("layout.png", [&](std::ostream& o) { o << png; });
}

void write_layout_pdf_output(const OutputContext& c, OutputSink& sink) {
  sink.write("layout.pdf",
             [&](std::ostream& o) { write_layout_pdf(o, *c.layout, c.installer_plan()); });
}

void write_layout_glb(const OutputContext& c, OutputSink& sink) {
  sink.write("layout.glb", [&](std::ostream& o) { write_glb(o, *c.layout); });
}

void write_layout_gltf(const OutputContext& c, OutputSink& sink) {
  std::ostringstream bin;
  sink.write("layout.gltf", [&](std::ostream& o) { write_gltf(o, bin, "layout.bin", *c.layout); });
  sink.write("layout.bin", [&](std::ostream& o) { o << bin.str(); });
}

void write_layout_ifc_output(const OutputContext& c, OutputSink& sink) {
  sink.write("layout.ifc", [&](std::ostream& o) { write_layout_ifc(o, *c.layout); });
}

void write_schedule(const OutputContext& c, OutputSink& sink) {
  sink.write("schedule.csv", [&](std::ostream& o) { write_schedule_csv(o, *c.layout); });
}

void write_quantities(const OutputContext& c, OutputSink& sink) {
  sink.write("quantities.csv", [&](std::ostream& o) { write_quantities_csv(o, *c.layout); });
}

void write_layout_dxf_output(const OutputContext& c, OutputSink& sink) {
  sink.write_via_file("layout.dxf",
                      [&](const fs::path& path) { write_layout_dxf(path, *c.layout, false); });
}

void write_layout_site_dxf_output(const OutputContext& c, OutputSink& sink) {
  sink.write_via_file("layout-site.dxf",
                      [&](const fs::path& path) { write_layout_dxf(path, *c.layout, true); });
}

void write_layout_gpkg_output(const OutputContext& c, OutputSink& sink) {
  sink.write_via_file("layout.gpkg",
                      [&](const fs::path& path) { write_layout_gpkg(path, *c.layout); });
}

void write_lots(const OutputContext& c, OutputSink& sink) {
  sink.write("lots.csv", [&](std::ostream& o) { write_lots_csv(o, *c.layout); });
}

void write_install(const OutputContext& c, OutputSink& sink) {
  sink.write("install.svg",
             [&](std::ostream& o) { write_install_svg(o, *c.layout, c.installer_plan()); });
}

void write_planting(const OutputContext& c, OutputSink& sink) {
  sink.write("planting.csv", [&](std::ostream& o) { write_planting_csv(o, *c.layout); });
}

void write_furniture(const OutputContext& c, OutputSink& sink) {
  sink.write("furniture.csv", [&](std::ostream& o) { write_furniture_csv(o, *c.layout); });
}

void write_surfaces(const OutputContext& c, OutputSink& sink) {
  sink.write("surfaces.csv", [&](std::ostream& o) { write_surfaces_csv(o, *c.layout); });
}

void write_punching(const OutputContext& c, OutputSink& sink) {
  sink.write("punching.csv", [&](std::ostream& o) { write_punching_csv(o, *c.layout); });
}

void write_sheets(const OutputContext& c, OutputSink& sink) {
  const Layout& layout = *c.layout;
  for (size_t i = 0; i < layout.sheets().size(); ++i) {
    const std::string id = layout.sheets()[i].id;
    const int sheet = static_cast<int>(i);
    sink.write_via_file("sheets/" + id + ".dxf",
                        [&](const fs::path& path) { write_sheet_dxf(path, layout, sheet); });
    sink.write("sheets/" + id + ".svg",
               [&](std::ostream& o) { write_sheet_svg(o, layout, sheet); });
  }
}

// Outputs of one kind of layout: a park's schedules, a perforation's order list.
template <class Add>
void add_kind_outputs(Add& add) {
  add({.name = "planting.csv",
       .description = "parks: every tree and shrub, its plant, centre to set out from, canopy "
                      "and zone",
       .needs_layout = true,
       .kind_owned = true,
       .write = write_planting});
  add({.name = "furniture.csv",
       .description = "parks: every bench and other standing object, its centre, size and zone",
       .needs_layout = true,
       .kind_owned = true,
       .write = write_furniture});
  add({.name = "surfaces.csv",
       .description = "parks: the ground and surfaces as areas per material and zone",
       .needs_layout = true,
       .kind_owned = true,
       .write = write_surfaces});
  add({.name = "punching.csv",
       .description = "perforations: the order list, per fabrication sheet its stock, material, "
                      "offcut, open share and the hits of each punch, and their total",
       .needs_layout = true,
       .kind_owned = true,
       .write = write_punching});
}

// Outputs of a surface read from a DXF: the layout laid back onto that drawing.
template <class Add>
void add_site_outputs(Add& add) {
  add({.name = "layout-site.dxf",
       .description = "layout.dxf in the site drawing's own coordinates and units, to attach "
                      "as an XREF at (0, 0, 0), scale 1 (a surface read from a DXF)",
       .needs_layout = true,
       .for_site_drawing = true,
       .skip_above = 2'000'000,
       .size_unit = "elements",
       .size = view_cells,
       .write = write_layout_site_dxf_output});
}

std::vector<Output> make_registry() {
  std::vector<Output> r;
  auto add = [&](Output o) { r.push_back(std::move(o)); };
  add({.name = "report.json",
       .description = "per-stage report: survivors, expectations, box counts and dimensions",
       .write = write_report});
  add({.name = "cells.csv",
       .description = "one row per cell: its value and a 0/1 column per curd",
       .skip_above = 10'000'000,
       .size_unit = "cells",
       .size = view_cells,
       .write = write_cells});
  add({.name = "preview.png",
       .description = "the curds' values as a picture, a colour per value",
       .memory = [](const Run& run) { return preview_memory(run.recipe.design, run.view); },
       .write = write_preview});
  add({.name = "layout.svg",
       .description = "the layout in true millimetres, with legend and title block",
       .needs_layout = true,
       .write = write_layout_svg_output});
  add({.name = "layout.png",
       .description = "sheet 1 of layout.pdf as a picture: the layout at a standard scale on its "
                      "ISO sheet, with legend, scale bar and title block",
       .needs_layout = true,
       .installed = cairo_installed,
       .memory =
           [](const Run& run) {
             // Selected only with a [layout], so the recipe has one.
             // The layout's own picture, and the sheet it is put on (cairo's 4 bytes a pixel,
             // then 3 for the PNG's rows).
             return layout_png_pixels(*run.recipe.layout, run.view) * kLayoutPngBytesPerPixel +
                    layout_sheet_pixels(*run.recipe.layout) * 8;
           },
       .write = write_layout_png});
  add({.name = "layout.pdf",
       .description = "the drawing set on ISO sheets: the whole layout, then the installer's "
                      "sheets where every ID reads",
       .needs_layout = true,
       .skip_above = 250'000,
       .size_unit = "elements",
       .size = view_cells,
       .installed = cairo_installed,
       .write = write_layout_pdf_output});
  add({.name = "layout.glb",
       .description = "the layout as a glTF 2.0 scene in metres",
       .needs_layout = true,
       .memory = [](const Run& run) { return run.view.cells() * kGltfBytesPerElement; },
       .write = write_layout_glb});
  add({.name = "layout.ifc",
       .description = "the layout as an IFC4 model in millimetres: an element per piece with "
                      "its ID, value, material, properties and quantities",
       .needs_layout = true,
       .skip_above = 100'000,
       .size_unit = "elements",
       .size = view_cells,
       .write = write_layout_ifc_output});
  add({.name = "layout.gltf",
       .description = "the same as glTF JSON with layout.bin beside it",
       .needs_layout = true,
       .by_default = false,
       .download = false,
       .memory = [](const Run& run) { return run.view.cells() * kGltfBytesPerElement * 2; },
       .write = write_layout_gltf});
  add({.name = "schedule.csv",
       .description = "one row per element: ID, lot, position, size, value, material",
       .needs_layout = true,
       .skip_above = 2'000'000,
       .size_unit = "elements",
       .size = view_cells,
       .write = write_schedule});
  add({.name = "layout.dxf",
       .description = "the pieces as laid for CAD: AutoCAD 2007 DXF in millimetres, a layer "
                      "per material, IDs on a layer that does not plot",
       .needs_layout = true,
       .skip_above = 2'000'000,
       .size_unit = "elements",
       .size = view_cells,
       .write = write_layout_dxf_output});
  add_site_outputs(add);
  add({.name = "layout.gpkg",
       .description = "the pieces as a GeoPackage for QGIS: a feature per piece with its "
                      "schedule attributes, a layer per kind, in layout.georef's CRS",
       .needs_layout = true,
       .skip_above = 2'000'000,
       .size_unit = "elements",
       .size = view_cells,
       .installed = gpkg_installed,
       .memory = [](const Run& run) { return run.view.cells() * kGpkgBytesPerElement; },
       .write = write_layout_gpkg_output});
  add({.name = "quantities.csv",
       .description =
           "per element type, material and size: whole and cut, laid area, stock to buy, packs",
       .needs_layout = true,
       .write = write_quantities});
  add({.name = "lots.csv",
       .description = "the quantities per lot, fabrication sheet or level, in laying order",
       .needs_layout = true,
       .write = write_lots});
  add({.name = "install.svg",
       .description = "the installer's map: every element's ID and the laying order",
       .needs_layout = true,
       .skip_above = 250'000,
       .size_unit = "elements",
       .size = view_cells,
       .write = write_install});
  add_kind_outputs(add);
  add({.name = "sheets",
       .description = "perforated sheets: a DXF and an SVG per fabrication sheet, in sheets/",
       .needs_layout = true,
       .download = false,
       .write = write_sheets});
  return r;
}

std::string known_outputs() {
  std::string names;
  for (const Output& o : output_registry())
    names += (names.empty() ? "" : ", ") + o.name + (o.needs_layout ? " (needs a [layout])" : "");
  return names;
}

}  // namespace

const std::vector<Output>& output_registry() {
  static const std::vector<Output> registry = make_registry();
  return registry;
}

bool is_output_name(const std::string& name, bool folder) {
  if (folder) return name == "sheets";
  if (name == "layout.bin") return true;
  for (const Output& o : output_registry())
    if (o.name == name && o.name != "sheets") return true;
  return false;
}

std::string owner_of(const Output& o) {
  for (const LayoutKind* k : layout_kinds())
    if (k->owns_output(o.name)) return std::string(k->name());
  return "";
}

void check_output_applies(const Output& o, const Run& run) {
  if (o.needs_layout && !run.recipe.layout)
    throw InputError(SourceLocation{run.recipe_path, 0, 0, "layout", ""},
                     o.name + " needs a [layout] section in the recipe (see patterns/README.md)");
  if (o.for_site_drawing && !run.recipe.layout->site_frame)
    throw InputError(SourceLocation{run.recipe_path, 0, 0, "layout.site", ""},
                     o.name +
                         " is the layout in its site drawing's own coordinates and units, "
                         "written where [layout.site] reads the surface from a DXF; this "
                         "recipe's surface is not read from one");
  if (!output_applies(o, run))
    throw InputError(SourceLocation{run.recipe_path, 0, 0, "layout.kind", ""},
                     o.name + " is written for layouts of kind \"" + owner_of(o) +
                         "\"; this recipe's is \"" + std::string(run.recipe.layout->kind->name()) +
                         "\"");
}

bool output_applies(const Output& o, const Run& run) {
  if (o.needs_layout && !run.recipe.layout) return false;
  if (o.for_site_drawing && !(run.recipe.layout && run.recipe.layout->site_frame)) return false;
  return !o.kind_owned || (run.recipe.layout && run.recipe.layout->kind->owns_output(o.name));
}

const Output* find_output(const std::string& name) {
  for (const Output& o : output_registry())
    if (o.name == name || o.name.substr(0, o.name.find('.')) == name) return &o;
  return nullptr;
}

std::vector<const Output*> select_outputs(const Run& run, const std::vector<std::string>& named,
                                          RunObserver* observer) {
  std::vector<const Output*> chosen;
  if (!named.empty()) {
    for (const std::string& name : named) {
      const Output* o = find_output(name);
      if (!o)
        throw InputError(parameter("outputs"),
                         "unknown output '" + name + "'; allowed: " + known_outputs());
      check_output_applies(*o, run);
      if (std::string why; o->installed && !o->installed(&why))
        throw InputError(parameter("outputs"), o->name + " cannot be written here: " + why);
      if (std::find(chosen.begin(), chosen.end(), o) == chosen.end()) chosen.push_back(o);
    }
    return chosen;
  }
  for (const Output& o : output_registry()) {
    if (!o.by_default || !output_applies(o, run)) continue;
    if (std::string why; o.installed && !o.installed(&why)) {
      if (observer) observer->not_installed(o.name, why);
      continue;
    }
    if (o.skip_above && o.size(run) > o.skip_above) {
      if (observer) observer->skipped(o.name, o.size(run), o.size_unit, o.skip_above);
      continue;
    }
    chosen.push_back(&o);
  }
  return chosen;
}

bool builds_layout(const Run& run, const std::vector<const Output*>& outputs) {
  if (!run.recipe.layout) return false;
  return std::any_of(outputs.begin(), outputs.end(),
                     [](const Output* o) { return o->needs_layout || o->name == "report.json"; });
}

uint64_t estimate_run_memory(const Run& run, const std::vector<const Output*>& outputs) {
  return estimate_run_memory(run, outputs, builds_layout(run, outputs));
}

uint64_t estimate_run_memory(const Run& run, const std::vector<const Output*>& outputs,
                             bool with_layout) {
  const Design& d = run.recipe.design;
  uint64_t need = estimate_memory(d, generation_box(d, run.view));
  for (const Output* o : outputs)
    if (o->memory) need += o->memory(run);
  // An element with its ID and shape is about 256 bytes.
  if (with_layout && run.recipe.layout) need += run.view.cells() * 256;
  return need;
}

void check_run_memory(const Run& run, const std::vector<const Output*>& outputs) {
  check_run_memory(run, outputs, builds_layout(run, outputs));
}

void check_run_memory(const Run& run, const std::vector<const Output*>& outputs, bool with_layout) {
  const uint64_t need = estimate_run_memory(run, outputs, with_layout);
  if (need > run.generate.max_memory_bytes)
    throw ResourceLimitError(
        "the curds and their outputs need about " + std::to_string(need >> 20) +
        " MiB, above the memory limit of " + std::to_string(run.generate.max_memory_bytes >> 20) +
        " MiB; use a smaller field or window" +
        (run.generate.memory_limit_hint.empty() ? "" : ", or " + run.generate.memory_limit_hint));
}

RunSummary write_outputs(const Run& run, const std::vector<const Output*>& outputs,
                         OutputSink& sink, int threads, RunObserver* observer) {
  check_run_memory(run, outputs);
  const GeneratedRun generated = generate_run(run, builds_layout(run, outputs), threads, observer);
  write_generated(generated, outputs, sink, observer, threads);
  RunSummary summary{.report = generated.report};
  if (generated.layout) {
    const bool sheets = std::any_of(outputs.begin(), outputs.end(),
                                    [](const Output* o) { return o->name == "sheets"; });
    summary.layout = summarize_layout(*generated.layout, sheets);
  }
  return summary;
}

std::string report_table(const Run& run, const CurdField& field) {
  return format_report_table(make_report(run.recipe.design, run.seed, field, run.view));
}

}  // namespace curdle::app
