// Fitting a recipe to a measured design: each curd's per-stage probabilities from how its
// occupied cells branch from stage to stage, with intervals, and a test of whether a curd
// explains the design at all.
//
// N_k, the stage-k cells (side b^(K-k), aligned to the lattice origin) that hold a cell of the
// curd, is the box count the report gives. In a curd the occupied children of an occupied
// stage-(k-1) cell are independent: a child survives with p_k and then keeps a final survivor
// inside the view with q (extinction.h; less for children the view cuts), and the parent is
// occupied because at least one child is. So the counts form a chain, and each stage's
// likelihood given the stage before has p_k as its only unknown once the later stages are fitted:
// p_k is fitted from stage K down, as the maximum of that likelihood. Its 95 % interval is where
// the likelihood ratio stays inside the chi-square point, or, for a stage of at most 100 children
// in view, whose count is too coarse for that, the split count's interval (fit.cpp); both include
// the conditioning on survival and extinction and are never of zero width. The fit matches each
// stage's count given the stage before, not the expected counts from the roots: those are given
// beside the measured ones with a standardised difference.
//
// The test: the number of occupied children of each occupied cell, stage by stage, against the
// distribution the fitted curd gives (Pearson's chi-square, bins merged to at least 1 expected).
// A gradient, a disk, stripes or a checkerboard branch far too evenly or too unevenly for any
// curd.
#pragma once

#include <cstdint>
#include <vector>

#include "curdle/box.h"
#include "curdle/lattice.h"

namespace curdle {

// N_k, k = 0..K, of a curd given as its finest cells over `view` (x fastest, then y, then z;
// cells in lattice coordinates from view.origin, boxes aligned to the lattice origin).
std::vector<uint64_t> occupied_cells(const Lattice& lattice, const Box& view,
                                     const std::vector<bool>& cells);

struct StageFit {
  int stage = 0;
  double probability = 0;
  double low = 0, high = 1;  // 95 % interval of the probability
  uint64_t measured = 0;     // N_k
  uint64_t parents = 0;      // N_(k-1), the occupied cells whose children are counted
  // E[N_k] and its standard deviation from the N_0 occupied roots with the fitted
  // probabilities, and (measured - expected) / sd.
  double expected = 0, expected_sd = 0, z = 0;
  // Occupied children per occupied parent against the fitted curd: Pearson's statistic, its
  // degrees of freedom (0: too few cells to test) and the chance of one as large; dispersion
  // says which way they differ: -1 more evenly than a curd branches, +1 more unevenly.
  double chi_square = 0;
  int degrees = 0;
  double p_value = 1;
  int dispersion = 0;
};

struct CurdFit {
  std::vector<StageFit> stages;  // 1..K
  double chi_square = 0;         // summed over the stages
  int degrees = 0;
  double p_value = 1;
};

// The probabilities of the curd whose finest cells are `cells` over `view`, with the test.
CurdFit fit_curd(const Lattice& lattice, const Box& view, const std::vector<bool>& cells);

}  // namespace curdle
