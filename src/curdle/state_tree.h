// A Markov curd's finest cells seen as the leaves of its tree of cells: every stage-k cell that
// meets the view, its state hidden, its children the stage-(k+1) cells inside it that meet the
// view. Given a chain, the likelihood of the leaves' states and the expected number of each
// parent-state to child-state step at each stage follow from one pass up the tree and one down
// (the upward-downward recursion of hidden Markov trees: Crouse, Nowak and Baraniuk 1998; with
// the scaling of Durand, Goncalves and Guedon 2004). Children cut off by the view are summed
// out: they contribute a factor 1.
#pragma once

#include <cstdint>
#include <vector>

#include "curdle/box.h"
#include "curdle/lattice.h"

namespace curdle {

// A chain as numbers: start[i] over states 0..S, transitions[k - 1][i][j] at stage k.
struct ChainValues {
  std::vector<double> start;
  std::vector<std::vector<std::vector<double>>> transitions;  // K matrices
};

// What one pass gives: the log-likelihood of the leaves, and the expected counts of the roots'
// states and of each step (i at stage k - 1 to j at stage k), given the leaves.
struct StateTreeCounts {
  double log_likelihood = 0;
  std::vector<double> roots;                            // per state
  std::vector<std::vector<std::vector<double>>> steps;  // [k - 1][i][j]
  // Per root and state i, the chance of the leaves below it were it in state i, over the
  // largest of its S (root * S + i).
  std::vector<double> root_leaves;
};

class StateTree {
 public:
  // `leaves`: the finest cells' states over `view` (x fastest, then y, then z), each below
  // `states`; the view in lattice coordinates, boxes aligned to the lattice origin.
  StateTree(const Lattice& lattice, const Box& view, std::vector<uint8_t> leaves, size_t states);

  StateTreeCounts expected_counts(const ChainValues& chain) const;

  size_t states() const { return states_; }
  int stages() const { return static_cast<int>(parent_.size()) - 1; }
  uint64_t leaves() const { return leaves_.size(); }
  uint64_t roots() const { return nodes_[0]; }
  uint8_t leaf(size_t i) const { return leaves_[i]; }
  // The stage-(k - 1) cell holding stage-k cell `i`.
  uint32_t parent(int k, size_t i) const { return parent_[static_cast<size_t>(k)][i]; }
  uint64_t cells(int k) const { return nodes_[static_cast<size_t>(k)]; }

 private:
  size_t states_;
  std::vector<uint8_t> leaves_;
  std::vector<uint64_t> nodes_;                // per stage, the cells meeting the view
  std::vector<std::vector<uint32_t>> parent_;  // per stage (stage 0's empty)
};

}  // namespace curdle
