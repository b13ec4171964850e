#include "export/title_block.h"

#include <fmt/format.h>

namespace curdle {
namespace {

std::string mm(double v) { return drawing_mm(v); }

std::string sheet_line(const Layout& layout) {
  const LayoutSpec& spec = layout.spec;
  if (layout.kind != LayoutKind::perforation) {
    const std::string corner = layout.origin == Corner::bottom_left    ? "bottom-left"
                               : layout.origin == Corner::bottom_right ? "bottom-right"
                               : layout.origin == Corner::top_left     ? "top-left"
                                                                       : "top-right";
    const std::string bond = spec.bond == 0.5    ? "; half bond"
                             : spec.bond == 0.25 ? "; quarter bond"
                             : spec.bond > 0     ? "; third bond"
                                                 : "";
    return (spec.centred ? "grid centred, laid from the " + corner + " corner"
                         : "origin " + corner) +
           bond + "; element IDs count rows and columns from it";
  }
  return fmt::format(
      "sheet {} mm thick, {} openings, open area {:.2f} %, {} rule violations{}",
      mm(spec.perforation().thickness), layout.elements.size(), 100 * layout.open_area,
      layout.violations.size(),
      spec.perforation().fix == HoleFix::drop && !layout.violations.empty() ? " (dropped)" : "");
}

}  // namespace

std::string drawing_mm(double v) {
  std::string s = fmt::format("{:.3f}", v);
  while (s.back() == '0') s.pop_back();
  if (s.back() == '.') s.pop_back();
  return s == "-0" ? "0" : s;
}

std::vector<std::string> title_lines(const Layout& layout) {
  const double W = layout.width, H = layout.height;
  std::string probabilities;
  for (const CurdSpec& c : layout.source.curds) {
    std::string p;
    for (const Probability& q : c.probabilities) p += (p.empty() ? "" : ", ") + q.text();
    probabilities += (probabilities.empty() ? "" : "; ") + c.name + " " + p;
    if (c.density) probabilities += " x " + describe(*c.density);
  }
  uint64_t cut_count = 0;
  for (const Element& e : layout.elements) cut_count += e.cut;
  return {layout.source.recipe +
              (layout.source.description.empty() ? "" : " - " + layout.source.description),
          fmt::format("seed {} - base {}, {}-D, {} stages, {} mode", layout.source.seed,
                      layout.source.lattice.base, layout.source.lattice.dimension,
                      layout.source.lattice.stages, to_string(layout.source.lattice.mode)),
          "probabilities: " + probabilities,
          layout.kind == LayoutKind::perforation
              ? fmt::format("{} x {} mm sheet: {} x {} cells of {} x {} mm", mm(W), mm(H),
                            layout.columns, layout.rows, mm(layout.module_w), mm(layout.module_h))
          : layout.kind == LayoutKind::rhythm
              ? fmt::format("{} x {} mm: {} bays of {} mm, {} fins", mm(W), mm(H), layout.columns,
                            mm(layout.module_w), layout.elements.size())
          : layout.kind == LayoutKind::blocks
              ? fmt::format("{} x {} x {} voxels of {} x {} x {} mm (w x d x h), {} blocks",
                            layout.view.size[0], layout.view.size[1], layout.view.size[2],
                            mm(layout.module_w), mm(layout.module_h),
                            mm(layout.spec.blocks().voxel_h), layout.elements.size())
          : layout.kind == LayoutKind::park
              ? fmt::format("{} x {} mm: {} x {} cells of {} x {} mm, {} elements", mm(W), mm(H),
                            layout.columns, layout.rows, mm(layout.module_w), mm(layout.module_h),
                            layout.elements.size())
              : fmt::format("{} x {} mm: {} {}s of {} x {} mm, joint {} mm ({} cut)", mm(W), mm(H),
                            layout.elements.size(), layout.element_type, mm(layout.module_w),
                            mm(layout.module_h), mm(layout.joint), cut_count),
          sheet_line(layout),
          "curdle - random curds (Mandelbrot; Cirovic 2014) - units mm"};
}

std::string legend_unit(const Layout& layout) {
  return layout.kind == LayoutKind::perforation || layout.kind == LayoutKind::park ? "cell"
         : layout.kind == LayoutKind::rhythm                                       ? "bay"
         : layout.kind == LayoutKind::blocks                                       ? "voxel"
                                             : layout.element_type;
}

std::string legend_count(const Layout& layout, uint64_t count) {
  return fmt::format("{} {}{}", count, legend_unit(layout), count == 1 ? "" : "s");
}

}  // namespace curdle
