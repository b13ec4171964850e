// Density fields ([curds.density]): a curd that thickens or thins across the surface.
//
// A field g >= 0 is given in the recipe's units (mm on a layout, cells otherwise) and read at
// each cell's place. A cell C of the finest stage K survives with probability exactly
//     min(1, P_K * g(centre of C)),          P_K = p_1 ... p_K,
// realised stage by stage so that the curd keeps its clustering: with
//     S_0(C) = 1,   S_k(C) = min(1, P_k * max of g over C) for 0 < k < K,
//     S_K(C) = min(1, P_K * g(centre of C)),
// the stage-k child C of a survivor A survives with q_k(C) = S_k(C) / S_(k-1)(A). A cell's
// region lies inside its parent's, so S_k(C) <= S_(k-1)(A) and q_k <= 1, and the chain of
// survivals telescopes: P(C alive at stage k) = S_k(C). With g = 1 everywhere, q_k = p_k, the
// plain curd. Survival draws are the plain curd's (random_stream.h, kinds 0 and 1), compared
// with each child's own threshold.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "curdle/box.h"
#include "curdle/lattice.h"
#include "curdle/probability.h"

namespace curdle {

// Where the lattice's cells lie in the field's units: finest cell coordinate u (continuous,
// cell i spans [i, i + 1)) lies at origin + scale * u along each axis; a bond moves each
// course (row y) along x by course_shift[(row_sign * y + row_base) mod size].
struct CellPlacement {
  std::array<double, 3> origin{0, 0, 0};
  std::array<double, 3> scale{1, 1, 1};
  std::vector<double> course_shift;  // empty: no bond
  int64_t row_sign = 1, row_base = 0;
  // Round a closed building the field is a ring: x taken round modulo `period` (0: no ring).
  double period = 0;

  double shift_of_row(int64_t y) const;
  // The centre of a finest cell (absolute coordinates) in the field's units.
  std::array<double, 3> centre(const std::array<int64_t, 3>& cell, int dimension) const;
  // The extent of the shifts (both 0 without a bond), to widen a region spanning many rows.
  std::array<double, 2> shift_range() const;
};

enum class DensityKind { linear, radial, image };

struct DensityField {
  DensityKind kind = DensityKind::linear;
  std::array<double, 2> values{1, 1};  // at from / to, at the centre / the radius, black / white
  // linear: g runs from values[0] at `from` to values[1] at `to` along the line between them,
  // and stays at the end values beyond.
  std::array<double, 3> from{0, 0, 0}, to{0, 0, 0};
  // radial: values[0] at `centre`, changing linearly with distance to values[1] at `radius`,
  // and values[1] beyond.
  std::array<double, 3> centre{0, 0, 0};
  double radius = 0;
  // image: a greyscale picture over `rect` ([x, y, w, h], top row at y + h); its luminance l
  // gives values[0] + (values[1] - values[0]) * l; beyond the picture, its nearest edge pixel.
  std::string path;  // as the recipe wrote it, relative to the recipe; read by the application
  std::array<double, 4> rect{0, 0, 0, 0};
  int width = 0, height = 0;
  std::shared_ptr<const std::vector<float>> luminance;  // row-major, top row first
  bool rect_given = false;

  CellPlacement placement;
  int dimension = 2;

  // g at a point in the field's units.
  double at(const std::array<double, 3>& point) const;
  // The largest g over the closed box [lo, hi] in the field's units.
  double most_in(const std::array<double, 3>& lo, const std::array<double, 3>& hi) const;

  // g at the centre of a finest cell (absolute finest coordinates).
  double at_cell(const std::array<int64_t, 3>& cell) const;
  // S_k above for the stage-k cell at `cell` (absolute coordinates in stage-k cells), given
  // P_k = survival (the product of the first k probabilities).
  double survival(const Lattice& lattice, int stage, const std::array<int64_t, 3>& cell,
                  double survival_product) const;
};

// One line for reports and title blocks: "radial: 2.7 at [12000, 12000] to 0.15 at 12000".
std::string describe(const DensityField& field);

// The 64-bit survival threshold of a probability q in [0, 1]: survive when the draw is below it;
// `certain` when q >= 1.
struct Threshold {
  uint64_t value = 0;
  bool certain = false;
};
Threshold threshold_of(double q);

}  // namespace curdle
