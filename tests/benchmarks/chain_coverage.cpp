// How often the intervals of a fitted chain (chain_fit.h) hold the chain that drew the cells:
// for each case, fixed seeds 1..N, the engine draws a Markov curd, its finest cells alone are
// fitted, and each entry's 95 % interval is checked against the true entry. Also how often the
// information criterion picks the reading that drew the cells: an overlay of two curds against
// a chain of three states. Prints a table; exits 1 when an entry's share leaves 92-98 % or a
// reading is picked in under 95 of 100.
//   curdle_chain_coverage [seeds per case, default 1000]
#include <tbb/parallel_for.h>

#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "curdle/chain_fit.h"
#include "curdle/curdling.h"
#include "curdle/markov.h"
#include "curdle/overlay.h"
#include "recipe/recipe.h"

namespace curdle {
namespace {

struct Case {
  const char* name;
  const char* lattice;
  const char* transitions;
  const char* cells;
  bool stage_wise, wheys;
};

Design design_of(const Case& c) {
  const std::string text = std::string("name = \"coverage\"\n[lattice]\n") + c.lattice +
                           "\n[field]\ncells = " + c.cells +
                           "\n[[curds]]\nname = \"tone\"\nstates = [\"dark\", \"mid\"]\n"
                           "start = [\"1/2\", \"1/2\"]\ntransitions = " +
                           c.transitions + "\n";
  return parse_recipe(text, "coverage.toml").design;
}

StateTree tree_of(const Design& d, uint64_t seed, size_t states) {
  const std::vector<uint16_t> values = values_in(curdle(d, seed, d.field), d.field);
  return StateTree(d.lattice, d.field, std::vector<uint8_t>(values.begin(), values.end()), states);
}

// The entries a fit estimates, as (block, row, column); block -1 the start.
struct Entry {
  int block;
  size_t row, column;
};

bool coverage_case(const Case& c, int seeds) {
  const Design d = design_of(c);
  const MarkovChain& truth = *d.curds[0].chain;
  const int K = d.lattice.stages;
  std::vector<Entry> entries;
  for (size_t j = 1; j < 3; ++j) entries.push_back({-1, 0, j});
  for (int b = 0; b < (c.stage_wise ? K : 1); ++b)
    for (size_t i = c.wheys ? 0 : 1; i < 3; ++i)
      for (size_t j = 0; j < 3; ++j) entries.push_back({b, i, j});
  std::vector<std::atomic<int>> held(entries.size());
  std::atomic<int> failed{0};
  ChainFitOptions o;
  o.stage_wise = c.stage_wise;
  o.wheys = c.wheys;
  tbb::parallel_for(1, seeds + 1, [&](int seed) {
    const ChainFit fit = fit_chain(tree_of(d, static_cast<uint64_t>(seed), 3), o);
    if (!fit.converged || !fit.intervals) ++failed;
    for (size_t e = 0; e < entries.size(); ++e) {
      const Entry& x = entries[e];
      const FittedEntry& f = x.block < 0
                                 ? fit.start[x.column]
                                 : fit.transitions[static_cast<size_t>(x.block)][x.row][x.column];
      const double want =
          x.block < 0 ? truth.start[x.column].value()
                      : truth.transitions[static_cast<size_t>(x.block)][x.row][x.column].value();
      if (f.low <= want && want <= f.high) ++held[e];
    }
  });
  bool ok = failed == 0;
  std::printf("%-34s %d seeds, %d fits not converged\n", c.name, seeds, failed.load());
  for (size_t e = 0; e < entries.size(); ++e) {
    const double share = static_cast<double>(held[e]) / seeds;
    const bool in = share >= 0.92 && share <= 0.98;
    ok &= in;
    const Entry& x = entries[e];
    if (x.block < 0)
      std::printf("  start[%zu]            %6.1f %%%s\n", x.column, 100 * share, in ? "" : "  OUT");
    else
      std::printf("  P%d[%zu][%zu]             %6.1f %%%s\n", x.block + 1, x.row, x.column,
                  100 * share, in ? "" : "  OUT");
  }
  return ok;
}

// Of 100 seeds, how often the information criterion picks the reading that drew the cells.
bool model_choice(int seeds) {
  const Design overlay =
      parse_recipe(
          "name = \"o\"\n[lattice]\nbase = 2\ndimension = 2\nstages = 5\n[field]\ncells = [128, "
          "128]\n"
          "[[curds]]\nname = \"a\"\nprobabilities = [0.8, 0.75, 0.7, 0.75, 0.8]\n"
          "[[curds]]\nname = \"b\"\nprobabilities = [0.7, 0.7, 0.7, 0.7, 0.7]\n",
          "o.toml")
          .design;
  const Design chain =
      design_of({"", "base = 2\ndimension = 2\nstages = 5",
                 R"([[["1", "0", "0"], ["1/8", "5/8", "1/4"], ["1/8", "1/4", "5/8"]]])"
                 "\nstages = 5",
                 "[128, 128]", false, false});
  std::atomic<int> overlay_right{0}, chain_right{0};
  auto overlay_bic = [](const StateTree& t, const Design& d) {
    double log_l = 0;
    for (int bit = 0; bit < 2; ++bit) {
      std::vector<uint8_t> cells;
      for (size_t i = 0; i < t.leaves(); ++i) cells.push_back(t.leaf(i) >> bit & 1);
      ChainFitOptions one;
      one.stage_wise = true;
      one.start_state = 1;
      one.intervals = false;
      log_l += fit_chain(StateTree(d.lattice, d.field, cells, 2), one).log_likelihood;
    }
    return information_criterion(log_l, 2 * d.lattice.stages, t.leaves());
  };
  ChainFitOptions as_chain;
  as_chain.intervals = false;
  tbb::parallel_for(1, seeds + 1, [&](int seed) {
    const StateTree a = tree_of(overlay, static_cast<uint64_t>(seed), 4);
    if (overlay_bic(a, overlay) < fit_chain(a, as_chain).bic) ++overlay_right;
    // The chain's three states are values 0..2 of two bits: read as an overlay they are
    // curd a (1), curd b (2), neither (0).
    const StateTree b = tree_of(chain, static_cast<uint64_t>(seed), 4);
    if (fit_chain(b, as_chain).bic < overlay_bic(b, chain)) ++chain_right;
  });
  std::printf(
      "model choice over %d seeds: overlay picked for overlaid curds %d, chain for a "
      "chain %d\n",
      seeds, overlay_right.load(), chain_right.load());
  return overlay_right * 100 >= 95 * seeds && chain_right * 100 >= 95 * seeds;
}

}  // namespace
}  // namespace curdle

int main(int argc, char** argv) {
  using curdle::Case;
  const int seeds = argc > 1 ? std::atoi(argv[1]) : 1000;
  // Cells keep their state three times in four, die one in eight: the hidden states are read
  // well enough from their children for the intervals' normal approximation to hold.
  const char* sticky = R"([["1", "0", "0"], ["1/8", "3/4", "1/8"], ["1/8", "1/8", "3/4"]])";
  const std::string sticky_5 = "[" + std::string(sticky) + "]\nstages = 5";
  const std::string sticky_4 = "[" + std::string(sticky) + "]\nstages = 4";
  const std::vector<Case> cases{
      {"3 states, b = 2, K = 5, 256 x 256", "base = 2\ndimension = 2\nstages = 5", sticky_5.c_str(),
       "[256, 256]", false, false},
      {"3 states, b = 3, K = 4, 324 x 324", "base = 3\ndimension = 2\nstages = 4", sticky_4.c_str(),
       "[324, 324]", false, false},
      {"wheys, b = 2, K = 5, 256 x 256", "base = 2\ndimension = 2\nstages = 5",
       R"([[["3/4", "1/8", "1/8"], ["1/8", "3/4", "1/8"], ["1/8", "1/8", "3/4"]]])"
       "\nstages = 5",
       "[256, 256]", false, true},
      {"stage-wise, b = 3, K = 3, 243 x 243", "base = 3\ndimension = 2\nstages = 3",
       R"([[["1", "0", "0"], ["1/8", "3/4", "1/8"], ["1/8", "1/8", "3/4"]],
           [["1", "0", "0"], ["1/4", "5/8", "1/8"], ["1/8", "1/8", "3/4"]],
           [["1", "0", "0"], ["1/8", "3/4", "1/8"], ["1/4", "1/8", "5/8"]]])",
       "[243, 243]", true, false},
  };
  bool ok = true;
  for (const Case& c : cases) ok &= curdle::coverage_case(c, seeds);
  ok &= curdle::model_choice(100);
  return ok ? 0 : 1;
}
