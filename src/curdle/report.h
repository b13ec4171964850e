// The per-stage report: what curdling gave beside what theory expects, per curd and stage,
// and the counts of the overlay's values. Plain data; exporters format it.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "curdle/boxcount.h"
#include "curdle/curd.h"
#include "curdle/markov_report.h"

namespace curdle {

struct StageRow {
  int stage = 0;
  Probability probability;
  uint64_t cells = 0;      // stage-k cells meeting the view
  uint64_t survivors = 0;  // N_k
  double expected = 0;     // C_k * p_1 ... p_k
  double expected_sd = 0;
  // Quota mode over the whole field: the stage's target when the survivors' children inside
  // the field were fewer, so that it could not be met (survivors is what was reached).
  std::optional<uint64_t> quota_missed;
  uint64_t box_count = 0;                  // stage-k cells keeping a final survivor
  double expected_box_count = 0;           // its expectation at this K, with extinction
  std::optional<double> local_dimension;   // log(N_k / N_(k-1)) / log b
  std::optional<double> mean_dimension;    // log(N_k / R) / (k log b), R roots meeting the view
  std::optional<double> theory_dimension;  // E + log p_k / log b
};

struct CurdReport {
  std::string name;
  uint64_t roots = 0;                // stage-0 cells meeting the view
  uint64_t root_box_count = 0;       // of them, those keeping a final survivor
  std::vector<StageRow> stages;      // k = 1..K
  std::vector<uint64_t> box_counts;  // level 0..K
  std::optional<LineFit> fit;
  std::vector<double> expected_box_counts;  // level 0..K, at this K and view (extinction.h)
  std::optional<LineFit> expected_fit;      // the same fit over the expected counts
  // Boxes the view cuts counted by the share of them it shows (views of up to 2^24 cells):
  // a crop's largest boxes then weigh what they hold, and the fit is not pulled down by them.
  std::optional<LineFit> share_weighted_fit;
  std::optional<LineFit> expected_share_weighted_fit;
  std::optional<double> theory_dimension;  // E + log(P_K^(1/K)) / log b, the limit K -> inf
  // Each cell's children survive P_K^(1/K) b^E at a time on average, 1 or fewer: run for many
  // stages, the curd dies out almost surely (Galton-Watson), and there is no limit dimension.
  bool dies_out = false;
  double final_probability = 0;  // P_K
  std::string density;           // the curd's density field (density.h, describe()); empty: none
};

struct ValueRow {
  uint32_t value = 0;
  std::string label;
  uint64_t count = 0;
  double expected = 0;
};

struct Report {
  std::string recipe;
  uint64_t seed = 0;
  Lattice lattice;
  Box field;
  Box view;
  uint64_t cells = 0;
  bool sd_is_approximate = false;    // quota mode seen through a window
  std::vector<CurdReport> curds;     // the plain curds
  std::vector<MarkovReport> markov;  // the Markov curds (markov_report.h)
  std::vector<ValueRow> values;
};

// Builds the report of `field` (from curdle()) seen through `view`.
Report make_report(const Design& design, uint64_t seed, const CurdField& field, const Box& view);

}  // namespace curdle
