// Markov curds: L. Petrusevski and I. Cirovic, "A Modification of the Random Curds Model by
// Markov Chain as a Design Tool in Architecture", Tehnicki vjesnik 25(1), 2018, 195-202.
// A cell is dead (state 0) or in one of S living states, and each child of a stage-(k-1) cell
// in state i takes state j with P_k[i][j]. Dead is absorbing unless its row gives life back
// (NLMR's "wheys": dead cells that come back).
//
// In the engine a chain's state is held in bit planes: a chain of S living states takes
// bit_width(S) consecutive entries of Design::curds, entry `plane` holding that bit of the
// state, so that a cell's value carries the state and the overlay's values, rows and counts
// need nothing new. A chain of one living state with P = [[1, 0], [1 - p, p]] draws exactly
// as a plain curd of probability p does (markov_curdling.h).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "curdle/curd.h"

namespace curdle {

struct MarkovChain {
  std::vector<std::string> states;          // the living states 1..S; 0 is "dead"
  std::vector<std::optional<Rgb>> colours;  // one per living state
  std::vector<Probability> start;           // the roots' states 0..S (start[0], dead, is 0)
  // transitions[k - 1][i][j]: at stage k, a child of a state-i cell takes state j.
  std::vector<std::vector<std::vector<Probability>>> transitions;

  size_t living() const { return states.size(); }
  int planes() const;  // bits a state takes
  const std::vector<Probability>& row(int stage, uint32_t from) const {
    return transitions[static_cast<size_t>(stage - 1)][from];
  }
  bool revives(int stage) const;                 // the dead row gives some living state a chance
  bool stationary() const;                       // the same matrix at every stage
  std::string state_name(uint32_t state) const;  // "dead" for 0
};

// Where a uniform 64-bit draw u falls in a row: living state j when u < T_j and not below
// T_(j-1), where T_j / 2^64 = P[i][1] + ... + P[i][j] (sums kept exact for fractions); dead
// above T_S. The first boundary is the plain curd's threshold, so one living state is a curd.
struct StateBounds {
  std::vector<uint64_t> bound;  // T_1..T_S
  std::vector<bool> whole;      // T_j is 2^64: every u is below
  uint32_t state_of(uint64_t u) const;
};
StateBounds state_bounds(const std::vector<Probability>& row);

// p_1 + ... + p_n, exact while the fractions' denominators allow, else in doubles; at most 1.
Probability probability_sum(const std::vector<Probability>& terms, size_t n);

// A curd as the recipe wrote it: a plain curd (one plane, no chain) or a Markov curd's planes.
struct CurdGroup {
  size_t first = 0;  // its first entry in Design::curds, and the value's bit it starts at
  int planes = 1;
  const MarkovChain* chain = nullptr;

  uint32_t state(uint32_t value) const { return value >> first & ((uint32_t{1} << planes) - 1); }
  size_t states() const { return chain ? chain->living() + 1 : 2; }  // with dead
};
std::vector<CurdGroup> curd_groups(const std::vector<CurdSpec>& curds);

// What a layout's per-curd list (perforation's holes, a park's elements) is indexed by: each
// plain curd, and each living state of a Markov curd, in curd order.
struct CurdMember {
  std::string name;  // the curd's, or the state's
  size_t group = 0;  // in curd_groups
  uint32_t state = 1;
};
std::vector<CurdMember> curd_members(const std::vector<CurdSpec>& curds);
// The members a value holds, as indices into curd_members, in order.
std::vector<size_t> members_of(const std::vector<CurdSpec>& curds, uint32_t value);

// The share of the stage-k cells in each state 0..S: start P_1 ... P_k.
std::vector<double> state_shares(const MarkovChain& chain, int stage);

}  // namespace curdle
