// `curdle fit SOURCE --base b --stages K [--curds n | --states S [--stage-wise] [--wheys]]
// [--out recipe.toml]`: a recipe whose curds curdle designs with the picture's statistics, and
// the measured and expected counts per stage, or the fitted chain with its intervals, and which
// reading (overlaid curds or one chain) the cells support.
#pragma once

#include <CLI/CLI.hpp>
#include <string>

namespace curdle::cli {

struct FitOptions {
  std::string source;
  int base = 2;
  int stages = 0;
  int curds = 1;
  int cell_pixels = 0;
  int states = 0;
  bool stage_wise = false, wheys = false;
  std::string out;
  std::string max_memory;
};

void add_fit_options(CLI::App& command, FitOptions& options);
int run_fit(const FitOptions& options);

}  // namespace curdle::cli
