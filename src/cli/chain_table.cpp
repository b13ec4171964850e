#include "cli/chain_table.h"

#include <fmt/format.h>

#include <cstdio>

namespace curdle::cli {

namespace {

void print_row(const std::string& from, const std::vector<FittedEntry>& row) {
  std::printf("  %-14s", from.c_str());
  for (const FittedEntry& e : row)
    if (e.fixed)
      std::printf("  %6.4f (fixed)       ", e.value);
    else
      std::printf("  %6.4f (%6.4f-%6.4f)", e.value, e.low, e.high);
  std::printf("\n");
}

}  // namespace

void print_chain(const app::ChainReading& c) {
  const ChainFit& f = c.fit;
  std::printf("Markov curd '%s': %zu living state%s, %s%s; EM %s in %d rounds\n", c.curd.c_str(),
              c.states.size(), c.states.size() == 1 ? " (a plain curd)" : "s",
              c.options.stage_wise ? "a matrix per stage" : "one matrix for every stage",
              c.options.wheys ? ", wheys" : "", f.converged ? "converged" : "stopped unconverged",
              f.iterations);
  std::printf("  each entry with its 95 %% interval%s\n",
              f.intervals ? "" : " (not computed: too many parameters for these cells)");
  std::string header = "  from \\ to      ";
  std::vector<std::string> names{"dead"};
  names.insert(names.end(), c.states.begin(), c.states.end());
  for (const std::string& n : names) header += fmt::format("  {:<21}", n.substr(0, 21));
  std::printf("%s\n", header.c_str());
  print_row("start", f.start);
  for (size_t k = 0; k < f.transitions.size(); ++k) {
    if (f.transitions.size() > 1) std::printf("  stage %zu\n", k + 1);
    for (size_t i = 0; i < f.transitions[k].size(); ++i) print_row(names[i], f.transitions[k][i]);
  }
}

void print_levels(const app::ChainReading& c) {
  if (c.levels.empty()) return;
  std::printf(
      "By stage: cells in each state (coarser stages' states are hidden: their expected "
      "number given the cells) and boxes holding a finest cell of each, beside the fitted "
      "chain\n");
  std::printf("  %5s %-14s %12s %12s %10s %12s\n", "stage", "state", "cells", "chain", "boxes",
              "chain");
  std::vector<std::string> names{"dead"};
  names.insert(names.end(), c.states.begin(), c.states.end());
  for (const app::StateLevel& l : c.levels)
    for (size_t s = 0; s < names.size(); ++s) {
      std::printf("  %5d %-14s %12.1f %12.1f", l.level, names[s].substr(0, 14).c_str(), l.cells[s],
                  l.expected_cells[s]);
      if (s == 0)
        std::printf("\n");
      else
        std::printf(" %10llu %12.1f\n", static_cast<unsigned long long>(l.boxes[s]),
                    l.expected_boxes[s]);
    }
}

void print_readings(const app::ChainReading& c) {
  if (c.readings.size() < 2) {
    std::printf("One living state: the chain and a plain curd are the same model.\n");
    return;
  }
  std::printf(
      "Which reading the cells support (BIC = -2 log L + parameters x log cells; lower "
      "is better):\n");
  for (const app::Reading& r : c.readings)
    std::printf("  %-8s log L %12.1f  %3d parameters  BIC %12.1f%s  %s\n", r.name.c_str(),
                r.log_likelihood, r.parameters, r.bic,
                r.name == c.supported ? "  supported" : "           ", r.what.c_str());
  std::printf("  the %s by %.1f (over 10: very strong)\n", c.supported.c_str(), c.margin);
}

}  // namespace curdle::cli
