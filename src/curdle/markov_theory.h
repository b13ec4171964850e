// What a Markov curd (markov.h) should give, per stage and state, for a box of finest cells.
//
// Shares: s_k = start P_1 ... P_k, the chance that a stage-k cell is in each state (independent
// of b). Expected count of state j: C_k s_k[j], C_k the stage-k cells meeting the box.
// Variance (a multitype branching process, Harris 1963 ch. 2): two distinct cells are
// correlated through their deepest common ancestor; with Q_(m,k) = P_(m+1) ... P_k and
// T_m the box's sum of squares (theory.h),
//   Var N_k[j] = C_k s_k[j] (1 - s_k[j]) + sum_(m<k) (T_m - T_(m+1)) (c_m - s_k[j]^2),
//   c_m = sum_i s_m[i] sum_(x,y) pair_(m+1)[i](x, y) Q_(m+1,k)[x][j] Q_(m+1,k)[y][j],
// pair[i](x, y) the chance that two given siblings of a state-i cell take states x and y:
// P[i][x] P[i][y] canonical; n_x (n_y - [x = y]) / (B (B - 1)) exact (n = P[i] B, dealt
// without replacement). Roots draw their states independently.
// Extinction and box counts: e_m(i; A), the chance that a stage-m cell in state i leaves no
// finest cell in the states A inside the view, from e_K(i) = [i not in A] and
//   e_m(i) = prod over the children inside of sum_t P_(m+1)[i][t] e_(m+1)(child, t)
// (canonical; exact mode's whole cells: prod_t e_(m+1)(t)^(n_t); its cells the view cuts: the same
// deal, child by child over the states still to deal, as the plain curd's hypergeometric sum).
// Expected box count of A at level m: sum over the stage-m cells meeting the view of sum_i s_m[i]
// (1 - e_m(i)). Dimension, for a stationary P: the set of a state j is fed by the states that can
// reach it, R_j (dead too, with wheys); D_j = log rho(B P restricted to R_j) / log b, rho the
// spectral radius, where rho > 1 (else the set dies out). The living set: the states that can reach
// a living one.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "curdle/box.h"
#include "curdle/lattice.h"
#include "curdle/markov.h"

namespace curdle {

// Per state 0..S, the SD of the count of stage-k cells in that state meeting `box`.
std::vector<double> state_count_sd(const Lattice& lattice, const MarkovChain& chain, int stage,
                                   const Box& box);

// The chance that a root leaves no finest cell in a state of `targets` (a flag per state 0..S),
// as the start row draws it; the whole root, at this K.
double extinction_chance(const Lattice& lattice, const MarkovChain& chain,
                         const std::vector<bool>& targets);

// Levels 0..K: the expected number of stage-m cells meeting `view` that hold a finest cell of
// a state in `targets` inside it.
std::vector<double> expected_state_box_counts(const Lattice& lattice, const MarkovChain& chain,
                                              const std::vector<bool>& targets, const Box& view);

// D_j above for the states in `targets`; nullopt when P changes with the stage or the set
// dies out (rho <= 1).
std::optional<double> stationary_dimension(const Lattice& lattice, const MarkovChain& chain,
                                           const std::vector<bool>& targets);

}  // namespace curdle
