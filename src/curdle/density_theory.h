// What a curd with a density field (density.h) should give on average over a view.
//
// A stage-k cell C is alive with probability S_k(C), so the expected survivors are the sum of
// S_k over the stage-k cells meeting the view. Two cells whose deepest common ancestor A is at
// stage j < k are alive together with probability S_k(C) S_k(C') / S_j(A) (below A their
// branches draw independently), so
//   Var N_k = sum_C S_k(C) (1 - S_k(C))
//           + sum_(j<k) sum_A (1 / S_j(A) - 1) (T_k(A)^2 - sum_(a child of A) T_k(a)^2),
// T_k(A) being the sum of S_k over A's stage-k cells in the view. A cell keeps a final
// survivor in the view with probability S_j(A) h(A), h(A) = 1 - prod_a (1 - S(a)/S(A) h(a))
// over its children in the view, h = 1 at the finest stage: the expected box counts.
// One walk down the tree of cells meeting the view gives all three.
#pragma once

#include <vector>

#include "curdle/box.h"
#include "curdle/density.h"
#include "curdle/lattice.h"
#include "curdle/probability.h"

namespace curdle {

struct DensityExpectation {
  std::vector<double> survivors;     // stage 0..K
  std::vector<double> survivors_sd;  // stage 0..K
  std::vector<double> box_counts;    // level 0..K
};

DensityExpectation expect_with_density(const Lattice& lattice, const std::vector<Probability>& p,
                                       const DensityField& field, const Box& view);

}  // namespace curdle
