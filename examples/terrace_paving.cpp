// A 6 x 4 m terrace of 400 x 400 mm slabs with 8 mm joints in two colours, drawn as SVG:
// the library without the command line, and without a recipe file.
#include <cstdio>
#include <fstream>

#include "curdle/curdling.h"
#include "export/svg.h"
#include "kinds/registry.h"
#include "layout/builder.h"

int main() {
  curdle::Design design;
  design.name = "terrace";
  design.lattice = {4, 2, 3, curdle::Mode::canonical};
  curdle::CurdSpec dark;
  dark.name = "dark";
  for (const char* p : {"3/4", "1/2", "1/2"})
    dark.probabilities.push_back(*curdle::Probability::parse(p));
  design.curds.push_back(dark);

  curdle::LayoutSpec spec;
  spec.set_kind(curdle::layout_kind("paving"));
  spec.module_w = spec.module_h = 400;
  spec.joint = 8;
  spec.size = std::array<double, 2>{6000, 4000};
  const auto cells = curdle::elements_to_cover(spec);  // 15 x 10 slabs, the last cut
  design.field.size = {cells[0], cells[1], 1};

  const curdle::CurdField field = curdle::curdle(design, 11, design.field);
  const curdle::Layout layout = curdle::make_layout(design, field, design.field, spec);
  std::ofstream svg("terrace.svg");
  curdle::write_layout_svg(svg, layout);

  size_t cut = 0;
  for (const auto& e : layout.elements) cut += e.cut;
  std::printf("terrace: %zu slabs, %zu cut, %llu dark, joints %.2f m2\n", layout.elements.size(),
              cut, static_cast<unsigned long long>(layout.legend[1].count),
              curdle::joint_area(layout) / 1e6);
  return svg ? 0 : 1;
}
