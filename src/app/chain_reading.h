// A picture's tones, or a cells.csv's states, read as one Markov curd (curdle/chain_fit.h) and as
// n overlaid plain curds, each fitted, and which reading the cells support. Tone 0 is the ground
// (dead); tones 1..S the living states.
//
// The overlay reading gives each living tone one of the 2^n - 1 non-zero values of n curds
// (n the fewest that hold the tones); every such assignment is tried for up to 3 living tones,
// and the tones in order for more. Each curd is then a one-state chain (dead absorbing, every
// root alive, one probability per stage). A reading's BIC is -2 log L + d log N; the lower is
// supported, and the difference says by how much (over 10 is very strong: Kass and Raftery 1995).
#pragma once

#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "curdle/box.h"
#include "curdle/chain_fit.h"
#include "curdle/lattice.h"

namespace curdle::app {

struct Reading {
  std::string name;  // "chain" or "overlay"
  std::string what;  // in words: "one Markov curd of 2 states", "2 overlaid curds (...)"
  double log_likelihood = 0;
  int parameters = 0;
  double bic = 0;
};

// At one level m (0..K) of the lattice, the cells' states beside what the fitted chain gives.
struct StateLevel {
  int level = 0;
  // Per state 0..S: the stage-m cells in it (the finest counted; coarser ones hidden, their
  // expected number given the cells), and the chain's expectation C_m s_m.
  std::vector<double> cells, expected_cells;
  // Per state 0..S (0 unused): the stage-m boxes holding a finest cell of it, and the chain's
  // expected box count (markov_theory.h).
  std::vector<uint64_t> boxes;
  std::vector<double> expected_boxes;
};

struct ChainReading {
  std::string curd;                  // the chain's name in the recipe
  std::vector<std::string> states;   // living states 1..S
  std::vector<std::string> colours;  // "#rrggbb" per living state; empty strings for none
  ChainFitOptions options;
  ChainFit fit;
  std::vector<Reading> readings;   // the chain's, then the overlay's (none when S = 1: the same)
  std::string supported;           // the reading with the lower BIC
  double margin = 0;               // the other's BIC minus the supported's
  std::vector<StateLevel> levels;  // 0..K (empty when the chain is only compared)
};

struct ChainRequest {
  Lattice lattice;
  Box view;
  std::vector<uint8_t> tones;  // per finest cell over `view`, x fastest
  std::string curd = "tone";
  std::vector<std::string> states, colours;  // per living tone; empty: "tone-1", ... and none
  bool stage_wise = false, wheys = false;
  bool intervals = true;    // false when the chain is only compared with an overlay
  uint64_t max_memory = 0;  // bytes the fit may take; 0: default_memory_limit()
};

// Most finest cells a chain is fitted to (its tree's memory grows with them).
inline constexpr uint64_t kMostChainCells = uint64_t{1} << 24;

// InputError when the cells hold no living state or a tone over 15; ResourceLimitError over
// kMostChainCells or when the tree's tables would pass max_memory.
ChainReading read_as_chain(ChainRequest request);

// The fitted curd as the recipe's [[curds]] table: a Markov curd, or for one state a plain curd's
// probabilities; each row's entries to 4 decimals that sum to 1 exactly, with each entry's
// interval in a comment above.
std::string chain_recipe_toml(const ChainReading& chain, int stages);

// Log-likelihood of n overlaid curds, each fitted, with the tones given these values.
double overlay_log_likelihood(const Lattice& lattice, const Box& view,
                              const std::vector<uint8_t>& tones, const std::vector<int>& value_of,
                              int curds);

nlohmann::ordered_json chain_reading_json(const ChainReading& chain, int stages);

}  // namespace curdle::app
