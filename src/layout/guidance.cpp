#include "layout/guidance.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "layout/laying_pattern.h"

namespace curdle {

namespace {

// The first stage at which a cell can die: some curd's p below 1 there (or a density field,
// which can thin any stage); 0 when none can.
int first_dying_stage(const Design& design) {
  for (int k = 1; k <= design.lattice.stages; ++k)
    for (const CurdSpec& c : design.curds)
      if (c.density || (static_cast<size_t>(k) <= c.probabilities.size() &&
                        c.probabilities[static_cast<size_t>(k) - 1].value() < 1))
        return k;
  return 0;
}

}  // namespace

void advise_lattice(Layout& layout, const Design& design) {
  const Lattice& lattice = design.lattice;
  if (layout.kind->dimension() != 2 || lattice.stages < 1 || layout.module_w <= 0) return;
  const int stage = first_dying_stage(design);
  if (stage == 0) return;
  const auto [pitch_w, pitch_h] =
      pattern_cell_pitch(layout.pattern, layout.module_w, layout.module_h, layout.joint);
  const double shorter = std::min(layout.width, layout.height);
  const double room = shorter / 3;
  const auto side = static_cast<double>(lattice.side_in_cells(stage));
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
  const std::string which = stage == 1
                                ? "the first stage's"
                                : fmt::format("stage {}'s (the first where a cell can die)", stage);
  std::string note = fmt::format(
      "{} cells are {:.2f} x {:.2f} m ({} x {} elements), more than a third of the "
      "surface's shorter side ({:.2f} m): where one dies, a blank with straight edges crosses much "
      "of the surface",
      which, cell_w / 1000, cell_h / 1000, side, side, shorter / 1000);
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
