#include "layout/guidance.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace curdle {

void advise_lattice(Layout& layout, const Lattice& lattice) {
  if (layout.kind->dimension() != 2 || lattice.stages < 1 || layout.module_w <= 0) return;
  const double pitch_w = layout.module_w + layout.joint, pitch_h = layout.module_h + layout.joint;
  const double shorter = std::min(layout.width, layout.height);
  const double room = shorter / 3;
  const auto side = static_cast<double>(lattice.side_in_cells(1));
  const double cell_w = side * pitch_w, cell_h = side * pitch_h;
  if (std::max(cell_w, cell_h) <= room || shorter <= 0) return;
  // Per base, the most stages whose first-stage cells (b^(K-1) elements) still fit.
  std::vector<std::string> fits;
  const double largest = room / std::max(pitch_w, pitch_h);  // elements a first-stage cell may span
  for (int b = 2; b <= 5; ++b) {
    int stages = 1;
    while (std::pow(b, stages) <= largest + 1e-9) ++stages;
    if (stages >= 2) fits.push_back(fmt::format("base {} and at most {} stages", b, stages));
  }
  std::string note = fmt::format(
      "the first stage's cells are {:.2f} x {:.2f} m ({} x {} elements), more than a third of the "
      "surface's shorter side ({:.2f} m): where one dies, a blank with straight edges crosses much "
      "of the surface",
      cell_w / 1000, cell_h / 1000, side, side, shorter / 1000);
  if (fits.empty()) {
    note +=
        "; no base of two or more stages has first-stage cells that small here: use smaller "
        "elements or a larger surface";
  } else {
    note += "; first-stage cells fit with ";
    for (size_t i = 0; i < fits.size(); ++i)
      note += (i == 0 ? "" : i + 1 == fits.size() ? " or " : ", ") + fits[i];
  }
  layout.notes.push_back(note);
}

}  // namespace curdle
