#include "layout/title_block.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <iterator>

#include "curdle/markov.h"

namespace curdle {

std::string segment_text(const Layout& layout) {
  const Box& v = layout.view;
  const Box& f = layout.source.field;
  const int e = layout.source.lattice.dimension;
  if (v == f || f.cells() <= 1) return "";
  // fmt rather than chains of string +, on which GCC 12 warns falsely (-Wrestrict).
  std::string at, size, whole;
  for (int d = 0; d < e; ++d) {
    const auto i = static_cast<size_t>(d);
    fmt::format_to(std::back_inserter(at), "{}{}", d ? "," : "", v.origin[i]);
    fmt::format_to(std::back_inserter(size), "{}{}", d ? "," : "", v.size[i]);
    fmt::format_to(std::back_inserter(whole), "{}{}", d ? " x " : "", f.size[i]);
  }
  return fmt::format("window {},{} of the {} field", at, size, whole);
}

std::string site_point_text(const SiteFrame& f, double x_mm, double y_mm) {
  auto grouped = [&](double v) {
    std::string t = fmt::format("{:.{}f}", std::fabs(v), std::clamp(f.precision, 0, 8));
    const size_t dot = std::min(t.find('.'), t.size());
    for (size_t i = dot; i > 3; i -= 3) t.insert(i - 3, ",");
    return (v < 0 ? "-" : "") + t;
  };
  return fmt::format("E {} N {} {} in {}", grouped(f.datum[0] + x_mm / f.unit_mm),
                     grouped(f.datum[1] + y_mm / f.unit_mm), f.unit_name, f.file);
}

namespace {

// "datum (0, 0) = E 530,000.000 N 180,000.000 m in site.dxf".
std::string datum_line(const SiteFrame& f) { return "datum (0, 0) = " + site_point_text(f, 0, 0); }

}  // namespace

std::vector<std::string> title_lines(const Layout& layout) {
  std::string probabilities;
  for (const CurdSpec& c : layout.source.curds) {
    if (c.chain) {
      // A Markov curd once, by its states: its matrices are too many for a title block.
      if (c.plane != 0) continue;
      std::string states;
      for (const std::string& s : c.chain->states) states += (states.empty() ? "" : ", ") + s;
      probabilities += (probabilities.empty() ? "" : "; ") + c.name + " Markov (" + states +
                       (c.chain->stationary() ? "; one matrix" : "; a matrix per stage") + ")";
      continue;
    }
    std::string p;
    for (const Probability& q : c.probabilities) p += (p.empty() ? "" : ", ") + q.text();
    probabilities += (probabilities.empty() ? "" : "; ") + c.name + " " + p;
    if (c.density) probabilities += " x " + describe(*c.density);
  }
  const std::string segment = segment_text(layout);
  std::vector<std::string> lines = {
      layout.source.recipe +
          (layout.source.description.empty() ? "" : " - " + layout.source.description),
      fmt::format("seed {}{} - base {}, {}-D, {} stages, {} mode", layout.source.seed,
                  segment.empty() ? "" : ", " + segment, layout.source.lattice.base,
                  layout.source.lattice.dimension, layout.source.lattice.stages,
                  to_string(layout.source.lattice.mode)),
      "probabilities: " + probabilities,
      layout.kind->size_line(layout),
      layout.kind->laying_line(layout),
      "curdle - random curds (Mandelbrot; Cirovic 2014) - units mm"};
  // The datum in the site drawing's own coordinates: what a surveyor sets out from.
  if (layout.site_frame) lines.insert(lines.end() - 1, datum_line(*layout.site_frame));
  return lines;
}

std::string legend_unit(const Layout& layout) {
  const std::string_view unit = layout.kind->legend_unit();
  return unit.empty() ? layout.element_type : std::string(unit);
}

std::string legend_count(const Layout& layout, uint64_t count) {
  return fmt::format("{} {}{}", count, legend_unit(layout), count == 1 ? "" : "s");
}

}  // namespace curdle
