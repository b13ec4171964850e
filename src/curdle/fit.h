// Fitting a recipe to a measured design: each curd's per-stage probabilities from the occupied
// cells of every stage, so that curdling with them gives designs with the same statistics.
//
// N_k, the stage-k cells of the lattice (cells of side b^(K-k), from the lattice corner) that
// hold a cell of the curd, is exactly the box count the report gives, and its expectation at K
// stages with extinction is extinction.h's. The fit finds p_1..p_K whose expected counts equal
// the measured ones: it starts from the ratios N_k / (N_(k-1) C_k / C_(k-1)) (C_k the stage-k
// cells meeting the field) and corrects each p_k by how far the expectations of stages k and
// k - 1 miss, until they agree. The standard deviation of each p_k is the binomial one of the
// ratio, sqrt(p (1 - p) / n) with n = N_(k-1) C_k / C_(k-1) candidates.
#pragma once

#include <cstdint>
#include <vector>

#include "curdle/box.h"
#include "curdle/lattice.h"
#include "curdle/probability.h"

namespace curdle {

// N_k, k = 0..K, of a curd given as its finest cells over `field` (x fastest, then y, then z;
// field.origin is ignored: the field starts at the lattice corner).
std::vector<uint64_t> occupied_cells(const Lattice& lattice, const Box& field,
                                     const std::vector<bool>& cells);

struct StageFit {
  int stage = 0;
  double probability = 0;
  double sd = 0;          // of the probability
  uint64_t measured = 0;  // N_k
  double expected = 0;    // its expectation with the fitted probabilities
};

// The probabilities whose expected counts match `measured` (N_0..N_K) over `field`.
std::vector<StageFit> fit_probabilities(const Lattice& lattice, const Box& field,
                                        const std::vector<uint64_t>& measured);

}  // namespace curdle
