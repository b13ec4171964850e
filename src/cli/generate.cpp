#include "cli/generate.h"

#include <cstdarg>
#include <fstream>
#include <memory>
#include <set>

#include "cli/progress.h"
#include "curdle/error.h"
#include "curdle/report.h"
#include "export/atomic_file.h"
#include "export/cells_csv.h"
#include "export/cutting.h"
#include "export/gltf.h"
#include "export/install.h"
#include "export/layout_png.h"
#include "export/mask_image.h"
#include "export/preview_png.h"
#include "export/report_json.h"
#include "export/schedule.h"
#include "export/svg.h"
#include "layout/builder.h"

namespace fs = std::filesystem;

namespace curdle::cli {
namespace {

void say(FILE* log, const char* format, ...) __attribute__((format(printf, 2, 3)));
void say(FILE* log, const char* format, ...) {
  if (!log) return;
  va_list args;
  va_start(args, format);
  std::vfprintf(log, format, args);
  va_end(args);
}

constexpr uint64_t kCellsCsvDefaultLimit = 10'000'000;
const std::vector<std::string> kOutputs = {
    "report.json", "cells.csv",    "preview.png",    "layout.svg",  "layout.png", "layout.glb",
    "layout.gltf", "schedule.csv", "quantities.csv", "install.svg", "sheets"};

std::set<std::string> parse_outputs(const std::vector<std::string>& names) {
  std::set<std::string> chosen;
  for (std::string n : names) {
    if (n.find('.') == std::string::npos)
      for (const auto& o : kOutputs)
        if (o.rfind(n + ".", 0) == 0) n = o;
    if (std::find(kOutputs.begin(), kOutputs.end(), n) == kOutputs.end())
      throw InputError(
          SourceLocation{"--outputs", 0, 0, ""},
          "unknown output '" + n +
              "'; allowed: report.json, cells.csv, preview.png, and with a [layout] "
              "section layout.svg, layout.png, layout.glb, layout.gltf (with layout.bin), "
              "schedule.csv, quantities.csv");
    chosen.insert(n);
  }
  return chosen;
}

}  // namespace

std::vector<fs::path> write_outputs(Session& s, const fs::path& dir,
                                    const std::vector<std::string>& outputs_named, int threads,
                                    FILE* log) {
  std::set<std::string> outputs = outputs_named.empty()
                                      ? std::set<std::string>(kOutputs.begin(), kOutputs.end())
                                      : parse_outputs(outputs_named);
  if (outputs_named.empty()) outputs.erase("layout.gltf");  // .glb by default; .gltf on request
  const bool has_layout = s.recipe.layout.has_value();
  if (!has_layout) {
    for (const char* name : {"layout.svg", "layout.png", "layout.glb", "layout.gltf",
                             "schedule.csv", "quantities.csv", "install.svg", "sheets"})
      if (outputs.erase(name) && !outputs_named.empty())
        throw InputError(
            SourceLocation{s.recipe_path, 0, 0, "layout"},
            std::string(name) + " needs a [layout] section in the recipe (see patterns/README.md)");
  } else if (!s.recipe.layout->mask.empty()) {
    LayoutSpec& spec = *s.recipe.layout;
    const fs::path mask = fs::path(s.recipe_path).parent_path() / spec.mask;
    for (const Rect& r :
         read_mask_openings(mask, (*spec.size)[0], (*spec.size)[1],
                            SourceLocation{s.recipe_path, 0, 0, "layout.mask"}))
      spec.openings.push_back(r);
  }
  const bool csv_named = outputs_named.size() && outputs.count("cells.csv");
  if (outputs.count("cells.csv") && !csv_named && s.view.cells() > kCellsCsvDefaultLimit) {
    outputs.erase("cells.csv");
    if (log) std::fprintf(stderr,
                 "note: cells.csv skipped: %llu cells is above %llu; name it with --outputs "
                 "cells.csv to write it anyway\n",
                 static_cast<unsigned long long>(s.view.cells()),
                 static_cast<unsigned long long>(kCellsCsvDefaultLimit));
  }
  {
    // Everything this run will hold at once, checked before anything is allocated.
    uint64_t need = estimate_memory(s.recipe.design, generation_box(s.recipe.design, s.view));
    if (outputs.count("preview.png")) need += preview_memory(s.recipe.design, s.view);
    if (has_layout) {
      // An element with its ID and shape is about 256 bytes; the drawing is 15 bytes a pixel.
      need += s.view.cells() * 256;
      if (outputs.count("layout.png")) need += layout_png_pixels(*s.recipe.layout, s.view) * 15;
      // glTF: the model, its buffer and the written copy, about 700 bytes an element.
      if (outputs.count("layout.glb") || outputs.count("layout.gltf")) need += s.view.cells() * 700;
    }
    if (need > s.generate.max_memory_bytes)
      throw InputError(
          SourceLocation{s.recipe_path, 0, 0, ""},
          "the curds and their outputs need about " + std::to_string(need >> 20) +
              " MiB, above the memory limit of " +
              std::to_string(s.generate.max_memory_bytes >> 20) +
              " MiB; use a smaller field or window, or raise the limit with --max-memory");
  }
  make_output_dir(dir);

  const CurdField field = run_engine(s, threads, log != nullptr);
  const Report report = make_report(s.recipe.design, s.seed, field, s.view);

  // Everything is written under temporary names first and renamed only when all succeeded,
  // so a failed run leaves no new or half-written output.
  std::vector<std::unique_ptr<StagedFile>> staged;
  auto stage = [&](const std::string& name) -> StagedFile& {
    staged.push_back(std::make_unique<StagedFile>(dir / name));
    return *staged.back();
  };
  if (outputs.count("cells.csv")) {
    Progress progress("writing cells.csv", log != nullptr);
    stage("cells.csv").write([&](std::ostream& o) {
      write_cells_csv(o, s.recipe.design, field, s.view, [&](double f) { progress.update(f); });
    });
  }
  if (outputs.count("preview.png")) {
    Progress progress("drawing preview.png", log != nullptr);
    write_png(
        stage("preview.png").temporary(),
        render_preview(s.recipe.design, field, s.view, [&](double f) { progress.update(f); }));
  }
  nlohmann::ordered_json layout_summary;  // what report.json says of the layout
  if (has_layout) {
    const LayoutSpec& spec = *s.recipe.layout;
    const Layout layout = make_layout(s.recipe.design, field, s.view, spec);
    if (outputs.count("layout.svg"))
      stage("layout.svg").write([&](std::ostream& o) {
        write_layout_svg(o, layout, s.recipe.design,
                         TitleBlock{s.recipe.design.name, s.recipe.description, s.seed}, spec);
      });
    if (outputs.count("layout.png"))
      write_png_at(stage("layout.png").temporary(), render_layout(layout, spec), spec.dpi);
    const TitleBlock title{s.recipe.design.name, s.recipe.description, s.seed};
    if (outputs.count("schedule.csv"))
      stage("schedule.csv").write([&](std::ostream& o) {
        write_schedule_csv(o, layout, s.recipe.design, spec);
      });
    if (!layout.sheets.empty() && outputs.count("sheets")) {
      make_output_dir(dir / "sheets");
      for (size_t i = 0; i < layout.sheets.size(); ++i) {
        const std::string id = layout.sheets[i].id;
        write_sheet_dxf(stage("sheets/" + id + ".dxf").temporary(), layout, static_cast<int>(i));
        stage("sheets/" + id + ".svg").write([&](std::ostream& o) {
          write_sheet_svg(o, layout, static_cast<int>(i));
        });
      }
      say(log, "sheets: %zu, each as DXF and SVG in sheets/\n", layout.sheets.size());
    }
    if (outputs.count("install.svg"))
      stage("install.svg").write([&](std::ostream& o) { write_install_svg(o, layout, title); });
    if (outputs.count("quantities.csv"))
      stage("quantities.csv").write([&](std::ostream& o) {
        write_quantities_csv(o, layout, spec);
      });
    if (outputs.count("layout.glb"))
      stage("layout.glb").write([&](std::ostream& o) {
        write_glb(o, layout, s.recipe.design, title, spec);
      });
    if (outputs.count("layout.gltf")) {
      StagedFile& bin = stage("layout.bin");
      std::ofstream bin_out(bin.temporary(), std::ios::binary | std::ios::trunc);
      stage("layout.gltf").write([&](std::ostream& o) {
        write_gltf(o, bin_out, "layout.bin", layout, s.recipe.design, title, spec);
      });
      bin_out.flush();
      if (!bin_out) throw InputError("cannot write " + bin.target().string());
    }
    uint64_t cut = 0;
    for (const Element& e : layout.elements) cut += e.cut;
    say(log, 
        "layout: %zu %ss (%llu cut, %llu over openings), %.0f x %.0f mm; layout.png at 1:%g, %g "
        "dpi\n",
        layout.elements.size(), layout.element_type.c_str(), static_cast<unsigned long long>(cut),
        static_cast<unsigned long long>(layout.omitted), layout.width, layout.height,
        drawing_scale(layout, spec), spec.dpi);
    for (const std::string& note : layout.notes) say(log, "  note: %s\n", note.c_str());
    for (size_t i = 0; i < layout.violations.size() && i < 20; ++i)
      say(log, "  rule: %s\n", layout.violations[i].c_str());
    if (layout.violations.size() > 20)
      say(log, "  rule: ... %zu more in report.json\n", layout.violations.size() - 20);
    layout_summary = {{"element_type", layout.element_type},
                      {"width_mm", layout.width},
                      {"height_mm", layout.height},
                      {"elements", layout.elements.size()},
                      {"cut", cut},
                      {"omitted_over_openings", layout.omitted},
                      {"open_area", layout.open_area},
                      {"notes", layout.notes},
                      {"rule_violations", layout.violations}};
  }
  if (outputs.count("report.json"))
    stage("report.json").write([&](std::ostream& o) {
      auto j = report_to_json(report);
      if (!layout_summary.is_null()) j["layout"] = layout_summary;
      o << j.dump(2) << "\n";
    });
  for (auto& f : staged) f->check_replaceable();
  for (auto& f : staged) f->commit();

  say(log, "%s, seed %llu: %llu cells\n", s.recipe.design.name.c_str(),
              static_cast<unsigned long long>(s.seed),
              static_cast<unsigned long long>(report.cells));
  for (const CurdReport& c : report.curds)
    say(log, 
        "  curd %-12s %llu survivors (expected %.1f), box dimension %s (theory %s)\n",
        c.name.c_str(), static_cast<unsigned long long>(c.stages.back().survivors),
        c.stages.back().expected, c.fit ? std::to_string(c.fit->slope).substr(0, 5).c_str() : "-",
        c.theory_dimension ? std::to_string(*c.theory_dimension).substr(0, 5).c_str() : "-");
  say(log, "outputs in %s:\n", fs::absolute(dir).lexically_normal().c_str());
  for (const auto& f : staged) say(log, "  %s\n", f->target().filename().c_str());
  std::vector<fs::path> written;
  for (const auto& f : staged) written.push_back(f->target());
  return written;
}


}  // namespace curdle::cli
