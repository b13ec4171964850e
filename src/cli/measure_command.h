// `curdle measure IMAGE`: a picture's values, shares, lacunarity and box-counting dimensions,
// printed as a table and written as measure.json and a log-log plot, measure.png.
#pragma once

#include <CLI/CLI.hpp>
#include <optional>
#include <string>

namespace curdle::cli {

struct MeasureOptions {
  std::string image;
  int values = 2;
  std::optional<double> threshold;
  int base = 2;
  int stages = 0;
  std::string out_dir;
  std::string max_memory;
};

void add_measure_options(CLI::App& command, MeasureOptions& options);
int run_measure(const MeasureOptions& options);

}  // namespace curdle::cli
