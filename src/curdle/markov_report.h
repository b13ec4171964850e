// The report of a Markov curd (markov.h): per stage and state the count beside its theory
// (markov_theory.h), and per state and for the living set the box counts, extinction and
// dimension. Plain data; exporters format it.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "curdle/boxcount.h"
#include "curdle/curd.h"
#include "curdle/markov.h"

namespace curdle {

struct StateStageRow {
  int stage = 0;
  std::string state;
  uint64_t cells = 0;   // stage-k cells meeting the view
  uint64_t count = 0;   // of them, in this state
  double share = 0;     // start P_1 ... P_k: the expected share
  double expected = 0;  // cells * share
  double expected_sd = 0;
  std::optional<double> z;  // (count - expected) / sd
};

// One state's set, or the living set (every living state).
struct StateSet {
  std::string name;
  std::vector<uint64_t> box_counts;          // level 0..K
  std::vector<double> expected_box_counts;   // level 0..K, at this K and view
  std::optional<LineFit> fit, expected_fit;  // box dimension of the counts and of theirs
  std::optional<double> theory_dimension;    // log rho(B P) / log b, for a stationary P
  double extinction = 0;  // the chance that a root leaves no finest cell in the set (whole root)
};

struct MarkovReport {
  std::string name;
  std::vector<std::string> states;  // the living states
  bool stationary = false;
  bool wheys = false;                 // some stage's dead row gives life back
  bool sd_is_approximate = false;     // quota mode: counts are set over the field
  std::vector<StateStageRow> stages;  // k = 0..K, every state (dead first) at each
  std::vector<StateSet> sets;         // each living state, then "living"
};

// The report of the Markov curd whose planes start at `group.first`, seen through `view`
// (`field` already restricted to it).
MarkovReport make_markov_report(const Design& design, const CurdGroup& group,
                                const CurdField& field, const Box& view);

}  // namespace curdle
