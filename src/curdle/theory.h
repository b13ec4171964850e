// What curdling should give on average, for a box of finest cells seen at stage k.
//
// Expected survivors: C_k * P_k, where C_k counts the stage-k cells meeting the box and
// P_k = p_1 ... p_k (linearity; for one whole root, b^(E k) P_k).
// Variance: survivors of two cells are correlated through their deepest common ancestor.
// With T_j = sum over stage-j ancestors of (their stage-k cells in the box)^2, r_i the chance
// that two given siblings both survive stage i (p_i^2 canonical; p_i (p_i B - 1)/(B - 1)
// exact, sampling without replacement) and Q = p_(j+2) ... p_k:
//   Var N_k = C_k P_k (1 - P_k) + sum_{j<k} (T_j - T_(j+1)) (P_j r_(j+1) Q^2 - P_k^2).
// For one whole root and constant p this is the Galton-Watson result
// sigma^2 m^(k-1) (m^k - 1)/(m - 1), m = p b^E, sigma^2 = b^E p (1 - p) (Harris 1963).
// Dimension: D = E + log p / log b (Mandelbrot 1982, p. 213).
#pragma once

#include <cstdint>
#include <vector>

#include "curdle/box.h"
#include "curdle/lattice.h"
#include "curdle/probability.h"

namespace curdle {

// Stage-k cells of `lattice` that meet `box`.
uint64_t cells_meeting(const Lattice& lattice, int stage, const Box& box);

// T_j above: the sum over the stage-j cells of (their stage-k cells meeting `box`)^2.
double sum_of_squares(const Lattice& lattice, int k, int j, const Box& box);

double survival_probability(const std::vector<Probability>& p, int stage);  // P_k

double expected_survivors(const Lattice& lattice, const std::vector<Probability>& p, int stage,
                          const Box& box);

// Standard deviation of the survivors of stage k in `box`, for canonical and exact modes.
double survivors_sd(const Lattice& lattice, const std::vector<Probability>& p, int stage,
                    const Box& box);

// E + log p / log b; -infinity for p = 0.
double theory_dimension(const Lattice& lattice, double p);

}  // namespace curdle
