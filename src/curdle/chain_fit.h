// A Markov curd's chain (markov.h) fitted to its finest cells' states by maximum likelihood.
//
// The states of the coarser cells are hidden: only the finest cells are seen. The likelihood of
// the leaves under a chain is a sum over every hidden state (state_tree.h), maximised by EM
// (Dempster, Laird and Rubin 1977): each round takes the expected number of each step i -> j at
// each stage given the leaves, and sets each row to those counts' shares, which never lowers the
// likelihood. It starts from a labelling a designer would read off the picture (a cell takes the
// commonest living state among its children), so that a state keeps its name at every stage.
//
// Intervals: the observed information (Louis 1982) is the negative Hessian of the log-likelihood,
// taken as central differences of its exact gradient (the expected counts' score: n_ij - N_i P_ij
// per row, in log-ratio coordinates) and inverted; each entry's variance follows by the delta
// method, and the 95 % interval is Wilson's with the effective count P(1 - P) / Var, which stays
// inside [0, 1] and keeps its coverage near the edges better than a Wald interval. An entry fitted
// as 0 gets [0, 1 - 0.025^(1/N)], N the row's expected count (no step seen in N tries).
//
// A plain curd is the chain of one living state with dead absorbing and every root alive; n
// overlaid curds are a chain of 2^n - 1 states whose entries are products of the curds' own (an
// overlay of n curds is a special chain). The Bayesian information criterion, -2 log L + d log n
// (d free parameters, n leaves; Schwarz 1978), tells the readings apart.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "curdle/state_tree.h"

namespace curdle {

struct ChainFitOptions {
  bool stage_wise = false;              // one matrix per stage; else one for every stage
  bool wheys = false;                   // the dead row fitted too; else dead is absorbing
  std::optional<uint32_t> start_state;  // every root in this state; else a start distribution
  bool intervals = true;                // take the information matrix (the costly part)
};

struct FittedEntry {
  double value = 0;
  double low = 0, high = 1;  // 95 % interval
  bool fixed = false;        // not fitted (dead's absorbing row, a fixed start)
};

struct ChainFit {
  std::vector<FittedEntry> start;                                  // states 0..S
  std::vector<std::vector<std::vector<FittedEntry>>> transitions;  // 1 or K matrices
  double log_likelihood = 0;
  int parameters = 0;  // free ones
  double bic = 0;
  int iterations = 0;
  bool converged = false;
  bool intervals = false;  // false: not computed (asked not to, or too many parameters)

  ChainValues values(int stages) const;  // one matrix per stage
};

ChainFit fit_chain(const StateTree& tree, const ChainFitOptions& options);

// BIC of a reading with this log-likelihood and these free parameters over `leaves` cells.
double information_criterion(double log_likelihood, int parameters, uint64_t leaves);

}  // namespace curdle
